// SPDX-License-Identifier: MIT
// The streaming JSON writer (json_writer.hpp). Strings escape the quote, the backslash, \n, \r,
// \t, and every other control character as \u00XX; UTF-8 passes through.
#include "dtm/io/json_writer.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace dtm::io {

std::size_t JsonWriter::blocks_open() const noexcept {
    std::size_t n = 0;
    for (const Open& o : open_) n += o.layout == Layout::block ? 1 : 0;
    return n;
}

void JsonWriter::newline(std::size_t blocks) {
    out_ += '\n';
    out_.append(blocks * 2, ' ');
}

void JsonWriter::member(std::string_view key) {
    if (!open_.empty()) {
        Open& parent = open_.back();
        if (parent.layout == Layout::block) {
            if (!parent.empty) out_ += ',';
            newline(blocks_open());
        } else if (!parent.empty) {
            out_ += ", ";
        }
        parent.empty = false;
    }
    if (!key.empty()) {
        quote(key);
        out_ += ": ";
    }
}

void JsonWriter::begin(std::string_view key, Layout layout, char open, char close) {
    member(key);
    out_ += open;
    open_.push_back({layout, close});
}

void JsonWriter::begin_object(std::string_view key, Layout layout) { begin(key, layout, '{', '}'); }

void JsonWriter::begin_array(std::string_view key, Layout layout) { begin(key, layout, '[', ']'); }

void JsonWriter::end() {
    const Open closing = open_.back();
    open_.pop_back();
    if (closing.layout == Layout::block && !closing.empty) newline(blocks_open());
    out_ += closing.close;
}

void JsonWriter::value(std::string_view key, double v) {
    member(key);
    out_ += json_number(v);
}

void JsonWriter::value(std::string_view key, std::size_t v) {
    member(key);
    out_ += std::to_string(v);
}

void JsonWriter::value(std::string_view key, std::string_view v) {
    member(key);
    quote(v);
}

void JsonWriter::value(std::string_view key, bool v) {
    member(key);
    out_ += v ? "true" : "false";
}

void JsonWriter::null(std::string_view key) {
    member(key);
    out_ += "null";
}

void JsonWriter::quote(std::string_view text) { out_ += json_string(text); }

std::string json_string(std::string_view text) {
    std::string out = "\"";
    for (const char c : text) {
        switch (c) {
            case '"':
                out += "\\\"";
                break;
            case '\\':
                out += "\\\\";
                break;
            case '\n':
                out += "\\n";
                break;
            case '\r':
                out += "\\r";
                break;
            case '\t':
                out += "\\t";
                break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) {
                    std::array<char, 8> escaped{};
                    std::snprintf(escaped.data(), escaped.size(), "\\u%04x",
                                  static_cast<unsigned>(static_cast<unsigned char>(c)));
                    out += escaped.data();
                } else {
                    out += c;
                }
        }
    }
    return out + '"';
}

std::string json_number(double v) {
    if (!std::isfinite(v)) return "null";
    std::array<char, 32> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), v);
    return std::string(buffer.data(), result.ptr);
}

}  // namespace dtm::io
