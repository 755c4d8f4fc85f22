// SPDX-License-Identifier: MIT
/// @file
/// @brief Internals of the delimited-text reader: reading in blocks, line scanning, field
/// splitting, number parsing and layout detection (shared by csv_blocks.cpp, csv_layout.cpp and
/// csv.cpp; the tests use the cuts below).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "dtm/core/progress.hpp"
#include "dtm/io/reader.hpp"

namespace dtm::io::csv {

/// How the reader cuts its input: the blocks it reads at a time and the chunks it parses in
/// parallel. The tests lower both so that a small input spans many blocks and chunks.
struct Cuts {
    std::size_t block_bytes = std::size_t{32} << 20;  ///< read at a time (more for a longer line)
    std::size_t chunk_bytes = std::size_t{4} << 20;   ///< parsed by one task, at least
};

/// read_csv() and parse_csv_text() with the given cuts.
[[nodiscard]] ReadResult read_csv(const InputFile& file,
                                  const ReadOptions& options,
                                  const Progress& progress,
                                  const Cuts& cuts);
[[nodiscard]] ReadResult parse_csv_text(std::string_view text,
                                        const InputFile& file,
                                        const ReadOptions& options,
                                        const Progress& progress,
                                        const Cuts& cuts);

/// Reads an input in blocks that end at a line end (or at the end of the input), reusing one
/// buffer: a block is valid until the next call of next() or extend().
class Blocks {
public:
    /// Reads up to @p bytes into @p to and returns how many: 0 at the end of the input.
    using Fill = std::function<std::size_t(char* to, std::size_t bytes)>;
    /// @p input_bytes: the size of the input if known (a smaller input gets a smaller buffer),
    /// else 0.
    Blocks(Fill fill, std::size_t block_bytes, std::size_t input_bytes);
    /// The next block; empty at the end of the input.
    std::string_view next();
    /// The current block with the lines that follow it, up to about another block's worth.
    std::string_view extend();
    /// Offset in the input of the current block.
    [[nodiscard]] std::size_t offset() const noexcept { return offset_; }
    /// True if nothing follows the current block.
    [[nodiscard]] bool at_end() const noexcept { return eof_ && cut_ == end_; }

private:
    std::string_view cut_after(std::size_t from);

    Fill fill_;
    std::size_t block_bytes_;
    std::string buffer_;
    std::size_t cut_ = 0;  ///< end of the current block in buffer_
    std::size_t end_ = 0;  ///< end of the bytes read into buffer_
    std::size_t offset_ = 0;
    bool eof_ = false;
};

/// What one column holds.
enum class Field : std::uint8_t { skip, x, y, z, id, code, line_id, lat, lon };

/// One field of a line: its text (quotes removed) and its 1-based column in the line.
struct Cell {
    std::string_view text;
    std::size_t column = 0;
};

/// Walks a text buffer line by line; strips a BOM, CR before LF, counts lines from 1.
class LineCursor {
public:
    explicit LineCursor(std::string_view text);
    /// Next line (without its end); false at the end of the text.
    bool next(std::string_view& line);
    /// Continue at byte @p offset (a line start; a BOM there is text) as if @p line_number lines
    /// were read.
    void seek(std::size_t offset, std::size_t line_number) noexcept {
        pos_ = offset;
        line_number_ = line_number;
    }
    [[nodiscard]] std::size_t line_number() const noexcept { return line_number_; }
    [[nodiscard]] std::size_t offset() const noexcept { return pos_; }
    [[nodiscard]] std::size_t size() const noexcept { return text_.size(); }

private:
    std::string_view text_;
    std::size_t pos_ = 0;
    std::size_t line_number_ = 0;
};

/// True for lines with only blanks, or starting (after blanks) with '#' or "//".
[[nodiscard]] bool is_blank(std::string_view line) noexcept;
[[nodiscard]] bool is_comment(std::string_view line) noexcept;

/// Splits @p line at @p delimiter (' ' means runs of spaces/tabs), trimming blanks around fields
/// and removing surrounding double quotes. Returns false on an unterminated quote.
bool split_fields(std::string_view line, char delimiter, std::vector<Cell>& cells);

/// Parses a finite decimal number (leading '+' allowed; ',' as decimal mark if
/// @p decimal_comma). False if the text is not exactly one finite number.
[[nodiscard]] bool parse_number(std::string_view text, bool decimal_comma, double& value) noexcept;

/// The detected or given shape of a text file.
struct Layout {
    char delimiter = ' ';
    bool decimal_comma = false;
    std::size_t header_line = 0;  ///< 1-based line of the header, 0 if none
    std::size_t count_line = 0;   ///< 1-based line of a point-count first line, 0 if none
    std::size_t declared_count = 0;
    std::vector<Field> fields;       ///< role of each column
    std::vector<std::string> names;  ///< header names (empty without a header)
    std::size_t data_offset = 0;     ///< byte offset where data lines start (after any BOM)
    std::size_t data_line = 0;       ///< line number before the first data line
};

/// Role named by a header or ReadOptions::columns word ("east", "elevation", "shapeid", ...); skip
/// if none.
/// @p polyline: "id" groups polyline vertices instead of naming points.
[[nodiscard]] Field field_from_name(std::string_view name, bool polyline);

/// True if @p text holds all the lines detect_layout() looks at: detecting on a longer text that
/// starts with @p text gives the same layout.
[[nodiscard]] bool holds_layout_sample(std::string_view text);

/// Detects the layout of @p text. @p columns is ReadOptions::columns (may be empty).
/// @throws InputError (located at @p file) for an empty file, an unknown ReadOptions::columns word
/// or a
///         header without the needed columns.
[[nodiscard]] Layout detect_layout(std::string_view text,
                                   const std::string& file,
                                   const std::string& columns,
                                   bool polyline);

/// The survey points of the data lines of @p text (whole lines, the line before it being
/// @p line) under @p layout: what read_csv gives for those lines (the distributed reader's byte
/// ranges, csv_distributed.cpp). @throws InputError as read_csv.
[[nodiscard]] ReadResult parse_points_range(std::string_view text,
                                            std::size_t line,
                                            const Layout& layout,
                                            const InputFile& file,
                                            const ReadOptions& options);

/// Index of the first column with role @p f, or -1.
[[nodiscard]] int column_of(const Layout& layout, Field f) noexcept;

}  // namespace dtm::io::csv
