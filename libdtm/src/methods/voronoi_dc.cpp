// SPDX-License-Identifier: MIT
// [voronoi-dc] The Voronoi diagram by divide and conquer, merged along the dividing chain sigma
// on a doubly connected edge list. Thesis 000 §3.4 (procedure VORONOI_DIAGRAM and the sigma
// construction of §3.4.1, after Preparata and Shamos 1985, ch. 5.5); M. I. Shamos, D. Hoey,
// "Closest-point problems", FOCS 1975.
//
// The generators are sorted lexicographically and split at the median, so the halves L and R
// are separated by a line (the thesis splits at the median x; ties in x are broken by y). A half
// of one point is a diagram without edges; when L u R is collinear the diagram is the parallel
// bisectors, joined directly. Otherwise sigma is walked from the upper bridge t1 down to the
// lower bridge t2 exactly as in the thesis' procedure: the current bisector of (pL, pR) is
// followed inside V(pL) of Vor(L), whose boundary is scanned clockwise, and V(pR) of Vor(R),
// scanned counter-clockwise, without backtracking; the nearer crossing wins, the chain turns
// onto the next bisector, the edges passed over on the wrong side of sigma are deleted and the
// crossed one is cut. Every decision is a predicate on generators: "the bisector crosses edge
// (pL | q) of V(pL) before the next edge (pL | q')" is "q' is not inside the circle through pL,
// pR, q", and "the crossing with V(pL) comes first" is "the R candidate is not inside the circle
// of the L candidate" (incircle), "a candidate lies ahead" is an orientation. In these terms the
// walk is the dual of Guibas and Stolfi's Delaunay merge (1985), whose tie-breaking it follows;
// ties leave zero-length edges, merged afterwards into vertices of degree > 3.
//
// DCEL: half-edges (origin, next, prev, face); an unbounded face's cycle is closed by its arc at
// infinity (next of the half-edge running out to infinity is the one coming back), so the hull
// of a sub-diagram is the sequence of those arcs. The sub-diagrams are only read while sigma is
// walked; the deletions, cuts and new links are applied afterwards. Deleted edges and vertices
// are reused through free lists.
#include "voronoi_dc.hpp"

#include <algorithm>
#include <numeric>
#include <string>

#include "dtm/core/error.hpp"
#include "methods/detail/counting_predicates.hpp"
#include "methods/detail/free_storage.hpp"
#include "methods/detail/voronoi_output.hpp"

namespace dtm::methods {
namespace {

using detail::dead_face;
using detail::no_index;
using HalfEdge = VoronoiDiagram::HalfEdge;

/// A sub-diagram: a lexicographic range of the generators.
struct Sub {
    std::uint32_t lo = 0;  ///< lexicographically smallest generator
    std::uint32_t hi = 0;  ///< largest
    /// The half-edges of lo's and hi's regions that run out to infinity (none for one point).
    std::uint32_t lo_out = no_index;
    std::uint32_t hi_out = no_index;
    bool collinear = true;
};

class Builder {
public:
    Builder(const std::vector<Point2>& xy,
            detail::CountingPredicates& pred,
            const Progress& progress)
        : xy_(xy), pred_(pred), progress_(progress) {
        const std::size_t n = xy.size();
        face_edge_.assign(n, no_index);
        stamp_.assign(n, 0);
        first_stop_.assign(n, no_index);
        // A diagram has at most 6n half-edges and 2n vertices; a merge makes its chain before
        // it deletes, a little more (6.03 n measured): room for that, so that no doubling of
        // the largest arrays (old and new copy resident at once) sets the peak.
        he_.reserve(6 * n + n / 16 + 64);
        prev_.reserve(he_.capacity());
        vref_.reserve(2 * n + n / 32 + 64);
    }

