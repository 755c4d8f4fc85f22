// SPDX-License-Identifier: MIT
/// @file
/// @brief Progress reporting and cancellation: a cheap, copyable, thread-safe handle.
#pragma once

#include <functional>
#include <memory>
#include <string_view>

namespace dtm {

/// Receives the overall fraction done in [0, 1] and the current stage. Return false to cancel.
using ProgressFn = std::function<bool(double fraction, std::string_view what)>;

/// Handle passed to every long-running algorithm. A default-constructed handle is silent and never
/// cancels. Calls from several threads are serialised; the callback is throttled to about one call
/// per 0.5 % of progress.
class Progress {
public:
    Progress() = default;
    explicit Progress(ProgressFn fn);

    /// Report completion in [0, 1] of this handle's range. Throws Cancelled if the callback says
    /// stop.
    void report(double fraction, std::string_view what = {}) const;
    /// Throw Cancelled if cancellation was requested; cheap (no callback), for hot loops and tasks.
    void check() const;
    /// Child handle mapping [0, 1] onto [begin, end] of this handle's range.
    [[nodiscard]] Progress sub(double begin, double end) const;
    /// Ask every holder of this handle (and its children) to stop at their next check().
    void cancel() const noexcept;

private:
    struct Shared;
    std::shared_ptr<Shared> shared_;
    double begin_ = 0.0;
    double end_ = 1.0;
};

}  // namespace dtm
