// SPDX-License-Identifier: MIT
// Delimited text: scanning lines and fields, parsing numbers, and detecting the layout.
//
// Detection looks at the first 20 data lines (blank and comment lines skipped):
//   - delimiter: ';' if any sample line has one outside quotes, else tab, else ',', else runs of
//     blanks. A decimal comma is accepted with ';', tab and blank delimiters only;
//   - a first line holding one integer, followed by lines with several fields, is a point count;
//   - the first line is a header if it has a field that is not a number and either a field
//     names a known column or the next line has fewer non-numbers;
//   - columns are mapped by header name, or by ReadOptions::columns, or guessed: "x y [z]"; for
//   points,
//     "id x y z [code]" when the first of 4+ columns holds integers and the next two do not;
//     for polylines, "line_id x y [z]" when the first of 3+ columns does (pputils layout).
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstring>
#include <set>
#include <string>

#include "csv_detail.hpp"
#include "dtm/core/error.hpp"

namespace dtm::io::csv {

LineCursor::LineCursor(std::string_view text) : text_(text) {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;
}

bool LineCursor::next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    const char* begin = text_.data() + pos_;
    const std::size_t rest = text_.size() - pos_;
    const void* nl = std::memchr(begin, '\n', rest);
    std::size_t len = nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - begin) : rest;
    pos_ += len + (nl ? 1 : 0);
    if (len > 0 && begin[len - 1] == '\r') --len;
    line = std::string_view(begin, len);
    ++line_number_;
    return true;
}

bool is_blank(std::string_view line) noexcept {
    return std::all_of(line.begin(), line.end(), [](char c) { return c == ' ' || c == '\t'; });
}

bool is_comment(std::string_view line) noexcept {
    const std::size_t i = line.find_first_not_of(" \t");
    if (i == std::string_view::npos) return false;
    return line[i] == '#' || line.substr(i, 2) == "//";
}

namespace {

bool is_space(char c) noexcept { return c == ' ' || c == '\t'; }

std::string_view trim(std::string_view s) noexcept {
    while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
    while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
    return s;
}

/// Reads one quoted field starting at line[i] == '"'; returns the index after the closing quote
/// or npos if it is unterminated. "" inside stays doubled in the view (ids only).
std::size_t end_of_quoted(std::string_view line, std::size_t i) noexcept {
    for (std::size_t j = i + 1; j < line.size(); ++j) {
        if (line[j] != '"') continue;
        if (j + 1 < line.size() && line[j + 1] == '"') {
            ++j;
            continue;
        }
        return j + 1;
    }
    return std::string_view::npos;
}

}  // namespace

bool split_fields(std::string_view line, char delimiter, std::vector<Cell>& cells) {
    cells.clear();
    std::size_t i = 0;
    const std::size_t n = line.size();
    const bool blanks = delimiter == ' ';
    while (true) {
        while (i < n && is_space(line[i])) ++i;
        if (blanks && i >= n) return true;
        const std::size_t start = i;
        Cell cell{{}, start + 1};
        if (i < n && line[i] == '"') {
            const std::size_t end = end_of_quoted(line, i);
            if (end == std::string_view::npos) return false;
            cell.text = line.substr(i + 1, end - i - 2);
            i = end;
            while (i < n && !(blanks ? is_space(line[i]) : line[i] == delimiter)) ++i;
        } else {
            while (i < n && !(blanks ? is_space(line[i]) : line[i] == delimiter)) ++i;
            cell.text = trim(line.substr(start, i - start));
        }
        cells.push_back(cell);
        if (i >= n) return true;
        ++i;  // past the delimiter (for blanks, the run is skipped at the loop top)
    }
}

bool parse_number(std::string_view text, bool decimal_comma, double& value) noexcept {
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    if (text.empty()) return false;
    char buffer[64];
    if (decimal_comma && text.find(',') != std::string_view::npos) {
        if (text.size() >= sizeof buffer) return false;
        std::copy(text.begin(), text.end(), buffer);
        std::replace(buffer, buffer + text.size(), ',', '.');
        text = std::string_view(buffer, text.size());
    }
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, value, std::chars_format::general);
    return ec == std::errc{} && ptr == end && std::isfinite(value);
}

