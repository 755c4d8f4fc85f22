// SPDX-License-Identifier: MIT
// The difference surface: overlay pieces triangulated into one TIN.
//
// Vertices are shared by key: a top vertex by its index, a base vertex by its index (a base
// vertex at the place of a top vertex is the top vertex: the overlay keeps one corner there), a
// crossing by its top edge and base edge (an open-addressing hash table). Neighbouring pieces
// list the same corners along their common side (every vertex or crossing on a side is a corner
// of both), so their triangles share edges and the TIN is conforming. A piece is fanned from a
// corner whose two sides carry no further corner in line with it (so no fan triangle is flat);
// when every corner has such a neighbour (a triangle with a corner in the middle of each side),
// from a vertex added at the centre of its corners (exact for a linear function).
#include "dtm/algo/difference_surface.hpp"

#include <array>
#include <cstdint>

#include "dtm/algo/tin_topology.hpp"
#include "dtm/core/error.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm {
namespace {

/// Open-addressing map from a 128-bit key to a vertex index.
class CrossingTable {
public:
    VertexIndex* find_or_insert(std::uint64_t k0, std::uint64_t k1, bool& inserted) {
        if (2 * (count_ + 1) > slots_.size()) {
            grow();
        }
        std::size_t i = hash(k0, k1) & (slots_.size() - 1);
        while (true) {
            Slot& s = slots_[i];
            if (s.value == no_vertex) {
                s = {k0, k1, no_vertex};
                ++count_;
                inserted = true;
                return &s.value;
            }
            if (s.k0 == k0 && s.k1 == k1) {
                inserted = false;
                return &s.value;
            }
            i = (i + 1) & (slots_.size() - 1);
        }
    }

private:
    struct Slot {
        std::uint64_t k0 = 0;
        std::uint64_t k1 = 0;
        VertexIndex value = no_vertex;
    };
    static std::size_t hash(std::uint64_t a, std::uint64_t b) {
        std::uint64_t h = a * 0x9E3779B97F4A7C15ULL ^ (b + 0x632BE59BD9B4E019ULL + (a << 6));
        h ^= h >> 29;
        h *= 0xBF58476D1CE4E5B9ULL;
        h ^= h >> 32;
        return static_cast<std::size_t>(h);
    }
    void grow() {
        std::vector<Slot> old = std::move(slots_);
        slots_.assign(std::max<std::size_t>(1024, old.size() * 2), Slot{});
        count_ = 0;
        for (const Slot& s : old) {
            if (s.value != no_vertex) {
                bool inserted = false;
                *find_or_insert(s.k0, s.k1, inserted) = s.value;
            }
        }
    }
    std::vector<Slot> slots_;
    std::size_t count_ = 0;
};

class Builder {
public:
    DifferenceSurface out;

    void add_piece(const OverlayPiece& piece) {
        const std::size_t n = piece.corners.size();
        std::array<VertexIndex, 12> ids{};
        for (std::size_t i = 0; i < n; ++i) {
            ids[i] = vertex(piece.corners[i]);
        }
        const std::size_t apex = fan_apex(piece.corners);
        if (apex < n) {
            for (std::size_t k = 1; k + 1 < n; ++k) {
                add_triangle(ids[apex], ids[(apex + k) % n], ids[(apex + k + 1) % n]);
            }
            return;
        }
        // A centre vertex: the mean of the corners (the difference is linear over the piece).
        Point3 c{};
        double top = 0.0;
        const OverlayCorner& o = piece.corners[0];
        for (const OverlayCorner& k : piece.corners) {
            c.x += k.x - o.x;
            c.y += k.y - o.y;
            c.z += k.z_top - k.z_base;
            top += k.z_top;
        }
        const double inv = 1.0 / static_cast<double>(n);
        const auto centre = static_cast<VertexIndex>(out.tin.vertices.size());
        out.tin.vertices.push_back({o.x + c.x * inv, o.y + c.y * inv, c.z * inv});
        out.top_z.push_back(top * inv);
        for (std::size_t k = 0; k < n; ++k) {
            add_triangle(centre, ids[k], ids[(k + 1) % n]);
        }
    }