    Sub build(const std::uint32_t* order, std::size_t n) {
        if (n == 1) return Sub{order[0], order[0]};
        const std::size_t half = n / 2;
        const Sub left = build(order, half);
        const Sub right = build(order + half, n - half);
        if ((++merges_ & 0x3ffu) == 0) progress_.check();
        if (n >= report_size_) progress_.report(0.05 + 0.75 * double(done_ += n) / double(total_));
        return merge(left, right);
    }

    void set_total(std::size_t n) {
        report_size_ = std::max<std::size_t>(n / 64, 1024);
        total_ = std::max<std::size_t>(n * 8, 1);
    }

    /// The working graph for finish_voronoi; free half-edges carry dead_face.
    detail::VoronoiGraph release() {
        for (std::uint32_t e : free_edges_) {
            he_[e].face = dead_face;
            he_[e ^ 1u].face = dead_face;
        }
        detail::VoronoiGraph g;
        g.vertex_count = static_cast<std::uint32_t>(vref_.size());
        g.he = std::move(he_);
        // The rest is the builder's own: freed before the result is made.
        detail::free_storage(prev_);
        detail::free_storage(vref_);
        detail::free_storage(free_edges_);
        detail::free_storage(free_vertices_);
        detail::free_storage(face_edge_);
        detail::free_storage(stamp_);
        detail::free_storage(first_stop_);
        detail::free_storage(events_);
        detail::free_storage(killed_);
        return g;
    }

    [[nodiscard]] std::size_t peak_bytes() const {
        return he_.capacity() * sizeof(HalfEdge) + prev_.capacity() * 4 + vref_.capacity() * 4 +
               (face_edge_.size() + stamp_.size() + first_stop_.size()) * 4;
    }

private:
    const std::vector<Point2>& xy_;
    detail::CountingPredicates& pred_;
    const Progress& progress_;
    std::vector<HalfEdge> he_;
    std::vector<std::uint32_t> prev_;
    std::vector<std::uint32_t> vref_;  ///< per vertex: half-edges starting there
    std::vector<std::uint32_t> free_edges_, free_vertices_;
    std::vector<std::uint32_t> face_edge_;
    std::vector<std::uint32_t> stamp_, first_stop_;  ///< per generator, for the current merge
    std::uint32_t merge_id_ = 0;
    std::uint64_t merges_ = 0;
    std::size_t done_ = 0, total_ = 1, report_size_ = 1024;

    // Per-merge scratch.
    struct Event {
        std::uint32_t edge;  ///< the half-edge crossed (of V(pL) or V(pR))
        std::uint32_t vertex;
        bool left;
        std::uint32_t l, r;  ///< the generators on either side of sigma after the event
    };
    std::vector<Event> events_;
    std::vector<std::uint32_t> killed_;

    [[nodiscard]] const Point2& p(std::uint32_t g) const { return xy_[g]; }
    [[nodiscard]] std::uint32_t twin_face(std::uint32_t h) const { return he_[h ^ 1u].face; }
    [[nodiscard]] bool dead(std::uint32_t h) const { return he_[h].face == dead_face; }

    [[gnu::always_inline]] std::uint32_t new_edge(std::uint32_t face_left,
                                                  std::uint32_t face_right) {
        std::uint32_t e;
        if (!free_edges_.empty()) {
            e = free_edges_.back();
            free_edges_.pop_back();
        } else {
            e = static_cast<std::uint32_t>(he_.size());
            if (he_.size() + 2 > he_.capacity()) grow();
            he_.resize(he_.size() + 2);
            prev_.resize(prev_.size() + 2);
        }
        he_[e] = {no_index, no_index, face_left};
        he_[e ^ 1u] = {no_index, no_index, face_right};
        return e;
    }

    /// Room for more half-edges and vertices, by an eighth (not by doubling); out of line, so
    /// that new_edge and new_vertex stay small.
    [[gnu::cold, gnu::noinline]] void grow() {
        he_.reserve(he_.size() + he_.size() / 8 + 64);
        prev_.reserve(he_.capacity());
        vref_.reserve(vref_.size() + vref_.size() / 8 + 64);
    }