Field field_from_name(std::string_view raw, bool polyline) {
    std::string name;
    for (char c : trim(raw)) name += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    static const std::set<std::string, std::less<>> xs{"x", "east", "easting", "e"};
    static const std::set<std::string, std::less<>> ys{"y", "north", "northing", "n"};
    static const std::set<std::string, std::less<>> zs{"z", "elev", "elevation", "height",
                                                       "h", "alt",  "altitude",  "zz"};
    static const std::set<std::string, std::less<>> lats{"lat", "latitude"};
    static const std::set<std::string, std::less<>> lons{"lon", "long", "longitude", "lng"};
    static const std::set<std::string, std::less<>> ids{
        "id", "name", "point", "number", "cislo", "\xC4\x8D\xC3\xADslo", "pt", "pid"};
    static const std::set<std::string, std::less<>> codes{"code", "kod",
                                                          "k\xC3\xB3"
                                                          "d"};
    static const std::set<std::string, std::less<>> lines{"shapeid", "shape_id", "line", "line_id",
                                                          "lineid"};
    if (xs.count(name)) return Field::x;
    if (ys.count(name)) return Field::y;
    if (zs.count(name)) return Field::z;
    if (lats.count(name)) return Field::lat;
    if (lons.count(name)) return Field::lon;
    if (lines.count(name)) return Field::line_id;
    if (ids.count(name)) return polyline && name == "id" ? Field::line_id : Field::id;
    if (codes.count(name)) return Field::code;
    return Field::skip;
}

int column_of(const Layout& layout, Field f) noexcept {
    const auto it = std::find(layout.fields.begin(), layout.fields.end(), f);
    return it == layout.fields.end() ? -1 : static_cast<int>(it - layout.fields.begin());
}

namespace {

/// How many data lines detection looks at (a point-count line, if any, is the first of them).
constexpr std::size_t sample_size = 21;

struct SampleLine {
    std::string_view text;
    std::size_t number = 0;
    std::size_t end_offset = 0;  ///< offset just past this line
};

std::vector<SampleLine> sample_lines(std::string_view text, std::size_t wanted) {
    std::vector<SampleLine> out;
    LineCursor cursor(text);
    std::string_view line;
    while (out.size() < wanted && cursor.next(line)) {
        if (is_blank(line) || is_comment(line)) continue;
        out.push_back({line, cursor.line_number(), cursor.offset()});
    }
    return out;
}

/// Count of @p c outside double quotes.
std::size_t count_unquoted(std::string_view line, char c) noexcept {
    std::size_t count = 0;
    bool quoted = false;
    for (char ch : line) {
        if (ch == '"')
            quoted = !quoted;
        else if (ch == c && !quoted)
            ++count;
    }
    return count;
}

char detect_delimiter(const std::vector<SampleLine>& sample) {
    std::size_t semicolons = 0, tabs = 0, commas = 0;
    for (const SampleLine& s : sample) {
        semicolons += count_unquoted(s.text, ';');
        tabs += count_unquoted(s.text, '\t');
        commas += count_unquoted(s.text, ',');
    }
    if (semicolons > 0) return ';';
    if (tabs > 0) {
        // A tab-separated file has tabs on every line; stray tabs among blanks are blanks.
        const bool every = std::all_of(sample.begin(), sample.end(), [](const SampleLine& s) {
            return count_unquoted(s.text, '\t') > 0;
        });
        if (every) return '\t';
    }
    if (commas > 0) return ',';
    return ' ';
}

bool is_integer(std::string_view text) noexcept {
    long long v = 0;
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    return ec == std::errc{} && ptr == text.data() + text.size();
}

std::size_t non_numbers(const std::vector<Cell>& cells, bool decimal_comma) {
    double v = 0;
    return static_cast<std::size_t>(std::count_if(cells.begin(), cells.end(), [&](const Cell& c) {
        return !parse_number(c.text, decimal_comma, v);
    }));
}

}  // namespace

