// SPDX-License-Identifier: MIT
// Delimited text reader. The input is read in blocks of 32 MiB cut at line ends (csv_blocks.cpp),
// so reading holds the points and about one block of text, never the whole file. The layout
// (csv_layout.cpp) is detected on the first block, extended until it holds every line detection
// looks at. Rows are parsed with std::from_chars for the numbers and no per-line allocation
// (fields are views into the block); they become points, or polyline vertices grouped by a
// line-id column (pputils "shapeid,x,y[,z]"), or hole seeds.
//
// A large block of point rows is parsed in parallel: it is cut into chunks at line ends, each
// chunk starts with its line number (newlines counted per chunk, then summed), is parsed on its
// own and the chunks' points, labels, skipped lines and warnings are joined in file order. Without
// skip_bad_lines the error reported is the first in file order, as in the sequential pass.
// Room for the points is reserved from the points per byte so far and the size of the input, so
// that the point array grows about once instead of doubling; the room never used is never touched
// and so costs no resident memory.
#include "dtm/io/formats/csv.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cmath>
#include <exception>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <string>

#include "csv_detail.hpp"
#include "dtm/core/error.hpp"

namespace dtm::io {
namespace {

using csv::Cell;
using csv::Field;

constexpr double no_z = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t max_listed_warnings = 20;

/// The columns the layout gives, shared by the parsers of every chunk.
struct Columns {
    Columns(csv::Layout detected, InputRole role);

    csv::Layout layout;
    int x = -1, y = -1, z = -1, id = -1, code = -1, line = -1, needed = 0;
    bool geographic = false;
    bool polyline = false;
    bool seeds = false;
};

Columns::Columns(csv::Layout detected, InputRole role)
    : layout(std::move(detected)), polyline(role != InputRole::points) {
    x = csv::column_of(layout, Field::x);
    y = csv::column_of(layout, Field::y);
    z = csv::column_of(layout, Field::z);
    if (x < 0 || y < 0) {
        x = csv::column_of(layout, Field::lon);
        y = csv::column_of(layout, Field::lat);
        geographic = true;
    }
    id = csv::column_of(layout, Field::id);
    code = csv::column_of(layout, Field::code);
    line = polyline ? csv::column_of(layout, Field::line_id) : -1;
    seeds = role == InputRole::holes && line < 0;
    for (int c : {x, y, z, id, code, line}) needed = std::max(needed, c + 1);
}

/// Turns rows into points, polyline vertices or hole seeds: one for the whole input, or one
/// per chunk of a block.
class RowParser {
public:
    /// Called with the offset in the text reached, every 2^16 lines.
    using Report = std::function<void(std::size_t offset)>;

    RowParser(const Columns& columns, const InputFile& file, const ReadOptions& options)
        : c_(columns), file_(file), options_(options) {}

    /// Parses the lines of @p text from byte @p begin (a line start), the line before it being
    /// @p line. Returns the number of the last line.
    std::size_t parse(std::string_view text,
                      std::size_t begin,
                      std::size_t line,
                      const Report& report);
    void flush_line();
    /// Appends a later chunk's rows, labels, skipped lines and warnings.
    void append(RowParser&& later);
    /// Room for @p points points (and their labels, if the layout has any).
    void reserve(std::size_t points);
    /// Gives back the room reserved beyond the points read, if it is large.
    void shrink();

    [[nodiscard]] ReadResult& result() noexcept { return result_; }
    [[nodiscard]] std::size_t rows() const noexcept { return rows_; }

private:
    void read_row(std::string_view line, std::size_t number);
    bool number_at(int column, double& value, std::size_t number);
    void bad(std::size_t line, std::size_t column, const std::string& what);
    void add_vertex(const Point3& p, std::string_view id, std::size_t number);
    [[nodiscard]] bool labelled() const noexcept { return c_.id >= 0 || c_.code >= 0; }
    [[nodiscard]] std::string column_name(int column) const;