    std::uint32_t new_vertex() {
        if (!free_vertices_.empty()) {
            const std::uint32_t v = free_vertices_.back();
            free_vertices_.pop_back();
            return v;
        }
        if (vref_.size() == vref_.capacity()) grow();
        vref_.push_back(0);
        return static_cast<std::uint32_t>(vref_.size() - 1);
    }

    void link(std::uint32_t a, std::uint32_t b) {
        he_[a].next = b;
        prev_[b] = a;
    }

    void set_origin(std::uint32_t h, std::uint32_t v) {
        const std::uint32_t old = he_[h].origin;
        if (old != no_index && --vref_[old] == 0) free_vertices_.push_back(old);
        he_[h].origin = v;
        if (v != no_index) ++vref_[v];
    }

    [[nodiscard]] std::uint32_t live_prev(std::uint32_t h) const {
        do h = prev_[h];
        while (dead(h));
        return h;
    }
    [[nodiscard]] std::uint32_t live_next(std::uint32_t h) const {
        do h = he_[h].next;
        while (dead(h));
        return h;
    }

    void kill(std::uint32_t h) {
        killed_.push_back(h & ~1u);
        he_[h].face = dead_face;
        he_[h ^ 1u].face = dead_face;
    }

    /// The stop of generator g's scan: the half-edge just before the sigma edges already on
    /// g's region in the scan direction (on the first visit, the one sigma enters by).
    std::uint32_t stop_for(std::uint32_t g, std::uint32_t entry) {
        if (stamp_[g] != merge_id_) {
            stamp_[g] = merge_id_;
            first_stop_[g] = entry;
        }
        return first_stop_[g];
    }

