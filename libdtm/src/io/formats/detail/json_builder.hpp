// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: a small streaming JSON builder for the reports (no dependency). Numbers use
/// the shortest text that reads back to the same double; NaN and infinities, which JSON cannot
/// hold, become null. Pretty-printed with two-space indentation.
#pragma once

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>

namespace dtm::io::detail {

class JsonBuilder {
public:
    void open(char bracket, std::string_view key = {}) {
        prefix(key);
        out_ += bracket;
        first_ = true;
        ++depth_;
    }
    void close(char bracket) {
        --depth_;
        if (!first_) {
            newline();
        }
        out_ += bracket;
        first_ = false;
    }
    void value(std::string_view key, double v) {
        prefix(key);
        if (!std::isfinite(v)) {
            out_ += "null";
            return;
        }
        std::array<char, 32> buffer{};
        const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), v);
        out_.append(buffer.data(), result.ptr);
    }
    void boolean(std::string_view key, bool v) {
        prefix(key);
        out_ += v ? "true" : "false";
    }
    void null(std::string_view key) {
        prefix(key);
        out_ += "null";
    }
    void value(std::string_view key, std::size_t v) {
        prefix(key);
        out_ += std::to_string(v);
    }
    void value(std::string_view key, std::string_view v) {
        prefix(key);
        quote(v);
    }
    void value(std::string_view key, const char* v) { value(key, std::string_view(v)); }
    void value(std::string_view key, const std::string& v) { value(key, std::string_view(v)); }
    [[nodiscard]] std::string str() const { return out_ + "\n"; }

private:
    void newline() {
        out_ += '\n';
        out_.append(static_cast<std::size_t>(depth_) * 2, ' ');
    }
    void prefix(std::string_view key) {
        if (depth_ > 0) {
            if (!first_) {
                out_ += ',';
            }
            newline();
        }
        first_ = false;
        if (!key.empty()) {
            quote(key);
            out_ += ": ";
        }
    }
    void quote(std::string_view text) {
        out_ += '"';
        for (const char c : text) {
            switch (c) {
                case '"':
                    out_ += "\\\"";
                    break;
                case '\\':
                    out_ += "\\\\";
                    break;
                case '\n':
                    out_ += "\\n";
                    break;
                case '\r':
                    out_ += "\\r";
                    break;
                case '\t':
                    out_ += "\\t";
                    break;
                default:
                    if (static_cast<unsigned char>(c) < 0x20) {
                        char escaped[8];
                        std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
                        out_ += escaped;
                    } else {
                        out_ += c;
                    }
            }
        }
        out_ += '"';
    }
    std::string out_;
    int depth_ = 0;
    bool first_ = true;
};

}  // namespace dtm::io::detail