    const Columns& c_;
    const InputFile& file_;
    const ReadOptions& options_;
    std::vector<Cell> cells_;
    ReadResult result_;
    Polyline current_;
    std::string current_id_;
    std::size_t rows_ = 0;
};

std::string RowParser::column_name(int column) const {
    const auto c = static_cast<std::size_t>(column);
    if (c < c_.layout.names.size()) return "column '" + c_.layout.names[c] + "'";
    return "field " + std::to_string(c + 1);
}

void RowParser::bad(std::size_t line, std::size_t column, const std::string& what) {
    if (!options_.skip_bad_lines) throw InputError(file_.path, line, column, what);
    ++result_.summary.skipped_lines;
    if (result_.summary.warnings.size() < max_listed_warnings) {
        result_.summary.warnings.push_back("skipped line " + std::to_string(line) + ":" +
                                           std::to_string(column) + ": " + what);
    }
}

bool RowParser::number_at(int column, double& value, std::size_t number) {
    const Cell& cell = cells_[static_cast<std::size_t>(column)];
    if (csv::parse_number(cell.text, c_.layout.decimal_comma, value)) return true;
    const std::string shown(cell.text.substr(0, 40));
    bad(number, cell.column,
        "expected a number for " + column_name(column) + ", found '" + shown + "'");
    return false;
}

void RowParser::read_row(std::string_view line, std::size_t number) {
    if (!csv::split_fields(line, c_.layout.delimiter, cells_)) {
        bad(number, line.find('"') + 1, "expected a closing quote");
        return;
    }
    if (cells_.size() < static_cast<std::size_t>(c_.needed)) {
        bad(number, line.size() + 1,
            "expected at least " + std::to_string(c_.needed) + " fields, found " +
                std::to_string(cells_.size()) + " in '" + std::string(line.substr(0, 60)) + "'");
        return;
    }
    Point3 p{0.0, 0.0, no_z};
    if (!number_at(c_.x, p.x, number) || !number_at(c_.y, p.y, number)) return;
    if (c_.z >= 0 && !number_at(c_.z, p.z, number)) return;
    ++rows_;
    const std::string_view id =
        c_.line >= 0 ? cells_[static_cast<std::size_t>(c_.line)].text : std::string_view{};
    add_vertex(p, id, number);
}

void RowParser::add_vertex(const Point3& p, std::string_view id, std::size_t number) {
    TerrainInput& t = result_.terrain;
    if (c_.seeds) {
        t.hole_seeds.push_back(p.xy());
        return;
    }
    if (!c_.polyline) {
        t.points.push_back(p);
        if (labelled()) {
            result_.labels.ids.emplace_back(
                c_.id >= 0 ? cells_[static_cast<std::size_t>(c_.id)].text : std::string_view{});
            result_.labels.codes.emplace_back(
                c_.code >= 0 ? cells_[static_cast<std::size_t>(c_.code)].text : std::string_view{});
        }
        return;
    }
    if (!current_.points.empty() && c_.line >= 0 && id != current_id_) flush_line();
    if (current_.points.empty()) {
        current_id_ = std::string(id);
        current_.source = file_.path.string() + ":" + std::to_string(number);
    }
    current_.points.push_back(p);
}

void RowParser::flush_line() {
    if (current_.points.empty()) return;
    Polyline line = std::move(current_);
    current_ = Polyline{};
    const bool ring = file_.role == InputRole::boundary || file_.role == InputRole::holes;
    const std::size_t n = line.points.size();
    if (n >= 3 && line.points.front().xy() == line.points.back().xy()) {
        line.points.pop_back();
        line.closed = true;
    }
    if (ring) line.closed = true;
    if (line.points.size() < (ring ? 3u : 2u)) {
        result_.summary.warnings.push_back(
            line.source + ": a " + (ring ? std::string("ring") : std::string("line")) + " of " +
            std::to_string(n) + " vertices is too short and was not used");
        return;
    }
    TerrainInput& t = result_.terrain;
    switch (file_.role) {
        case InputRole::breaklines:
            t.breaklines.push_back(std::move(line));
            break;
        case InputRole::soft_breaklines:
            t.soft_breaklines.push_back(std::move(line));
            break;
        case InputRole::boundary:
            t.boundaries.push_back(std::move(line));
            break;
        case InputRole::holes:
            t.holes.push_back(std::move(line));
            break;
        case InputRole::points:
            break;
    }
}

std::size_t RowParser::parse(std::string_view text,
                             std::size_t begin,
                             std::size_t line_number,
                             const Report& report) {
    csv::LineCursor cursor(text);
    cursor.seek(begin, line_number);
    std::string_view line;
    std::size_t next_report = line_number + (1u << 16);
    while (cursor.next(line)) {
        if (csv::is_blank(line)) {
            if (c_.polyline && c_.line < 0) flush_line();
            continue;
        }
        if (csv::is_comment(line)) continue;
        read_row(line, cursor.line_number());
        if (report && cursor.line_number() >= next_report) {
            next_report += 1u << 16;
            report(cursor.offset());
        }
    }
    return cursor.line_number();
}

void RowParser::append(RowParser&& later) {
    TerrainInput& to = result_.terrain;
    TerrainInput& from = later.result_.terrain;
    to.points.insert(to.points.end(), from.points.begin(), from.points.end());
    from.points = {};
    auto& ids = result_.labels.ids;
    auto& codes = result_.labels.codes;
    ids.insert(ids.end(), std::make_move_iterator(later.result_.labels.ids.begin()),
               std::make_move_iterator(later.result_.labels.ids.end()));
    codes.insert(codes.end(), std::make_move_iterator(later.result_.labels.codes.begin()),
                 std::make_move_iterator(later.result_.labels.codes.end()));
    result_.summary.skipped_lines += later.result_.summary.skipped_lines;
    for (std::string& w : later.result_.summary.warnings) {
        if (result_.summary.warnings.size() < max_listed_warnings) {
            result_.summary.warnings.push_back(std::move(w));
        }
    }
    rows_ += later.rows_;
}

void RowParser::reserve(std::size_t points) {
    result_.terrain.points.reserve(points);
    if (!labelled()) return;
    result_.labels.ids.reserve(points);
    result_.labels.codes.reserve(points);
}

/// A copy of the used part costs a moment of twice its size; only a large overshoot is worth it.
template <class T>
void shrink_if_large(std::vector<T>& v) {
    if (v.capacity() - v.size() > v.size() / 4) v.shrink_to_fit();
}

void RowParser::shrink() {
    shrink_if_large(result_.terrain.points);
    shrink_if_large(result_.labels.ids);
    shrink_if_large(result_.labels.codes);
}

/// Offsets in @p block of the chunks from @p begin (line starts), and the block's end: several
/// chunks of at least cuts.chunk_bytes when there are threads for them, else one.
std::vector<std::size_t> chunk_starts(std::string_view block,
                                      std::size_t begin,
                                      const csv::Cuts& cuts) {
    const std::size_t size = block.size() - begin;
    const auto threads = static_cast<std::size_t>(tbb::this_task_arena::max_concurrency());
    const std::size_t chunk = std::max<std::size_t>(cuts.chunk_bytes, 1);
    const std::size_t wanted = threads > 1 ? std::min(size / chunk, 8 * threads) : 1;
    std::vector<std::size_t> starts{begin};
    for (std::size_t k = 1; k < wanted; ++k) {
        const std::size_t nominal = begin + size / wanted * k;
        const std::size_t nl = block.find('\n', nominal);
        if (nl == std::string_view::npos) break;
        if (nl + 1 > starts.back() && nl + 1 < block.size()) starts.push_back(nl + 1);
    }
    starts.push_back(block.size());
    return starts;
}

/// The number of the line before each chunk, and the last line's: the newlines of every chunk
/// counted in parallel, then summed in order from @p line.
std::vector<std::size_t> chunk_lines(std::string_view block,
                                     const std::vector<std::size_t>& starts,
                                     std::size_t line) {
    const std::size_t chunks = starts.size() - 1;
    std::vector<std::size_t> lines(chunks + 1, 0);
    tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t k) {
        const std::string_view part = block.substr(starts[k], starts[k + 1] - starts[k]);
        lines[k + 1] = static_cast<std::size_t>(std::count(part.begin(), part.end(), '\n'));
    });
    lines[0] = line;
    for (std::size_t k = 0; k < chunks; ++k) lines[k + 1] += lines[k];
    return lines;
}

