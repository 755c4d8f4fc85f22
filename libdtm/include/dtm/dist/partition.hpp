// SPDX-License-Identifier: MIT
/// @file
/// @brief The serial kernel's recursion tree spread over ranks (R-D1 of docs/distributed.md).
///
/// The divide and conquer cuts its points at lexicographic medians, alternately by x and by y,
/// strips of at most 16 points by x (delaunay_dc.cpp, kd_order.hpp). partition_points computes
/// the top levels of that same tree from points spread over the ranks in any way: the medians
/// are selected in place (samples gathered, candidates counted by integer reductions, the last
/// few thousand candidates gathered and ordered exactly), then one alltoallv moves every point
/// to the rank that owns its leaf. The leaves and their position ranges are those of the serial
/// tree whatever the rank count or the initial spread, because the set on each side of a median
/// cut is a function of the point set only.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "dtm/core/progress.hpp"
#include "dtm/dist/comm.hpp"

namespace dtm::dist {

/// A point with its global vertex number (the merged input order).
struct Point {
    double x = 0.0;
    double y = 0.0;
    std::uint64_t id = 0;
};

/// A leaf of the distributed tree: a subtree of the serial one.
struct Leaf {
    std::uint64_t lo = 0;  ///< positions [lo, hi) in the serial kernel order; slots [2 lo, 2 hi)
    std::uint64_t hi = 0;
    std::uint32_t depth = 0;
    std::uint8_t cut = 0;  ///< axis of the leaf's first cut as the serial build sees it (0 x, 1 y)
    std::uint8_t frame = 0;  ///< axis of its parent's cut (the order the parent merge reads it in)
    int owner = 0;           ///< the rank that holds its points
};

struct PartitionOptions {
    /// Levels below ceil(log2 P): 2^3 = 8 leaves per rank by default.
    unsigned extra_levels = 3;
    /// Points sampled per node and selection round (over all ranks).
    std::size_t sample = 512;
    /// A node's candidates are gathered and ordered exactly once at most this many remain.
    std::size_t gather_below = 2048;
};

struct PartitionStats {
    std::uint32_t levels = 0;
    std::uint32_t sample_rounds = 0;    ///< selection rounds with samples, all levels
    std::uint64_t gathered = 0;         ///< candidates this rank sent for exact ordering
    std::uint64_t received_points = 0;  ///< points this rank received in the shuffle
};

/// A cut of the tree above the leaves: node [lo, hi), its axis (the strip rule applied) and its
/// median, the first point of its right half (in the axis' order).
struct Cut {
    std::uint64_t lo = 0;
    std::uint64_t hi = 0;
    std::uint8_t axis = 0;
    double x = 0.0;
    double y = 0.0;
};

/// This rank's part of the tree.
struct Share {
    std::uint64_t total = 0;     ///< points over all ranks
    std::vector<Leaf> leaves;    ///< every leaf, in tree order (about 8 P of them)
    std::vector<Cut> cuts;       ///< every cut above the leaves, level by level
    std::size_t first_leaf = 0;  ///< this rank owns leaves [first_leaf, last_leaf)
    std::size_t last_leaf = 0;
    /// The owned leaves' points, leaf after leaf, each leaf sorted lexicographically by (x, y).
    std::vector<Point> points;
    /// Leaf first_leaf + i is points[offsets[i], offsets[i + 1]).
    std::vector<std::size_t> offsets;
    PartitionStats stats;
};

/// The leaves of the serial tree for @p total points at depth at most ceil(log2 ranks) +
/// extra_levels (nodes of at most 3 points are leaves higher up), with their owners: contiguous
/// runs in tree order, balanced by point count. A function of (total, ranks) only.
std::vector<Leaf> tree_leaves(std::uint64_t total, int ranks, unsigned extra_levels);

/// Collective: computes the tree from every rank's @p local points (pairwise distinct in xy over
/// all ranks; ids unique) and returns this rank's share.
/// @throws InputError on every rank when two points coincide; Cancelled on every rank when
/// any rank's @p progress asks to stop.
Share partition_points(Comm& comm,
                       std::vector<Point> local,
                       const PartitionOptions& options,
                       const Progress& progress);

}  // namespace dtm::dist
