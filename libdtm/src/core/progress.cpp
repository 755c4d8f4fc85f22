// SPDX-License-Identifier: MIT
#include "dtm/core/progress.hpp"

#include <atomic>
#include <mutex>
#include <string>

#include "dtm/core/error.hpp"

namespace dtm {

struct Progress::Shared {
    ProgressFn fn;
    std::mutex mutex;
    std::atomic<bool> cancelled{false};
    double last_reported = -1.0;
    std::string last_what;
};

Progress::Progress(ProgressFn fn) : shared_(std::make_shared<Shared>()) {
    shared_->fn = std::move(fn);
}

void Progress::report(double fraction, std::string_view what) const {
    if (!shared_) return;
    check();
    fraction = fraction < 0.0 ? 0.0 : (fraction > 1.0 ? 1.0 : fraction);
    const double overall = begin_ + (end_ - begin_) * fraction;
    {
        std::lock_guard lock(shared_->mutex);
        const bool new_stage = what != shared_->last_what;
        if (!new_stage && overall < 1.0 && overall - shared_->last_reported < 0.005) return;
        shared_->last_reported = overall;
        shared_->last_what.assign(what);
        if (shared_->fn && !shared_->fn(overall, what)) shared_->cancelled.store(true);
    }
    check();
}

void Progress::check() const {
    if (shared_ && shared_->cancelled.load(std::memory_order_relaxed)) throw Cancelled();
}

Progress Progress::sub(double begin, double end) const {
    Progress child = *this;
    child.begin_ = begin_ + (end_ - begin_) * begin;
    child.end_ = begin_ + (end_ - begin_) * end;
    return child;
}

void Progress::cancel() const noexcept {
    if (shared_) shared_->cancelled.store(true);
}

}  // namespace dtm
