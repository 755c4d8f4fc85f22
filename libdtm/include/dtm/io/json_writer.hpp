// SPDX-License-Identifier: MIT
/// @file
/// @brief The one JSON writer of the project (report.json, `dtm tin --stats/--report`,
/// `dtm info --json`): a streaming builder whose objects and arrays are laid out either as blocks
/// (one member per line, indented two spaces per enclosing block) or inline (on one line,
/// members separated by ", "). Numbers are the shortest text that reads back to the same
/// double; NaN and infinities, which JSON cannot hold, become null.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace dtm::io {

class JsonWriter {
public:
    enum class Layout { block, inline_ };

    /// Opens an object or array as the value of @p key (no key: an array element or the root).
    void begin_object(std::string_view key = {}, Layout layout = Layout::block);
    void begin_array(std::string_view key = {}, Layout layout = Layout::block);
    /// Closes the innermost open object or array.
    void end();

    void value(std::string_view key, double v);
    void value(std::string_view key, std::size_t v);
    void value(std::string_view key, std::string_view v);
    void value(std::string_view key, bool v);
    void value(std::string_view key, const char* v) { value(key, std::string_view(v)); }
    void value(std::string_view key, const std::string& v) { value(key, std::string_view(v)); }
    void null(std::string_view key);

    /// The document so far, with a final newline.
    [[nodiscard]] std::string str() const { return out_ + "\n"; }

private:
    struct Open {
        Layout layout;
        char close;
        bool empty = true;
    };
    void begin(std::string_view key, Layout layout, char open, char close);
    void member(std::string_view key);
    void newline(std::size_t blocks);
    void quote(std::string_view text);
    [[nodiscard]] std::size_t blocks_open() const noexcept;

    std::string out_;
    std::vector<Open> open_;
};

/// @p text as a JSON string literal, quotes included.
[[nodiscard]] std::string json_string(std::string_view text);
/// @p v as JSON: the shortest text that reads back to the same double; null if not finite.
[[nodiscard]] std::string json_number(double v);

}  // namespace dtm::io