    void set_sizes(std::size_t top_vertices, std::size_t base_vertices) {
        top_map_.assign(top_vertices, no_vertex);
        base_map_.assign(base_vertices, no_vertex);
    }

private:
    VertexIndex add_vertex(const OverlayCorner& c) {
        if (out.tin.vertices.size() >= no_vertex - 1) {
            throw Error("difference surface: more than 2^32 vertices");
        }
        out.tin.vertices.push_back({c.x, c.y, c.z_top - c.z_base});
        out.top_z.push_back(c.z_top);
        return static_cast<VertexIndex>(out.tin.vertices.size() - 1);
    }

    VertexIndex vertex(const OverlayCorner& c) {
        VertexIndex* slot = nullptr;
        switch (c.kind) {
            case CornerKind::top_vertex:
                slot = &top_map_[c.top_u];
                break;
            case CornerKind::base_vertex:
                slot = &base_map_[c.base_u];
                break;
            case CornerKind::crossing: {
                bool inserted = false;
                slot =
                    crossings_.find_or_insert((std::uint64_t{c.top_u} << 32) | c.top_v,
                                              (std::uint64_t{c.base_u} << 32) | c.base_v, inserted);
                break;
            }
        }
        if (*slot == no_vertex) {
            *slot = add_vertex(c);
        }
        return *slot;
    }

    /// A corner to fan from: strictly convex, with neither side continued straight by the next
    /// corner; n (none) if there is no such corner.
    static std::size_t fan_apex(std::span<const OverlayCorner> c) {
        const std::size_t n = c.size();
        if (n == 3) {
            return 0;
        }
        const auto turn = [&](std::size_t i) {
            const OverlayCorner& a = c[(i + n - 1) % n];
            const OverlayCorner& b = c[i];
            const OverlayCorner& d = c[(i + 1) % n];
            return geom::orient2d(a.x, a.y, b.x, b.y, d.x, d.y);
        };
        for (std::size_t i = 0; i < n; ++i) {
            if (turn(i) > 0 && turn((i + 1) % n) != 0 && turn((i + n - 1) % n) != 0) {
                return i;
            }
        }
        return n;
    }

    void add_triangle(VertexIndex a, VertexIndex b, VertexIndex c) {
        // A fan triangle of rounded crossing points can come out flat or turned over (a sliver
        // along a side where both surfaces have edges nearly in line): it has no area and would
        // overlap its neighbour, so it is left out.
        const Point3& pa = out.tin.vertices[a];
        const Point3& pb = out.tin.vertices[b];
        const Point3& pc = out.tin.vertices[c];
        if (geom::orient2d(pa.x, pa.y, pb.x, pb.y, pc.x, pc.y) <= 0) {
            return;
        }
        Triangle t;
        t.v = {a, b, c};
        out.tin.triangles.push_back(t);
    }

    std::vector<VertexIndex> top_map_;
    std::vector<VertexIndex> base_map_;
    CrossingTable crossings_;
};

}  // namespace

DifferenceSurface difference_surface(const TinOverlay& overlay, const Progress& progress) {
    Builder builder;
    std::size_t top_vertices = 0;
    std::size_t base_vertices = 0;
    overlay.vertex_counts(top_vertices, base_vertices);
    builder.set_sizes(top_vertices, base_vertices);
    overlay.run_ordered(
        [&](std::size_t, std::span<const OverlayPiece> pieces) {
            for (const OverlayPiece& piece : pieces) {
                builder.add_piece(piece);
            }
        },
        progress.sub(0.0, 0.9));
    progress.report(0.9, "linking the difference surface");
    DifferenceSurface out = std::move(builder.out);
    out.tin.vertices.shrink_to_fit();
    out.tin.triangles.shrink_to_fit();
    link_neighbours(out.tin);
    progress.report(1.0, "linking the difference surface");
    return out;
}

}  // namespace dtm