namespace {

[[noreturn]] void fail(const std::string& file,
                       std::size_t line,
                       std::size_t column,
                       const std::string& what) {
    throw InputError(file, line, column, what);
}

std::vector<Field> fields_from_columns(const std::string& columns,
                                       const std::string& file,
                                       bool polyline) {
    std::vector<Field> fields;
    std::size_t start = 0;
    while (start <= columns.size()) {
        std::size_t end = columns.find(',', start);
        if (end == std::string::npos) end = columns.size();
        const std::string_view word = trim(std::string_view(columns).substr(start, end - start));
        Field f = field_from_name(word, polyline);
        if (f == Field::skip && !(word.empty() || word == "-" || word == "skip" || word == "_")) {
            fail(file, 0, 0,
                 "`columns`: expected a column name (x, y, z, east, north, elev, lat, lon, id, "
                 "code, shapeid or - to skip), found '" +
                     std::string(word) + "'");
        }
        fields.push_back(f);
        start = end + 1;
    }
    return fields;
}

/// Guesses the roles of a headerless file from its first data lines.
std::vector<Field> guess_fields(const std::vector<std::vector<Cell>>& rows,
                                bool polyline,
                                bool decimal_comma) {
    const std::size_t n = rows.front().size();
    std::vector<Field> fields(n, Field::skip);
    if (n < 2) return fields;
    const auto all_integer = [&](std::size_t col) {
        return std::all_of(rows.begin(), rows.end(), [&](const std::vector<Cell>& r) {
            return r.size() > col && is_integer(r[col].text);
        });
    };
    bool first_is_id = false;
    first_is_id =
        n >= (polyline ? 3u : 4u) && all_integer(0) && !(all_integer(1) && all_integer(2));
    const std::size_t c0 = first_is_id ? 1 : 0;
    if (first_is_id) fields[0] = polyline ? Field::line_id : Field::id;
    fields[c0] = Field::x;
    fields[c0 + 1] = Field::y;
    if (c0 + 2 < n) fields[c0 + 2] = Field::z;
    double v = 0;
    if (first_is_id && !polyline && n >= 5 && !parse_number(rows.front()[4].text, decimal_comma, v))
        fields[4] = Field::code;
    return fields;
}

void check_header_fields(Layout& layout, const std::vector<Cell>& cells, const std::string& file) {
    for (std::size_t i = 0; i < layout.fields.size(); ++i) {
        if (layout.fields[i] == Field::skip) continue;
        for (std::size_t j = 0; j < i; ++j) {
            if (layout.fields[j] == layout.fields[i]) {
                fail(file, layout.header_line, cells[i].column,
                     "expected one column per coordinate, found '" + std::string(cells[i].text) +
                         "' naming the same thing as '" + std::string(cells[j].text) + "'");
            }
        }
    }
}

}  // namespace

bool holds_layout_sample(std::string_view text) {
    return sample_lines(text, sample_size).size() == sample_size;
}

Layout detect_layout(std::string_view text,
                     const std::string& file,
                     const std::string& columns,
                     bool polyline) {
    std::vector<SampleLine> sample = sample_lines(text, sample_size);
    if (sample.empty()) fail(file, 0, 0, "expected data lines, found an empty file");
    Layout layout;
    std::size_t first = 0;
    if (sample.size() > 1 && is_integer(trim(sample[0].text))) {
        layout.count_line = sample[0].number;
        long long declared = 0;
        const auto t = trim(sample[0].text);
        std::from_chars(t.data(), t.data() + t.size(), declared);
        layout.declared_count = declared > 0 ? static_cast<std::size_t>(declared) : 0;
        first = 1;
    }
    sample.erase(sample.begin(), sample.begin() + static_cast<std::ptrdiff_t>(first));
    layout.delimiter = detect_delimiter(sample);
    layout.decimal_comma = layout.delimiter != ',';
    std::vector<std::vector<Cell>> rows;
    for (const SampleLine& s : sample) {
        rows.emplace_back();
        if (!split_fields(s.text, layout.delimiter, rows.back())) rows.pop_back();
    }
    if (rows.empty()) fail(file, sample[0].number, 0, "expected a closing quote");
    const std::size_t bad_first = non_numbers(rows[0], layout.decimal_comma);
    bool named = false;
    for (const Cell& c : rows[0]) named = named || field_from_name(c.text, polyline) != Field::skip;
    const bool header =
        bad_first > 0 &&
        (named || (rows.size() > 1 && non_numbers(rows[1], layout.decimal_comma) < bad_first));
    layout.data_offset =
        first > 0 ? sample_lines(text, 1).front().end_offset : LineCursor(text).offset();
    layout.data_line = first > 0 ? layout.count_line : 0;
    if (header) {
        layout.header_line = sample[0].number;
        layout.data_offset = sample[0].end_offset;
        layout.data_line = sample[0].number;
        for (const Cell& c : rows[0]) {
            layout.names.emplace_back(c.text);
            layout.fields.push_back(field_from_name(c.text, polyline));
        }
        check_header_fields(layout, rows[0], file);
        rows.erase(rows.begin());
    }
    if (!columns.empty()) {
        layout.fields = fields_from_columns(columns, file, polyline);
    } else if (!header) {
        layout.fields = guess_fields(rows, polyline, layout.decimal_comma);
    }
    const bool planar = column_of(layout, Field::x) >= 0 && column_of(layout, Field::y) >= 0;
    const bool geographic =
        column_of(layout, Field::lat) >= 0 && column_of(layout, Field::lon) >= 0;
    if (!planar && !geographic) {
        fail(file, layout.header_line > 0 ? layout.header_line : sample[0].number, 0,
             "expected x and y columns (x/y, east/north, e/n or lat/lon; or `columns`), found " +
                 std::to_string(rows.empty() ? 0 : rows[0].size()) + " unnamed columns");
    }
    return layout;
}

}  // namespace dtm::io::csv
