// SPDX-License-Identifier: MIT
//
// In-process transport: P virtual ranks as threads that meet at a barrier for every collective.
// A collective deposits each rank's payload in a shared table, waits for all, reads its own
// column in source order and waits again before the table is reused. A failing rank leaves the
// barrier for good (arrive_and_drop) and marks the run aborted, so the others stop at their
// next collective instead of waiting forever.
#include "dtm/dist/in_process.hpp"

#include <atomic>
#include <barrier>
#include <exception>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

#include "dist/posix_shared_file.hpp"

namespace dtm::dist {
namespace {

struct Hub {
    explicit Hub(int p)
        : ranks(p),
          sync(p),
          mail(static_cast<std::size_t>(p)),
          values(static_cast<std::size_t>(p)),
          sequence(static_cast<std::size_t>(p), 0) {}

    int ranks;
    std::barrier<> sync;
    std::vector<std::vector<Bytes>> mail;           ///< [source][destination]
    std::vector<std::vector<std::int64_t>> values;  ///< [source]
    std::vector<std::uint64_t> sequence;            ///< [source] at the current call
    std::atomic<bool> aborted{false};
};

class InProcessComm final : public Comm {
public:
    InProcessComm(Hub& hub, int rank) : hub_(hub), rank_(rank) {}

    [[nodiscard]] int rank() const noexcept override { return rank_; }
    [[nodiscard]] int size() const noexcept override { return hub_.ranks; }
    std::unique_ptr<SharedFile> open_shared(const std::string& path) override {
        return open_posix_shared(*this, path);
    }

protected:
    std::vector<Bytes> do_alltoallv(std::vector<Bytes> out) override {
        if (static_cast<int>(out.size()) != hub_.ranks) {
            throw std::logic_error("alltoallv: one payload per rank expected");
        }
        hub_.mail[me()] = std::move(out);
        meet();
        std::vector<Bytes> in(hub_.mail.size());
        for (std::size_t s = 0; s < in.size(); ++s) in[s] = std::move(hub_.mail[s][me()]);
        wait();
        return in;
    }

    std::vector<Bytes> do_allgatherv(Bytes mine) override {
        hub_.mail[me()].assign(1, std::move(mine));
        meet();
        std::vector<Bytes> in(hub_.mail.size());
        for (std::size_t s = 0; s < in.size(); ++s) in[s] = hub_.mail[s][0];
        wait();
        return in;
    }

    void do_allreduce(std::span<std::int64_t> values, Reduce op) override {
        hub_.values[me()].assign(values.begin(), values.end());
        meet();
        for (std::size_t s = 0; s < hub_.values.size(); ++s) {
            const auto& v = hub_.values[s];
            if (v.size() != values.size()) throw std::logic_error("allreduce: lengths differ");
            for (std::size_t i = 0; i < v.size(); ++i) {
                if (s == 0) {
                    values[i] = v[i];
                } else if (op == Reduce::min) {
                    values[i] = std::min(values[i], v[i]);
                } else if (op == Reduce::max) {
                    values[i] = std::max(values[i], v[i]);
                } else {
                    values[i] += v[i];
                }
            }
        }
        wait();
    }

    std::int64_t do_exscan_sum(std::int64_t value) override {
        hub_.values[me()].assign(1, value);
        meet();
        std::int64_t sum = 0;
        for (std::size_t s = 0; s < me(); ++s) sum += hub_.values[s][0];
        wait();
        return sum;
    }

    void do_bcast(Bytes& data, int root) override {
        if (rank_ == root) hub_.mail[me()].assign(1, data);
        meet();
        if (rank_ != root) data = hub_.mail[static_cast<std::size_t>(root)][0];
        wait();
    }

    void do_barrier() override {
        meet();
        wait();
    }

private:
    [[nodiscard]] std::size_t me() const noexcept { return static_cast<std::size_t>(rank_); }

    /// Waits for every rank after the deposit; checks that all are at the same collective call.
    void meet() {
        hub_.sequence[me()] = sequence();
        wait();
        for (std::size_t s = 0; s < hub_.sequence.size(); ++s) {
            if (hub_.sequence[s] != sequence()) {
                throw std::logic_error("in-process transport: rank " + std::to_string(s) +
                                       " is at collective call " +
                                       std::to_string(hub_.sequence[s]) + ", rank " +
                                       std::to_string(rank_) + " at " + std::to_string(sequence()));
            }
        }
    }

    /// Waits for every rank to have read (the table may be reused after it).
    void wait() {
        hub_.sync.arrive_and_wait();
        if (hub_.aborted.load()) throw Aborted();
    }

    Hub& hub_;
    int rank_;
};

}  // namespace

void run_in_process(int ranks,
                    const std::function<void(Comm&)>& job,
                    const InProcessOptions& options) {
    if (ranks < 1) throw std::invalid_argument("run_in_process: at least one rank");
    Hub hub(ranks);
    std::vector<std::exception_ptr> errors(static_cast<std::size_t>(ranks));
    std::vector<std::thread> threads;
    threads.reserve(static_cast<std::size_t>(ranks));
    for (int r = 0; r < ranks; ++r) {
        threads.emplace_back([&, r] {
            InProcessComm comm(hub, r);
            if (options.jitter_microseconds > 0) {
                comm.set_jitter(options.jitter_microseconds, options.seed);
            }
            try {
                job(comm);
            } catch (...) {
                errors[static_cast<std::size_t>(r)] = std::current_exception();
                hub.aborted.store(true);
                hub.sync.arrive_and_drop();
            }
        });
    }
    for (auto& t : threads) t.join();
    std::exception_ptr first_aborted;
    for (const auto& e : errors) {
        if (!e) continue;
        try {
            std::rethrow_exception(e);
        } catch (const Aborted&) {
            if (!first_aborted) first_aborted = e;
        } catch (...) {
            throw;
        }
    }
    if (first_aborted) std::rethrow_exception(first_aborted);
}

}  // namespace dtm::dist
