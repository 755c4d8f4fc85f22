// SPDX-License-Identifier: MIT
/// @file
/// @brief The explicit table of triangulation methods (src/methods/registry.cpp).
#pragma once

#include <span>
#include <string_view>

#include "dtm/methods/method.hpp"

namespace dtm::methods {

enum class Family { delaunay, voronoi, optimal, greedy, constrained, pseudo, enumeration };

/// What kind of result a method fills in MethodResult.
enum class Output { triangulation, voronoi, polygon_faces, all_triangulations };

struct MethodInfo {
    std::string_view name;  ///< registry name, e.g. "incremental-walk"
    Family family;
    std::string_view source;      ///< where in the literature: "000 §3.8", "003 Alg. 1-4", ...
    std::string_view complexity;  ///< as claimed by the source, e.g. "O(n log n) expected"
    std::string_view summary;     ///< one line for `dtm methods list`
    bool takes_constraints;       ///< honours MethodInput::segments
    bool quadratic;               ///< worst/typical time above n log n: the lab caps its n
    Output output;
    std::string_view params;  ///< documented parameter keys, "key=a|b ..." (empty: none)
    MethodFn run;
};

/// Every method, in a fixed order (the order of `dtm methods list`).
[[nodiscard]] std::span<const MethodInfo> registry();

/// The method named @p name, or nullptr.
[[nodiscard]] const MethodInfo* find_method(std::string_view name);

[[nodiscard]] std::string_view family_name(Family family);

}  // namespace dtm::methods
