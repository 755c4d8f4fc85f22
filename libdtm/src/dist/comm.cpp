// SPDX-License-Identifier: MIT
//
// The backend-independent part of dist::Comm: sequence numbers, per-phase counters, jitter.
#include "dtm/dist/comm.hpp"

#include <chrono>
#include <climits>
#include <thread>

#include "dtm/core/error.hpp"

namespace dtm::dist {

void Comm::set_jitter(unsigned max_microseconds, std::uint64_t seed) {
    jitter_us_ = max_microseconds;
    jitter_state_ = seed * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(rank()) + 1;
}

void Comm::begin_call(std::uint64_t bytes, std::uint64_t messages) {
    PhaseTraffic& t = traffic_[phase_];
    t.bytes += bytes;
    t.messages += messages;
    ++t.calls;
    ++sequence_;
    if (jitter_us_ > 0) {
        // splitmix64: a private stream per rank, never the global random state.
        std::uint64_t z = (jitter_state_ += 0x9E3779B97F4A7C15ULL);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
        z ^= z >> 31;
        std::this_thread::sleep_for(std::chrono::microseconds(z % (jitter_us_ + 1)));
    }
}

std::vector<Bytes> Comm::alltoallv(std::vector<Bytes> out) {
    std::uint64_t bytes = 0;
    std::uint64_t messages = 0;
    for (std::size_t r = 0; r < out.size(); ++r) {
        if (static_cast<int>(r) == rank()) continue;
        bytes += out[r].size();
        messages += out[r].empty() ? 0 : 1;
    }
    begin_call(bytes, messages);
    return do_alltoallv(std::move(out));
}

std::vector<Bytes> Comm::allgatherv(Bytes mine) {
    const auto others = static_cast<std::uint64_t>(size() - 1);
    begin_call(mine.size() * others, mine.empty() ? 0 : others);
    return do_allgatherv(std::move(mine));
}

void Comm::allreduce(std::span<std::int64_t> values, Reduce op) {
    begin_call(values.size_bytes(), size() > 1 ? 1 : 0);
    do_allreduce(values, op);
}

std::int64_t Comm::allreduce(std::int64_t value, Reduce op) {
    allreduce(std::span<std::int64_t>(&value, 1), op);
    return value;
}

std::int64_t Comm::exscan_sum(std::int64_t value) {
    begin_call(sizeof value, size() > 1 ? 1 : 0);
    return do_exscan_sum(value);
}

void Comm::bcast(Bytes& data, int root) {
    const auto others = static_cast<std::uint64_t>(size() - 1);
    const bool sends = rank() == root;
    begin_call(sends ? data.size() * others : 0, sends && !data.empty() ? others : 0);
    do_bcast(data, root);
}

void throw_first_error(Comm& comm, const std::string& error) {
    const std::int64_t first = comm.allreduce(error.empty() ? INT64_MAX : comm.rank(), Reduce::min);
    Bytes text;
    if (comm.rank() == first) {
        const auto* p = reinterpret_cast<const std::byte*>(error.data());
        text.assign(p, p + error.size());
    }
    comm.bcast(text, static_cast<int>(first));
    throw Error(std::string(reinterpret_cast<const char*>(text.data()), text.size()));
}

void Comm::barrier() {
    begin_call(0, 0);
    do_barrier();
}

}  // namespace dtm::dist
