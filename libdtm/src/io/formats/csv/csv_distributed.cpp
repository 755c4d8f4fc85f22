// SPDX-License-Identifier: MIT
//
// Survey points by byte ranges (csv_distributed.hpp). A line belongs to the rank whose nominal
// range holds its first byte: rank r starts at the first line start at or after r S / P, so
// neighbours agree on the boundary without talking. Line numbers: the data starts after line
// `data_line`; the newlines of every range are counted and an exclusive scan gives each rank the
// number of the line before its first. Errors are elected, so every rank reports the one the
// serial reader reports (the first bad line in file order).
#include "io/formats/csv/csv_distributed.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <optional>
#include <string>

#include "dtm/core/error.hpp"
#include "io/formats/csv/csv_detail.hpp"

namespace dtm::io {
namespace {

constexpr std::size_t head_bytes = std::size_t{1} << 16;

class ReadOnlyFile {
public:
    explicit ReadOnlyFile(const std::filesystem::path& path) : path_(path) {
        fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
        if (fd_ < 0) fail("cannot open the file");
        const off_t end = ::lseek(fd_, 0, SEEK_END);
        if (end < 0) fail("cannot read the file");
        size_ = static_cast<std::size_t>(end);
    }
    ReadOnlyFile(const ReadOnlyFile&) = delete;
    ReadOnlyFile& operator=(const ReadOnlyFile&) = delete;
    ~ReadOnlyFile() { ::close(fd_); }

    [[nodiscard]] std::size_t size() const noexcept { return size_; }
    /// Bytes [from, to) of the file.
    [[nodiscard]] std::string read(std::size_t from, std::size_t to) const {
        std::string out(to - from, '\0');
        std::size_t done = 0;
        while (done < out.size()) {
            const ssize_t n =
                ::pread(fd_, out.data() + done, out.size() - done, static_cast<off_t>(from + done));
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) fail("cannot read the file");
            done += static_cast<std::size_t>(n);
        }
        return out;
    }
    /// The first line start at or after @p at, not before @p floor (the data's start).
    [[nodiscard]] std::size_t line_start(std::size_t at, std::size_t floor) const {
        if (at <= floor) return floor;
        constexpr std::size_t step = 4096;
        for (std::size_t from = at - 1; from < size_; from += step) {
            const std::string bytes = read(from, std::min(size_, from + step));
            const std::size_t newline = bytes.find('\n');
            if (newline != std::string::npos) return from + newline + 1;
        }
        return size_;
    }

private:
    [[noreturn]] void fail(const char* what) const {
        throw Error("cannot read " + path_.string() + ": " + what + " (" + std::strerror(errno) +
                    ")");
    }

    std::filesystem::path path_;
    int fd_ = -1;
    std::size_t size_ = 0;
};

/// The first InputError of the file over all ranks, rethrown on every rank (none: returns).
void elect_error(dist::Comm& comm, const InputFile& file, const InputError* mine) {
    const std::int64_t line = mine != nullptr ? static_cast<std::int64_t>(mine->line()) : INT64_MAX;
    const std::int64_t key[2] = {line, mine != nullptr ? comm.rank() : INT64_MAX};
    std::int64_t first[2] = {key[0], INT64_MAX};
    comm.allreduce(std::span<std::int64_t>(first, 1), dist::Reduce::min);
    if (first[0] == INT64_MAX) return;
    first[1] = comm.allreduce(key[0] == first[0] ? key[1] : INT64_MAX, dist::Reduce::min);
    dist::Bytes text;
    std::int64_t column = 0;
    if (comm.rank() == first[1]) {
        // The message without the location read_csv puts in front of it.
        const std::string full = mine->what();
        const std::string prefix = InputError(file.path, mine->line(), mine->column(), "").what();
        const std::string raw = full.rfind(prefix, 0) == 0 ? full.substr(prefix.size()) : full;
        text.assign(reinterpret_cast<const std::byte*>(raw.data()),
                    reinterpret_cast<const std::byte*>(raw.data()) + raw.size());
        column = static_cast<std::int64_t>(mine->column());
    }
    comm.bcast(text, static_cast<int>(first[1]));
    column = comm.allreduce(comm.rank() == first[1] ? column : 0, dist::Reduce::max);
    throw InputError(file.path, static_cast<std::size_t>(first[0]),
                     static_cast<std::size_t>(column),
                     std::string(reinterpret_cast<const char*>(text.data()), text.size()));
}

}  // namespace

DistributedPoints read_text_points_distributed(dist::Comm& comm,
                                               const InputFile& file,
                                               const ReadOptions& options) {
    comm.set_phase("read");
    const ReadOnlyFile in(file.path);
    const std::string head = in.read(0, std::min(in.size(), head_bytes));
    const csv::Layout layout = csv::detect_layout(head, file.path.string(), options.columns, false);
    const std::size_t begin = layout.data_offset;
    const std::size_t data = in.size() - std::min(in.size(), begin);
    const auto r = static_cast<std::size_t>(comm.rank());
    const auto p = static_cast<std::size_t>(comm.size());
    const std::size_t from = in.line_start(begin + r * data / p, begin);
    const std::size_t to =
        r + 1 == p ? in.size() : in.line_start(begin + (r + 1) * data / p, begin);
    const std::string text = in.read(from, std::max(from, to));
    const auto newlines = static_cast<std::int64_t>(std::count(text.begin(), text.end(), '\n'));
    const auto before = static_cast<std::size_t>(comm.exscan_sum(newlines));

    DistributedPoints out;
    ReadResult result;
    std::optional<InputError> failure;
    try {
        result = csv::parse_points_range(text, layout.data_line + before, layout, file, options);
    } catch (const InputError& e) {
        failure = e;
    }
    elect_error(comm, file, failure ? &*failure : nullptr);
    out.points.reserve(result.terrain.points.size());
    for (const Point3& q : result.terrain.points) out.points.push_back({q, true});
    out.first_input =
        static_cast<std::uint64_t>(comm.exscan_sum(static_cast<std::int64_t>(out.points.size())));
    out.total = static_cast<std::uint64_t>(
        comm.allreduce(static_cast<std::int64_t>(out.points.size()), dist::Reduce::sum));
    out.skipped_lines = static_cast<std::uint64_t>(
        comm.allreduce(static_cast<std::int64_t>(result.summary.skipped_lines), dist::Reduce::sum));
    return out;
}

}  // namespace dtm::io
