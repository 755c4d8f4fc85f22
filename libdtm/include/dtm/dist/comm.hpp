// SPDX-License-Identifier: MIT
/// @file
/// @brief The transport of the distributed run: one interface, an MPI and an in-process backend.
///
/// Every operation is collective (all ranks call it in the same order) and delivers what it
/// received in source-rank order, never in arrival order, so nothing a rank computes depends on
/// timing. Each call carries a sequence number; the in-process backend checks that all ranks
/// are at the same call. There are integer reductions only: no decision may depend on a
/// floating-point sum whose value depends on the rank count.
///
/// Bytes are counted per phase (set_phase) with the same nominal rule in both backends (what a
/// rank hands to the transport for other ranks), so an MPI run and an in-process run of the same
/// job report the same counters.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace dtm::dist {

using Bytes = std::vector<std::byte>;

enum class Reduce { min, max, sum };

/// Per-phase traffic of one rank.
struct PhaseTraffic {
    std::uint64_t bytes = 0;     ///< payload handed to the transport for other ranks
    std::uint64_t messages = 0;  ///< non-empty payloads for other ranks
    std::uint64_t calls = 0;     ///< collective calls
};

/// A file all ranks write at once, each its own byte ranges (collective open and close).
class SharedFile {
public:
    SharedFile() = default;
    SharedFile(const SharedFile&) = delete;
    SharedFile& operator=(const SharedFile&) = delete;
    virtual ~SharedFile() = default;
    /// Writes @p bytes at @p offset. @throws Error naming the file.
    virtual void write_at(std::uint64_t offset, std::span<const std::byte> bytes) = 0;
    /// Collective: flushes and closes; every rank learns whether any rank's write failed.
    /// @throws Error on every rank when one failed.
    virtual void close() = 0;
};

class Comm;

/// Collective, for a failure some ranks met: throws Error on every rank with the message of the
/// lowest rank whose @p error is not empty (the others pass an empty one).
[[noreturn]] void throw_first_error(Comm& comm, const std::string& error);

class Comm {
public:
    Comm() = default;
    Comm(const Comm&) = delete;
    Comm& operator=(const Comm&) = delete;
    virtual ~Comm() = default;

    [[nodiscard]] virtual int rank() const noexcept = 0;
    [[nodiscard]] virtual int size() const noexcept = 0;

    /// Sends out[r] to rank r (out.size() == size()); returns what every rank s sent to this
    /// one, at index s.
    std::vector<Bytes> alltoallv(std::vector<Bytes> out);
    /// Every rank's @p mine, at index s.
    std::vector<Bytes> allgatherv(Bytes mine);
    /// Element-wise reduction of @p values over all ranks, in place (same length everywhere).
    void allreduce(std::span<std::int64_t> values, Reduce op);
    std::int64_t allreduce(std::int64_t value, Reduce op);
    /// Sum of @p value over the ranks before this one (0 on rank 0).
    std::int64_t exscan_sum(std::int64_t value);
    /// Root's @p data on every rank.
    void bcast(Bytes& data, int root);
    void barrier();

    /// Collective: creates (or truncates) @p path for writing by all ranks (MPI-IO on MPI).
    virtual std::unique_ptr<SharedFile> open_shared(const std::string& path) = 0;

    /// Names the phase the following calls are counted under.
    void set_phase(std::string name) { phase_ = std::move(name); }
    [[nodiscard]] const std::map<std::string, PhaseTraffic>& traffic() const noexcept {
        return traffic_;
    }
    /// Sleep a pseudo-random time of up to @p max_microseconds before every send (testing: no
    /// output may depend on timing). 0 turns it off.
    void set_jitter(unsigned max_microseconds, std::uint64_t seed);
    /// Collective calls made so far (the sequence number of the next one).
    [[nodiscard]] std::uint64_t sequence() const noexcept { return sequence_; }

protected:
    virtual std::vector<Bytes> do_alltoallv(std::vector<Bytes> out) = 0;
    virtual std::vector<Bytes> do_allgatherv(Bytes mine) = 0;
    virtual void do_allreduce(std::span<std::int64_t> values, Reduce op) = 0;
    virtual std::int64_t do_exscan_sum(std::int64_t value) = 0;
    virtual void do_bcast(Bytes& data, int root) = 0;
    virtual void do_barrier() = 0;

private:
    void begin_call(std::uint64_t bytes, std::uint64_t messages);

    std::string phase_ = "other";
    std::map<std::string, PhaseTraffic> traffic_;
    std::uint64_t sequence_ = 0;
    unsigned jitter_us_ = 0;
    std::uint64_t jitter_state_ = 0;
};

/// A trivially copyable array as bytes, and back.
template <class T>
Bytes to_bytes(std::span<const T> values) {
    static_assert(std::is_trivially_copyable_v<T>);
    Bytes out(values.size_bytes());
    if (!values.empty()) std::memcpy(out.data(), values.data(), values.size_bytes());
    return out;
}
/// Appends the bytes of one trivially copyable value (the native byte order: every rank of a
/// job runs on the same architecture).
template <class T>
void append_value(Bytes& out, const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto* p = reinterpret_cast<const std::byte*>(&value);
    out.insert(out.end(), p, p + sizeof(T));
}
template <class T>
std::vector<T> from_bytes(const Bytes& bytes);
/// The values every rank sent, concatenated in source order.
template <class T>
std::vector<T> concatenated(const std::vector<Bytes>& in) {
    static_assert(std::is_trivially_copyable_v<T>);
    std::size_t n = 0;
    for (const Bytes& b : in) n += b.size() / sizeof(T);
    std::vector<T> out(n);
    std::size_t at = 0;
    for (const Bytes& b : in) {
        const std::size_t k = b.size() / sizeof(T);
        if (k > 0) std::memcpy(out.data() + at, b.data(), k * sizeof(T));
        at += k;
    }
    return out;
}
/// As above, freeing each part once copied: the peak is the values plus one part, not twice
/// the values (the result's pages are touched only as they are filled).
template <class T>
std::vector<T> concatenated(std::vector<Bytes>&& in) {
    static_assert(std::is_trivially_copyable_v<T>);
    std::size_t n = 0;
    for (const Bytes& b : in) n += b.size() / sizeof(T);
    std::vector<T> out;
    out.reserve(n);
    for (Bytes& b : in) {
        const std::size_t k = b.size() / sizeof(T);
        const std::size_t at = out.size();
        out.resize(at + k);
        if (k > 0) std::memcpy(out.data() + at, b.data(), k * sizeof(T));
        Bytes().swap(b);
    }
    return out;
}
template <class T>
std::vector<T> from_bytes(const Bytes& bytes) {
    static_assert(std::is_trivially_copyable_v<T>);
    std::vector<T> out(bytes.size() / sizeof(T));
    if (!out.empty()) std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
    return out;
}

}  // namespace dtm::dist
