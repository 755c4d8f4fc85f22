// SPDX-License-Identifier: MIT
// Delimited text reader: one pass over the text held in one buffer, std::from_chars for the
// numbers, no per-line allocation (fields are views into the buffer). The layout comes from
// csv_layout.cpp. Rows become points, or polyline vertices grouped by a line-id column
// (pputils "shapeid,x,y[,z]"), or hole seeds.
//
// A large point file is parsed in parallel: the data is cut into chunks at line ends, each chunk
// starts with its line number (newlines counted per chunk, then summed), is parsed on its own and
// the chunks' points, labels, skipped lines and warnings are joined in file order. Without
// --skip-bad-lines the error reported is the first in file order, as in the sequential pass.
#include "dtm/io/formats/csv.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <exception>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

#include "csv_detail.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/formats/ogr.hpp"

namespace dtm::io {
namespace {

using csv::Cell;
using csv::Field;

constexpr double no_z = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t max_listed_warnings = 20;
constexpr std::size_t parallel_chunk_bytes = std::size_t{4} << 20;  ///< at least, per chunk

class CsvReader {
public:
    CsvReader(std::string_view text, const InputFile& file, const LoadOptions& options,
              const Progress& progress)
        : text_(text), file_(file), options_(options), progress_(progress),
          polyline_(file.role != InputRole::points),
          layout_(csv::detect_layout(text, file.path.string(), options.columns, polyline_))
    {
        x_ = csv::column_of(layout_, Field::x);
        y_ = csv::column_of(layout_, Field::y);
        z_ = csv::column_of(layout_, Field::z);
        if (x_ < 0 || y_ < 0) {
            x_ = csv::column_of(layout_, Field::lon);
            y_ = csv::column_of(layout_, Field::lat);
            geographic_ = true;
        }
        id_ = csv::column_of(layout_, Field::id);
        code_ = csv::column_of(layout_, Field::code);
        line_ = polyline_ ? csv::column_of(layout_, Field::line_id) : -1;
        seeds_ = file.role == InputRole::holes && line_ < 0;
        for (int c : {x_, y_, z_, id_, code_, line_}) needed_ = std::max(needed_, c + 1);
    }

    ReadResult run();

private:
    /// Parses the rows of [begin, end) (line starts), the line before @p begin being @p line.
    void parse_range(std::size_t begin, std::size_t end, std::size_t line, bool report);
    /// Points only: the data in chunks, in parallel, joined in file order.
    void parse_chunks();
    /// Appends a later chunk's rows, labels, skipped lines and warnings.
    void append(CsvReader&& later);

    void read_row(std::string_view line, std::size_t number);
    bool number_at(int column, double& value, std::size_t number);
    void bad(std::size_t line, std::size_t column, const std::string& what);
    void add_vertex(const Point3& p, std::string_view id, std::size_t number);
    void flush_line();
    [[nodiscard]] std::string column_name(int column) const;