class CsvReader {
public:
    CsvReader(csv::Blocks& blocks,
              std::string_view head,
              std::size_t size,
              const InputFile& file,
              const ReadOptions& options,
              const Progress& progress,
              const csv::Cuts& cuts)
        : blocks_(blocks),
          file_(file),
          options_(options),
          progress_(progress),
          cuts_(cuts),
          size_(size),
          columns_(csv::detect_layout(
                       head, file.path.string(), options.columns, file.role != InputRole::points),
                   file.role),
          parser_(columns_, file, options) {}
    CsvReader(const CsvReader&) = delete;
    CsvReader& operator=(const CsvReader&) = delete;

    /// Reads the input from @p head, its first block.
    ReadResult run(std::string_view head);

private:
    /// Parses @p block from @p begin, the line before being @p line; returns the last line.
    std::size_t parse_block(std::string_view block, std::size_t begin, std::size_t line);
    /// Points only: the chunks of @p block in parallel, joined in file order.
    void parse_chunks(std::string_view block,
                      const std::vector<std::size_t>& starts,
                      const std::vector<std::size_t>& lines);
    /// Room for @p more points beyond those read, the block read reaching byte @p through.
    void make_room(std::size_t more, std::size_t through);
    void report(std::size_t offset) const;

    csv::Blocks& blocks_;
    const InputFile& file_;
    const ReadOptions& options_;
    const Progress& progress_;
    csv::Cuts cuts_;
    std::size_t size_;  ///< bytes of the input, 0 if unknown
    Columns columns_;
    RowParser parser_;
};

