// SPDX-License-Identifier: MIT
/// @file
/// @brief What every Delaunay method of the module does the same way: reading its parameters,
/// preparing the input (distinct points in input order, the production kernel's refusals),
/// accounting its memory, building the output Tin from a triangle list, filling the counters.
#pragma once

#include <array>
#include <cstddef>
#include <initializer_list>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dtm/methods/method.hpp"
#include "methods/detail/counting_predicates.hpp"
#include "methods/detail/free_storage.hpp"

namespace dtm::methods::detail {

/// The method's parameters: each key read once with its allowed values; finish() rejects the
/// keys nobody read (UsageError naming the key and the method).
class ParamReader {
public:
    ParamReader(std::string_view method, const MethodOptions& options);
    /// The value of @p key (one of @p allowed), or @p fallback when absent.
    [[nodiscard]] std::string choice(std::string_view key,
                                     std::initializer_list<std::string_view> allowed,
                                     std::string_view fallback);
    /// A number in [lo, hi], or @p fallback when absent.
    [[nodiscard]] double number(std::string_view key, double fallback, double lo, double hi);
    void finish() const;

private:
    std::string method_;
    const MethodOptions& options_;
    std::set<std::string, std::less<>> read_;
};

struct PreparedPoints {
    std::vector<Point3> vertices;  ///< distinct xy positions, first occurrence, input order
    std::size_t duplicates = 0;    ///< input points dropped as repeats of an earlier xy
};

/// The distinct points of @p input. @throws UsageError when segments are given (the Delaunay
/// methods take none); InputError for a non-finite coordinate, fewer than 3 distinct points or
/// all points collinear (the production kernel's refusals, same wording).
[[nodiscard]] PreparedPoints prepare_points(std::string_view method,
                                            const MethodInput& input,
                                            CountingPredicates& predicates);

/// Heap bytes of a vector (its capacity).
template <class T>
[[nodiscard]] std::size_t bytes_of(const std::vector<T>& v) noexcept {
    return v.capacity() * sizeof(T);
}

/// The peak of a running byte count.
class PeakBytes {
public:
    void note(std::size_t current) noexcept {
        if (current > peak_) peak_ = current;
    }
    [[nodiscard]] std::size_t peak() const noexcept { return peak_; }

private:
    std::size_t peak_ = 0;
};

using TriangleCorners = std::array<VertexIndex, 3>;

/// Sets every n of the counter-clockwise @p triangles (vertex ids below @p vertex_count) by
/// matching each directed edge with its reverse (no_triangle where there is none); for a
/// triangulation (each directed edge in one triangle). Linear; 16 bytes per vertex of scratch.
void link_in_place(std::span<Triangle> triangles, std::size_t vertex_count);

/// Tin triangles of the counter-clockwise @p triangles over @p vertex_count vertices, neighbour
/// links found by matching each directed edge with its reverse.
[[nodiscard]] std::vector<Triangle> link_triangles(std::span<const TriangleCorners> triangles,
                                                   std::size_t vertex_count);

/// A Tin of @p vertices and the counter-clockwise @p triangles, neighbour links found by
/// matching each directed edge with its reverse (linear: edges bucketed by origin vertex).
[[nodiscard]] Tin tin_from_triangles(std::vector<Point3> vertices,
                                     std::span<const TriangleCorners> triangles);
/// The same, freeing @p triangles as soon as the Tin holds their corners (a lower peak).
[[nodiscard]] Tin tin_from_triangles(std::vector<Point3> vertices,
                                     std::vector<TriangleCorners>&& triangles);

/// Fills the predicate counts, the duplicates and the peak bytes into @p result.
void finish_counters(MethodResult& result,
                     const CountingPredicates& predicates,
                     std::size_t duplicates,
                     std::size_t peak_bytes);

}  // namespace dtm::methods::detail