    std::string_view text_;
    const InputFile& file_;
    const LoadOptions& options_;
    const Progress& progress_;
    bool polyline_;
    csv::Layout layout_;
    int x_ = -1, y_ = -1, z_ = -1, id_ = -1, code_ = -1, line_ = -1, needed_ = 0;
    bool geographic_ = false;
    bool seeds_ = false;
    std::vector<Cell> cells_;
    ReadResult result_;
    Polyline current_;
    std::string current_id_;
    std::size_t rows_ = 0;
};

std::string CsvReader::column_name(int column) const
{
    const auto c = static_cast<std::size_t>(column);
    if (c < layout_.names.size()) return "column '" + layout_.names[c] + "'";
    return "field " + std::to_string(c + 1);
}

void CsvReader::bad(std::size_t line, std::size_t column, const std::string& what)
{
    if (!options_.skip_bad_lines) throw InputError(file_.path, line, column, what);
    ++result_.summary.skipped_lines;
    if (result_.summary.warnings.size() < max_listed_warnings) {
        result_.summary.warnings.push_back("skipped line " + std::to_string(line) + ":" +
                                           std::to_string(column) + ": " + what);
    }
}

bool CsvReader::number_at(int column, double& value, std::size_t number)
{
    const Cell& cell = cells_[static_cast<std::size_t>(column)];
    if (csv::parse_number(cell.text, layout_.decimal_comma, value)) return true;
    const std::string shown(cell.text.substr(0, 40));
    bad(number, cell.column,
        "expected a number for " + column_name(column) + ", found '" + shown + "'");
    return false;
}

void CsvReader::read_row(std::string_view line, std::size_t number)
{
    if (!csv::split_fields(line, layout_.delimiter, cells_)) {
        bad(number, line.find('"') + 1, "expected a closing quote");
        return;
    }
    if (cells_.size() < static_cast<std::size_t>(needed_)) {
        bad(number, line.size() + 1,
            "expected at least " + std::to_string(needed_) + " fields, found " +
                std::to_string(cells_.size()) + " in '" + std::string(line.substr(0, 60)) + "'");
        return;
    }
    Point3 p{0.0, 0.0, no_z};
    if (!number_at(x_, p.x, number) || !number_at(y_, p.y, number)) return;
    if (z_ >= 0 && !number_at(z_, p.z, number)) return;
    ++rows_;
    const std::string_view id = line_ >= 0 ? cells_[static_cast<std::size_t>(line_)].text
                                           : std::string_view{};
    add_vertex(p, id, number);
}

void CsvReader::add_vertex(const Point3& p, std::string_view id, std::size_t number)
{
    TerrainInput& t = result_.terrain;
    if (seeds_) {
        t.hole_seeds.push_back(p.xy());
        return;
    }
    if (!polyline_) {
        t.points.push_back(p);
        if (id_ >= 0 || code_ >= 0) {
            result_.labels.ids.emplace_back(
                id_ >= 0 ? cells_[static_cast<std::size_t>(id_)].text : std::string_view{});
            result_.labels.codes.emplace_back(
                code_ >= 0 ? cells_[static_cast<std::size_t>(code_)].text : std::string_view{});
        }
        return;
    }
    if (!current_.points.empty() && line_ >= 0 && id != current_id_) flush_line();
    if (current_.points.empty()) {
        current_id_ = std::string(id);
        current_.source = file_.path.string() + ":" + std::to_string(number);
    }
    current_.points.push_back(p);
}

void CsvReader::flush_line()
{
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
        result_.summary.warnings.push_back(line.source + ": a " +
                                           (ring ? std::string("ring") : std::string("line")) +
                                           " of " + std::to_string(n) +
                                           " vertices is too short and was not used");
        return;
    }
    TerrainInput& t = result_.terrain;
    switch (file_.role) {
        case InputRole::breaklines: t.breaklines.push_back(std::move(line)); break;
        case InputRole::soft_breaklines: t.soft_breaklines.push_back(std::move(line)); break;
        case InputRole::boundary: t.boundaries.push_back(std::move(line)); break;
        case InputRole::holes: t.holes.push_back(std::move(line)); break;
        case InputRole::points: break;
    }
}

ReadResult CsvReader::run()
{
    result_.summary.path = file_.path;
    result_.summary.format = "text";
    if (!polyline_ && z_ < 0) {
        throw InputError(file_.path, layout_.header_line, 0,
                         "expected a z column for points (z, elev, elevation, height, h, alt; "
                         "or --columns)");
    }
    const bool parallel = !polyline_ && !seeds_ &&
                          text_.size() - layout_.data_offset >= 2 * parallel_chunk_bytes &&
                          tbb::this_task_arena::max_concurrency() > 1;
    if (parallel) {
        parse_chunks();
    } else {
        parse_range(layout_.data_offset, text_.size(), layout_.data_line, true);
    }
    flush_line();
    if (layout_.count_line > 0 && layout_.declared_count != rows_) {
        result_.summary.warnings.push_back(
            "line " + std::to_string(layout_.count_line) + " declares " +
            std::to_string(layout_.declared_count) + " points, the file has " +
            std::to_string(rows_));
    }
    if (geographic_) {
        result_.crs_wkt = "EPSG:4326";
        result_.summary.crs = "EPSG:4326";
    }
    return std::move(result_);
}

void CsvReader::parse_range(std::size_t begin, std::size_t end, std::size_t line_number,
                            bool report)
{
    csv::LineCursor cursor(text_.substr(0, end));
    cursor.seek(begin, line_number);
    std::string_view line;
    std::size_t next_report = 1u << 16;
    while (cursor.next(line)) {
        if (csv::is_blank(line)) {
            if (polyline_ && line_ < 0) flush_line();
            continue;
        }
        if (csv::is_comment(line)) continue;
        read_row(line, cursor.line_number());
        if (report && cursor.line_number() >= next_report) {
            next_report += 1u << 16;
            progress_.report(static_cast<double>(cursor.offset()) /
                             static_cast<double>(text_.size()));
        }
    }
}

void CsvReader::parse_chunks()
{
    const std::size_t begin = layout_.data_offset;
    const std::size_t size = text_.size() - begin;
    const std::size_t wanted = std::min<std::size_t>(
        size / parallel_chunk_bytes, 8 * static_cast<std::size_t>(tbb::this_task_arena::max_concurrency()));
    std::vector<std::size_t> starts{begin};
    for (std::size_t k = 1; k < wanted; ++k) {
        const std::size_t nominal = begin + size / wanted * k;
        const std::size_t nl = text_.find('\n', nominal);
        if (nl == std::string_view::npos) break;
        if (nl + 1 > starts.back() && nl + 1 < text_.size()) starts.push_back(nl + 1);
    }
    starts.push_back(text_.size());
    const std::size_t chunks = starts.size() - 1;
    // Line numbers: the newlines of every chunk, counted in parallel, then summed in order.
    std::vector<std::size_t> first_line(chunks + 1, 0);
    tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t k) {
        const std::string_view part = text_.substr(starts[k], starts[k + 1] - starts[k]);
        first_line[k + 1] = static_cast<std::size_t>(std::count(part.begin(), part.end(), '\n'));
    });
    first_line[0] = layout_.data_line;
    for (std::size_t k = 0; k < chunks; ++k) first_line[k + 1] += first_line[k];
    std::vector<CsvReader> parts(chunks, *this);
    std::vector<std::exception_ptr> errors(chunks);
    std::atomic<std::size_t> done{0};
    tbb::parallel_for(std::size_t{0}, chunks, [&](std::size_t k) {
        try {
            parts[k].parse_range(starts[k], starts[k + 1], first_line[k], false);
        } catch (const InputError&) {
            errors[k] = std::current_exception();
        }
        const std::size_t bytes = done.fetch_add(starts[k + 1] - starts[k]) + starts[k + 1] - starts[k];
        progress_.report(static_cast<double>(bytes) / static_cast<double>(size));
    });
    for (const std::exception_ptr& e : errors) {
        if (e) std::rethrow_exception(e);  // the first error in file order
    }
    std::size_t total = result_.terrain.points.size();
    for (const CsvReader& part : parts) total += part.result_.terrain.points.size();
    result_.terrain.points.reserve(total);
    for (CsvReader& part : parts) append(std::move(part));
}

void CsvReader::append(CsvReader&& later)
{
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

}  // namespace

ReadResult parse_csv_text(std::string_view text, const InputFile& file,
                          const LoadOptions& options, const Progress& progress)
{
    CsvReader reader(text, file, options, progress);
    return reader.run();
}

bool csv_has_geometry_column(std::string_view text)
{
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

ReadResult read_csv(const InputFile& file, const LoadOptions& options, const Progress& progress)
{
    std::ifstream in(file.path, std::ios::binary);
    if (!in) throw InputError(file.path, 0, 0, "cannot open the file");
    std::error_code ec;
    const auto size = std::filesystem::file_size(file.path, ec);
    std::string text;
    if (!ec) {
        text.resize(static_cast<std::size_t>(size));
        in.read(text.data(), static_cast<std::streamsize>(size));
        text.resize(static_cast<std::size_t>(in.gcount()));
    } else {
        text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    if (csv_has_geometry_column(text)) {
        ReadResult r = read_ogr(file, options, progress);
        r.summary.format = "text (OGR, geometry column)";
        return r;
    }
    ReadResult result = parse_csv_text(text, file, options, progress);
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

}  // namespace dtm::io