    Sub merge(const Sub& l, const Sub& r);
    Sub join_collinear(const Sub& l, const Sub& r);
    void walk_sigma(std::uint32_t l, std::uint32_t hl, std::uint32_t r, std::uint32_t hr);
    void assemble(std::uint32_t l0, std::uint32_t r0);
    std::uint32_t chain_start(std::uint32_t h) const;
    std::uint32_t chain_end(std::uint32_t h) const;
    std::uint32_t out_of(std::uint32_t g) const;
};

/// Both halves and the line between them are collinear: the parallel bisectors, joined.
Sub Builder::join_collinear(const Sub& l, const Sub& r) {
    const std::uint32_t a = l.hi;
    const std::uint32_t b = r.lo;
    const std::uint32_t e = new_edge(a, b);  // e has a on its left, e ^ 1 has b
    // The region of a gains e: with its old line (if any) it becomes a strip.
    if (l.hi_out != no_index) {
        link(l.hi_out, e);
        link(e, l.hi_out);
    } else {
        link(e, e);
    }
    if (r.lo_out != no_index) {
        link(r.lo_out, e ^ 1u);
        link(e ^ 1u, r.lo_out);
    } else {
        link(e ^ 1u, e ^ 1u);
    }
    face_edge_[a] = e;
    face_edge_[b] = e ^ 1u;
    Sub s;
    s.lo = l.lo;
    s.hi = r.hi;
    s.lo_out = l.lo_out != no_index ? l.lo_out : e;
    s.hi_out = r.hi_out != no_index ? r.hi_out : (e ^ 1u);
    s.collinear = true;
    return s;
}

Sub Builder::merge(const Sub& l, const Sub& r) {
    if (l.collinear && r.collinear && pred_.orient(p(l.lo), p(r.hi), p(l.hi)) == 0 &&
        pred_.orient(p(l.lo), p(r.hi), p(r.lo)) == 0) {
        return join_collinear(l, r);
    }
    // The upper bridge t1 = (pL, pR): from L's largest and R's smallest generator, climb L's
    // hull counter-clockwise and R's clockwise while a hull neighbour lies above the line.
    std::uint32_t a = l.hi, ha = l.hi_out;
    std::uint32_t b = r.lo, hb = r.lo_out;
    for (;;) {
        if (ha != no_index) {
            const std::uint32_t step = he_[ha].next ^ 1u;  // out half-edge of the ccw neighbour
            const std::uint32_t next_gen = he_[step].face;
            if (pred_.orient(p(b), p(a), p(next_gen)) < 0) {
                a = next_gen;
                ha = step;
                continue;
            }
        }
        if (hb != no_index) {
            const std::uint32_t prev_gen = twin_face(hb);
            if (pred_.orient(p(b), p(a), p(prev_gen)) < 0) {
                b = prev_gen;
                hb = prev_[hb ^ 1u];
                continue;
            }
        }
        break;
    }
    ++merge_id_;
    walk_sigma(a, ha, b, hb);
    assemble(a, b);
    Sub s;
    s.lo = l.lo;
    s.hi = r.hi;
    s.lo_out = out_of(l.lo);
    s.hi_out = out_of(r.hi);
    s.collinear = false;
    return s;
}

void Builder::walk_sigma(std::uint32_t l, std::uint32_t hl, std::uint32_t r, std::uint32_t hr) {
    events_.clear();
    killed_.clear();
    // L's region is scanned clockwise (prev) from the half-edge before its upper arc, R's
    // counter-clockwise (next) from the one after its arc; each scan stops where sigma entered.
    std::uint32_t el = hl;
    std::uint32_t stop_l = hl != no_index ? stop_for(l, he_[hl].next) : no_index;
    std::uint32_t er = hr != no_index ? he_[hr].next : no_index;
    std::uint32_t stop_r = hr != no_index ? stop_for(r, hr) : no_index;
    if (hl == no_index) stop_for(l, no_index);
    if (hr == no_index) stop_for(r, no_index);
    for (;;) {
        // The left candidate: the generator across el, if it lies ahead (below the base l r).
        bool valid_l = false;
        std::uint32_t lc = no_index;
        if (el != no_index) {
            lc = twin_face(el);
            valid_l = pred_.orient(p(l), p(r), p(lc)) < 0;
            while (valid_l && el != stop_l) {
                const std::uint32_t nx = live_prev(el);
                const std::uint32_t ln = twin_face(nx);
                if (pred_.incircle(p(l), p(lc), p(r), p(ln)) <= 0) break;
                kill(el);  // entirely beyond sigma
                el = nx;
                lc = ln;
            }
        }
        bool valid_r = false;
        std::uint32_t rc = no_index;
        if (er != no_index) {
            rc = twin_face(er);
            valid_r = pred_.orient(p(l), p(r), p(rc)) < 0;
            while (valid_r && er != stop_r) {
                const std::uint32_t nx = live_next(er);
                const std::uint32_t rn = twin_face(nx);
                if (pred_.incircle(p(l), p(rc), p(r), p(rn)) <= 0) break;
                kill(er);
                er = nx;
                rc = rn;
            }
        }
        if (!valid_l && !valid_r) break;  // the lower bridge t2
        const bool take_r = !valid_l || (valid_r && pred_.incircle(p(l), p(lc), p(r), p(rc)) > 0);
        const std::uint32_t v = new_vertex();
        if (take_r) {
            const std::uint32_t entry = er ^ 1u;
            events_.push_back({er, v, false, l, rc});
            r = rc;
            stop_r = stop_for(r, entry);
            er = live_next(entry);
        } else {
            const std::uint32_t entry = el ^ 1u;
            events_.push_back({el, v, true, lc, r});
            l = lc;
            stop_l = stop_for(l, entry);
            el = live_prev(entry);
        }
    }
}

void Builder::assemble(std::uint32_t l0, std::uint32_t r0) {
    // Sigma edge k runs down from vertex k (infinity for k = 0) to vertex k + 1 (infinity after
    // the last event); its half-edge s_k has R's generator on its left, t_k = s_k ^ 1 L's.
    const std::size_t m = events_.size();
    if (m == 0) throw Error("voronoi-dc: internal error: a merge without a sigma vertex");
    std::vector<std::uint32_t> s(m + 1);
    for (std::size_t k = 0; k <= m; ++k) {
        const std::uint32_t lk = k == 0 ? l0 : events_[k - 1].l;
        const std::uint32_t rk = k == 0 ? r0 : events_[k - 1].r;
        s[k] = new_edge(rk, lk);
        face_edge_[rk] = s[k];
        face_edge_[lk] = s[k] ^ 1u;
    }
    for (std::size_t k = 0; k <= m; ++k) {
        set_origin(s[k], k == 0 ? no_index : events_[k - 1].vertex);
        set_origin(s[k] ^ 1u, k == m ? no_index : events_[k].vertex);
    }
    for (std::size_t i = 0; i < m; ++i) {
        const Event& ev = events_[i];
        const std::uint32_t s_in = s[i], s_out = s[i + 1];
        const std::uint32_t t_in = s[i + 1] ^ 1u, t_out = s[i] ^ 1u;  // t runs up
        const std::uint32_t e = ev.edge;
        if (ev.left) {
            // e (of the old left region) now ends at the vertex; its twin starts there.
            set_origin(e ^ 1u, ev.vertex);
            link(e, t_out);
            link(t_in, e ^ 1u);
            link(s_in, s_out);
        } else {
            set_origin(e, ev.vertex);
            link(s_in, e);
            link(e ^ 1u, s_out);
            link(t_in, t_out);
        }
    }
    for (std::uint32_t e : killed_) {
        set_origin(e, no_index);
        set_origin(e ^ 1u, no_index);
        free_edges_.push_back(e);
    }
    // The arcs at infinity of the four corner regions (each now has one chain of edges).
    const std::uint32_t top_l = s[0] ^ 1u;  // runs up to infinity
    const std::uint32_t top_r = s[0];       // comes down from infinity
    const std::uint32_t bottom_l = s[m] ^ 1u;
    const std::uint32_t bottom_r = s[m];
    link(top_l, chain_start(top_l));
    link(chain_end(top_r), top_r);
    link(chain_end(bottom_l), bottom_l);
    link(bottom_r, chain_start(bottom_r));
}

/// The half-edge that comes in from infinity at the start of h's chain (walking back).
std::uint32_t Builder::chain_start(std::uint32_t h) const {
    while (he_[h].origin != no_index) h = prev_[h];
    return h;
}

/// The half-edge that runs out to infinity at the end of h's chain.
std::uint32_t Builder::chain_end(std::uint32_t h) const {
    while (he_[h ^ 1u].origin != no_index) h = he_[h].next;
    return h;
}

std::uint32_t Builder::out_of(std::uint32_t g) const { return chain_end(face_edge_[g]); }

}  // namespace

MethodResult run_voronoi_dc(const MethodInput& input,
                            const MethodOptions& options,
                            const Progress& progress) {
    if (!options.params.empty()) {
        throw UsageError("method voronoi-dc takes no parameter (got '" +
                         options.params.begin()->first + "')");
    }
    detail::Sites sites = detail::make_sites(input.points, "voronoi-dc");
    std::vector<std::uint32_t> order(sites.real);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        const Point2& p = sites.xy[a];
        const Point2& q = sites.xy[b];
        return p.x < q.x || (p.x == q.x && p.y < q.y);
    });
    progress.report(0.05, "voronoi-dc");
    detail::CountingPredicates pred;
    MethodResult result;
    Builder builder(sites.xy, pred, progress);
    builder.set_total(order.size());
    builder.build(order.data(), order.size());
    detail::free_storage(order);
    result.counters.peak_bytes = builder.peak_bytes();
    detail::finish_voronoi(builder.release(), std::move(sites), input.points,
                           detail::FinishOptions{}, pred, result, progress.sub(0.8, 1.0));
    pred.add_to(result.counters);
    return result;
}

}  // namespace dtm::methods
