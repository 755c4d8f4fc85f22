// SPDX-License-Identifier: MIT
/// @file
/// @brief JSON text for the subcommands' machine-readable output (--json, --stats, --report).
#pragma once

#include <charconv>
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>

namespace dtm::cli {

/// @p text as a JSON string literal (quotes, backslashes and control characters escaped).
inline std::string json_string(std::string_view text)
{
    std::string out = "\"";
    for (char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (c == '\n') {
            out += "\\n";
        } else if (u < 0x20) {
            char buffer[8];
            std::snprintf(buffer, sizeof buffer, "\\u%04x", u);
            out += buffer;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

/// Shortest text that reads back to the same double; null for NaN and infinities.
inline std::string json_number(double v)
{
    if (!std::isfinite(v)) return "null";
    char buffer[32];
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
    return std::string(buffer, r.ptr);
}

}  // namespace dtm::cli