ReadResult CsvReader::run(std::string_view head) {
    ReadResult& result = parser_.result();
    result.summary.path = file_.path;
    result.summary.format = "text";
    const csv::Layout& layout = columns_.layout;
    if (!columns_.polyline && columns_.z < 0) {
        throw InputError(file_.path, layout.header_line, 0,
                         "expected a z column for points (z, elev, elevation, height, h, alt; "
                         "or `columns`)");
    }
    std::size_t line = parse_block(head, layout.data_offset, layout.data_line);
    for (std::string_view block = blocks_.next(); !block.empty(); block = blocks_.next()) {
        line = parse_block(block, 0, line);
    }
    parser_.flush_line();
    parser_.shrink();
    if (layout.count_line > 0 && layout.declared_count != parser_.rows()) {
        result.summary.warnings.push_back("line " + std::to_string(layout.count_line) +
                                          " declares " + std::to_string(layout.declared_count) +
                                          " points, the file has " +
                                          std::to_string(parser_.rows()));
    }
    if (columns_.geographic) {
        result.crs_wkt = "EPSG:4326";
        result.summary.crs = "EPSG:4326";
    }
    return std::move(result);
}

std::size_t CsvReader::parse_block(std::string_view block, std::size_t begin, std::size_t line) {
    const RowParser::Report report = [&](std::size_t offset) {
        this->report(blocks_.offset() + offset);
    };
    if (columns_.polyline) return parser_.parse(block, begin, line, report);
    const std::vector<std::size_t> starts = chunk_starts(block, begin, cuts_);
    const std::vector<std::size_t> lines = chunk_lines(block, starts, line);
    make_room(lines.back() - line + 1, blocks_.offset() + block.size());
    if (starts.size() == 2) return parser_.parse(block, begin, line, report);
    parse_chunks(block, starts, lines);
    return lines.back();
}

void CsvReader::parse_chunks(std::string_view block,
                             const std::vector<std::size_t>& starts,
                             const std::vector<std::size_t>& lines) {
    const std::size_t chunks = starts.size() - 1;
    std::vector<RowParser> parts(chunks, RowParser(columns_, file_, options_));
    std::vector<std::exception_ptr> errors(chunks);
    std::atomic<std::size_t> done{blocks_.offset() + starts[0]};
    tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t k) {
        try {
            parts[k].reserve(lines[k + 1] - lines[k] + 1);
            parts[k].parse(block.substr(0, starts[k + 1]), starts[k], lines[k], {});
        } catch (const InputError&) {
            errors[k] = std::current_exception();
        }
        report(done.fetch_add(starts[k + 1] - starts[k]) + starts[k + 1] - starts[k]);
    });
    for (const std::exception_ptr& e : errors) {
        if (e) std::rethrow_exception(e);  // the first error in file order
    }
    for (RowParser& part : parts) parser_.append(std::move(part));
}

void CsvReader::make_room(std::size_t more, std::size_t through) {
    const std::vector<Point3>& points = parser_.result().terrain.points;
    const std::size_t needed = points.size() + more;
    const std::size_t capacity = points.capacity();
    if (needed <= capacity) return;
    std::size_t room = needed;
    if (size_ == 0) {
        room = std::max(needed, 2 * capacity);  // size unknown: grow as a vector does
    } else if (through < size_) {
        // The points of the whole input at the rate so far, and 1/32 more; at least 1/8 more.
        const double estimate = static_cast<double>(needed) / static_cast<double>(through) *
                                static_cast<double>(size_) * (1.0 + 1.0 / 32);
        room = std::max({needed, capacity + capacity / 8, static_cast<std::size_t>(estimate)});
    }
    parser_.reserve(room);
}

void CsvReader::report(std::size_t offset) const {
    if (size_ == 0) return;
    progress_.report(std::min(1.0, static_cast<double>(offset) / static_cast<double>(size_)));
}

