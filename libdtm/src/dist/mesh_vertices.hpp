// SPDX-License-Identifier: MIT
/// @file
/// @brief What the writers and products of a distributed run need of the kernel's mesh beyond
/// one rank's slots: which rank holds a number, the vertex numbers of foreign positions, the
/// ghost slots of all ranks, and the triangles with their vertices' heights (docs/distributed.md).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include "dist/kernel.hpp"
#include "dtm/core/point.hpp"
#include "dtm/core/tin.hpp"
#include "dtm/dist/duplicates.hpp"

namespace dtm::dist {

/// The rank of a number when ranks hold contiguous runs [lo, hi) of them in rank order (kernel
/// positions, merged vertex numbers). Collective construction (one allgatherv of two numbers).
class RunOwners {
public:
    RunOwners(Comm& comm, std::uint64_t lo, std::uint64_t hi);
    [[nodiscard]] int of(std::uint64_t number) const;
    /// The rank of @p number and its place in that rank's run.
    [[nodiscard]] std::pair<int, std::uint64_t> locate(std::uint64_t number) const;

private:
    struct Run {
        std::uint64_t lo, hi;
        int rank;
    };
    std::vector<Run> runs_;
};

/// Collective: the merged vertex numbers of the foreign positions this rank's triangles name,
/// asked of the positions' owners.
[[nodiscard]] std::unordered_map<std::uint64_t, std::uint64_t> foreign_vertex_numbers(
    Comm& comm, const DistributedMesh& kernel);

/// Collective: the ghost slots of all ranks (the hull's and the unused ones), in slot order.
[[nodiscard]] std::vector<std::uint64_t> all_ghost_slots(Comm& comm, const LocalMesh& mesh);

/// The index in the serial TIN of the real triangle in kernel slot @p slot: the slot itself
/// below the real count @p real; the k-th real slot at or above it fills the k-th ghost slot
/// below it (tin_build_triangles). @p ghosts: every ghost slot, ascending.
[[nodiscard]] std::uint64_t serial_face(std::uint64_t slot,
                                        std::span<const std::uint64_t> ghosts,
                                        std::uint64_t real);

/// A vertex of the TIN: its merged number (the serial TIN's) and position.
struct SurfaceVertex {
    std::uint64_t id = 0;
    Point3 p{};
};

/// A real triangle of the TIN in the Tin's conventions: corners as in the serial TIN (indices
/// into the mesh's vertices), edge e opposite corner e, bit e of `border` set when no triangle
/// lies across edge e (the hull).
struct SurfaceFace {
    std::uint64_t face = 0;  ///< its index among the serial TIN's triangles (after the domain)
    std::array<std::uint32_t, 3> v{};
    std::uint32_t border = 0;
};

/// Some of the TIN's real triangles and the vertices they name, each vertex once.
struct SurfaceMesh {
    std::vector<SurfaceVertex> vertices;  ///< ascending id
    std::vector<SurfaceFace> faces;
};

struct SurfaceMeshOptions {
    /// Also every vertex of this rank's kernel positions, named by a triangle or not (a tile of
    /// the tiled TIN holds each vertex of the TIN on its kernel owner's tile).
    bool every_own_vertex = false;
};

/// @p mesh as a Tin of its own: vertices in ascending number, the faces' corners, no links.
[[nodiscard]] Tin surface_tin(const SurfaceMesh& mesh);

/// Collective: this rank's real triangles (in slot order) with their vertices as the merge keeps
/// them (x and y from the kernel's positions, z asked of the vertices' owners in @p merged).
[[nodiscard]] SurfaceMesh surface_mesh(Comm& comm,
                                       const MergedShare& merged,
                                       const DistributedMesh& kernel,
                                       const SurfaceMeshOptions& options = {});
/// As above, consuming @p kernel: its triangles are freed once the faces are listed, before the
/// vertices are numbered (a rank's peak is then the kernel or the surface, not both whole).
[[nodiscard]] SurfaceMesh surface_mesh(Comm& comm,
                                       const MergedShare& merged,
                                       DistributedMesh&& kernel,
                                       const SurfaceMeshOptions& options = {});

/// Collective: this rank's merged vertices [merged.first_vertex, + merged.count()) as x, y, z in
/// consecutive runs of at most a sixteenth of the largest rank's count (at least 65536), passed
/// to @p run with the first vertex number of each: x and y from the vertices' kernel owners, z
/// from @p merged. Every rank calls @p run the same number of times (a run may be empty), so
/// @p run may be collective. A rank holds one run's records at a time, not the whole block.
void merged_vertex_runs(Comm& comm,
                        const MergedShare& merged,
                        const DistributedMesh& kernel,
                        const std::function<void(std::uint64_t, std::span<const Point3>)>& run);

}  // namespace dtm::dist
