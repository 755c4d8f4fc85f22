// SPDX-License-Identifier: MIT
/// @file
/// @brief The exact predicates with call counters: every method takes its geometric decisions
/// through one of these, so `dtm methods` can report how many each method needs.
#pragma once

#include <cstdint>

#include "dtm/geom/predicates.hpp"
#include "dtm/methods/method.hpp"

namespace dtm::methods::detail {

/// Not thread-safe: a parallel method gives each task its own and adds them up (add_to).
class CountingPredicates {
public:
    template <class A, class B, class C>
    [[nodiscard]] int orient(const A& a, const B& b, const C& c) noexcept {
        ++orient_;
        return geom::orient2d(a, b, c);
    }
    template <class A, class B, class C, class D>
    [[nodiscard]] int incircle(const A& a, const B& b, const C& c, const D& d) noexcept {
        ++incircle_;
        return geom::incircle(a, b, c, d);
    }
    /// The lifted 3-D orientation (counted with the orientations).
    template <class A, class B, class C, class D>
    [[nodiscard]] int orient3d_lifted(const A& a, const B& b, const C& c, const D& d) noexcept {
        ++orient_;
        return geom::orient3d_lifted(a, b, c, d);
    }
    /// Sign of |a-b|^2 - |c-d|^2 (counted as "distance_calls").
    template <class A, class B, class C, class D>
    [[nodiscard]] int compare_distances(const A& a, const B& b, const C& c, const D& d) noexcept {
        ++distance_;
        return geom::compare_distances(a, b, c, d);
    }
    [[nodiscard]] std::uint64_t orient_calls() const noexcept { return orient_; }
    [[nodiscard]] std::uint64_t incircle_calls() const noexcept { return incircle_; }
    void add(const CountingPredicates& other) noexcept {
        orient_ += other.orient_;
        incircle_ += other.incircle_;
        distance_ += other.distance_;
    }
    void add_to(MethodCounters& counters) const noexcept {
        counters.orient_calls += orient_;
        counters.incircle_calls += incircle_;
        if (distance_ > 0) counters.extra["distance_calls"] += distance_;
    }

private:
    std::uint64_t orient_ = 0;
    std::uint64_t incircle_ = 0;
    std::uint64_t distance_ = 0;
};

}  // namespace dtm::methods::detail