/// The first block, extended until it holds every line layout detection looks at.
std::string_view first_block(csv::Blocks& blocks) {
    std::string_view head = blocks.next();
    while (!blocks.at_end() && !csv::holds_layout_sample(head)) head = blocks.extend();
    return head;
}

ReadResult parse_blocks(csv::Blocks& blocks,
                        std::string_view head,
                        std::size_t size,
                        const InputFile& file,
                        const ReadOptions& options,
                        const Progress& progress,
                        const csv::Cuts& cuts) {
    CsvReader reader(blocks, head, size, file, options, progress, cuts);
    return reader.run(head);
}

}  // namespace

bool csv_has_geometry_column(std::string_view text) {
    csv::LineCursor cursor(text);
    std::string_view line;
    while (cursor.next(line)) {
        if (csv::is_blank(line) || csv::is_comment(line)) continue;
        std::vector<Cell> cells;
        const char delimiter = line.find(';') != std::string_view::npos ? ';' : ',';
        if (!csv::split_fields(line, delimiter, cells)) return false;
        for (const Cell& c : cells) {
            std::string name;
            for (char ch : c.text)
                name += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
            if (name == "wkt" || name == "geometry" || name == "the_geom" || name == "geom" ||
                name == "wkt_geom")
                return true;
        }
        return false;
    }
    return false;
}

ReadResult read_csv(const InputFile& file, const ReadOptions& options, const Progress& progress) {
    return csv::read_csv(file, options, progress, csv::Cuts{});
}

ReadResult parse_csv_text(std::string_view text,
                          const InputFile& file,
                          const ReadOptions& options,
                          const Progress& progress) {
    return csv::parse_csv_text(text, file, options, progress, csv::Cuts{});
}

namespace csv {

ReadResult read_csv(const InputFile& file,
                    const ReadOptions& options,
                    const Progress& progress,
                    const Cuts& cuts) {
    std::ifstream in(file.path, std::ios::binary);
    if (!in) throw InputError(file.path, 0, 0, "cannot open the file");
    std::error_code ec;
    const auto size = std::filesystem::file_size(file.path, ec);
    const std::size_t known = ec ? 0 : static_cast<std::size_t>(size);
    Blocks blocks(
        [&in](char* to, std::size_t bytes) {
            in.read(to, static_cast<std::streamsize>(bytes));
            return static_cast<std::size_t>(in.gcount());
        },
        cuts.block_bytes, known);
    const std::string_view head = first_block(blocks);
    ReadResult result = parse_blocks(blocks, head, known, file, options, progress, cuts);
    // A sidecar .prj (as next to a shapefile) gives the CRS of a text file.
    std::filesystem::path prj = file.path;
    prj.replace_extension(".prj");
    if (result.crs_wkt.empty() && std::filesystem::is_regular_file(prj, ec)) {
        std::ifstream prj_in(prj, std::ios::binary);
        std::string wkt((std::istreambuf_iterator<char>(prj_in)), std::istreambuf_iterator<char>());
        if (!wkt.empty()) result.crs_wkt = std::move(wkt);
    }
    return result;
}

ReadResult parse_csv_text(std::string_view text,
                          const InputFile& file,
                          const ReadOptions& options,
                          const Progress& progress,
                          const Cuts& cuts) {
    std::size_t at = 0;
    Blocks blocks(
        [text, &at](char* to, std::size_t bytes) {
            const std::size_t n = std::min(bytes, text.size() - at);
            std::copy_n(text.data() + at, n, to);
            at += n;
            return n;
        },
        cuts.block_bytes, text.size());
    const std::string_view head = first_block(blocks);
    return parse_blocks(blocks, head, text.size(), file, options, progress, cuts);
}

}  // namespace csv
}  // namespace dtm::io

namespace dtm::io::csv {

ReadResult parse_points_range(std::string_view text,
                              std::size_t line,
                              const Layout& layout,
                              const InputFile& file,
                              const ReadOptions& options) {
    const Columns columns(layout, InputRole::points);
    if (columns.z < 0) {
        throw InputError(file.path, layout.header_line, 0,
                         "expected a z column for points (z, elev, elevation, height, h, alt; "
                         "or `columns`)");
    }
    RowParser parser(columns, file, options);
    parser.parse(text, 0, line, {});
    parser.flush_line();
    parser.shrink();
    ReadResult& result = parser.result();
    result.summary.path = file.path;
    result.summary.format = "text";
    if (columns.geographic) {
        result.crs_wkt = "EPSG:4326";
        result.summary.crs = "EPSG:4326";
    }
    return std::move(result);
}

}  // namespace dtm::io::csv
