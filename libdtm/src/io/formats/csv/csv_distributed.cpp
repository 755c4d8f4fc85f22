// SPDX-License-Identifier: MIT
//
// Survey points by byte ranges (csv_distributed.hpp). A line belongs to the rank whose nominal
// range holds its first byte: rank r starts at the first line start at or after r S / P, so
// neighbours agree on the boundary without talking. Line numbers: the data starts after line
// `data_line`; the newlines of every range are counted and an exclusive scan gives each rank the
// number of the line before its first. Errors are elected, so every rank reports the one the
// serial reader reports (the first bad line in file order).
#include "io/formats/csv/csv_distributed.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <string_view>

#include "dtm/core/error.hpp"
#include "io/detail/file_bytes.hpp"
#include "io/detail/file_crs.hpp"
#include "io/formats/csv/csv_detail.hpp"

namespace dtm::io {

std::size_t distributed_block_bytes = std::size_t{32} << 20;

void elect_input_error(dist::Comm& comm,
                       const InputFile& file,
                       const InputError* mine,
                       std::int64_t order) {
    // The smallest order, then the lowest rank that has it.
    const std::int64_t first = comm.allreduce(order, dist::Reduce::min);
    if (first == INT64_MAX) return;
    const std::int64_t rank =
        comm.allreduce(order == first ? comm.rank() : INT64_MAX, dist::Reduce::min);
    dist::Bytes text;
    std::int64_t where[2] = {0, 0};  // line, column
    if (comm.rank() == rank) {
        // The message without the location the reader puts in front of it.
        const std::string full = mine->what();
        const std::string prefix = InputError(file.path, mine->line(), mine->column(), "").what();
        const std::string raw = full.rfind(prefix, 0) == 0 ? full.substr(prefix.size()) : full;
        text.assign(reinterpret_cast<const std::byte*>(raw.data()),
                    reinterpret_cast<const std::byte*>(raw.data()) + raw.size());
        where[0] = static_cast<std::int64_t>(mine->line());
        where[1] = static_cast<std::int64_t>(mine->column());
    }
    comm.bcast(text, static_cast<int>(rank));
    comm.allreduce(where, dist::Reduce::max);
    throw InputError(file.path, static_cast<std::size_t>(where[0]),
                     static_cast<std::size_t>(where[1]),
                     std::string(reinterpret_cast<const char*>(text.data()), text.size()));
}

namespace {

constexpr std::size_t head_bytes = std::size_t{1} << 16;

/// The first line start at or after @p at in @p bytes, not before @p floor (the data's start).
std::size_t line_start(std::string_view bytes, std::size_t at, std::size_t floor) {
    if (at <= floor) return floor;
    const std::size_t newline = bytes.find('\n', at - 1);
    return newline == std::string_view::npos ? bytes.size() : newline + 1;
}

}  // namespace

DistributedPoints read_text_points_distributed(dist::Comm& comm,
                                               const InputFile& file,
                                               const ReadOptions& options) {
    comm.set_phase("read");
    // Mapped, not read: a rank's pages are only those of its range (and the head).
    const detail::FileBytes in(file.path, detail::Access::sequential);
    const std::string_view bytes = in.view();
    const std::string_view head = bytes.substr(0, std::min(bytes.size(), head_bytes));
    const csv::Layout layout = csv::detect_layout(head, file.path.string(), options.columns, false);
    const std::size_t begin = layout.data_offset;
    const std::size_t data = bytes.size() - std::min(bytes.size(), begin);
    const auto r = static_cast<std::size_t>(comm.rank());
    const auto p = static_cast<std::size_t>(comm.size());
    const std::size_t from = line_start(bytes, begin + r * data / p, begin);
    const std::size_t to =
        r + 1 == p ? bytes.size() : line_start(bytes, begin + (r + 1) * data / p, begin);
    const std::string_view text = bytes.substr(from, std::max(from, to) - from);
    const auto newlines = static_cast<std::int64_t>(std::count(text.begin(), text.end(), '\n'));
    const auto before = static_cast<std::size_t>(comm.exscan_sum(newlines));

    // The range in blocks of whole lines, each block's pages dropped once parsed: a rank holds
    // one block of the file and its points, not its whole range twice.
    const std::size_t block_bytes = std::max<std::size_t>(1, distributed_block_bytes);
    DistributedPoints out;
    if (csv::column_of(layout, csv::Field::x) < 0 || csv::column_of(layout, csv::Field::y) < 0) {
        ReadResult crs;  // lat/lon columns: read_csv's EPSG:4326, identified as load_inputs does
        crs.crs_wkt = "EPSG:4326";
        detail::identify_file_crs(file, crs);
        out.crs_wkt = std::move(crs.crs_wkt);
    }
    std::uint64_t skipped = 0;
    std::optional<InputError> failure;
    try {
        std::size_t line = layout.data_line + before;
        for (std::size_t at = 0; at < text.size();) {
            const std::size_t end = at + block_bytes >= text.size()
                                        ? text.size()
                                        : line_start(text, at + block_bytes, at);
            const std::string_view block = text.substr(at, end - at);
            const ReadResult part = csv::parse_points_range(block, line, layout, file, options);
            if (at == 0 && end < text.size()) {  // reserve from the first block's density
                out.points.reserve(part.terrain.points.size() * (text.size() / (end - at) + 1));
            }
            for (const Point3& q : part.terrain.points) out.points.push_back({q, true});
            skipped += part.summary.skipped_lines;
            line += static_cast<std::size_t>(std::count(block.begin(), block.end(), '\n'));
            in.release(from + at, from + end);
            at = end;
        }
    } catch (const InputError& e) {
        failure = e;
    }
    elect_input_error(comm, file, failure ? &*failure : nullptr,
                      failure ? static_cast<std::int64_t>(failure->line()) : INT64_MAX);
    out.first_input =
        static_cast<std::uint64_t>(comm.exscan_sum(static_cast<std::int64_t>(out.points.size())));
    out.total = static_cast<std::uint64_t>(
        comm.allreduce(static_cast<std::int64_t>(out.points.size()), dist::Reduce::sum));
    out.skipped_lines = static_cast<std::uint64_t>(
        comm.allreduce(static_cast<std::int64_t>(skipped), dist::Reduce::sum));
    return out;
}

}  // namespace dtm::io
