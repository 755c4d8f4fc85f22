// SPDX-License-Identifier: MIT
// HP-GL tokenizer with PCL/PJL unwrapping.
//
// An HP-GL instruction is two letters followed by parameters; separators (';', ',', blanks) are
// optional, so "PUSP1PA10,20PD" is four instructions. Numbers end at the next letter. Three
// instructions carry non-numeric data: LB/BL/WD (text up to the label terminator, ETX unless DT
// changed it), DT (the terminator byte itself), SM (one symbol byte), and PE (encoded polyline,
// see hpgl_pe.cpp). Plot files are often wrapped:
//  - PCL: ESC E (reset), ESC %#B enters HP-GL/2, ESC %#A returns to PCL (whose bytes are skipped
//    up to the next escape), parameterized escapes ESC X y #... Z, with binary payloads after
//    "...#W" and ESC &p#X that are skipped by their byte count;
//  - PJL: ESC %-12345X (universal exit language) followed by "@PJL ..." lines;
//  - HP RS-232 device control: ESC . X with parameters up to ':' (ESC .I81;;17:).
// References: HP-GL/2 and HP RTL Reference Guide (1997); PCL 5 Technical Reference Manual,
// chapter 2 "PCL command syntax"; PJL Technical Reference Manual, "UEL command".
#include "io/formats/hpgl/hpgl_lexer.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>

#include "dtm/core/error.hpp"

namespace dtm::io::hpgl {
namespace {

constexpr char escape = '\x1B';
constexpr std::size_t max_stored_warnings = 40;

bool is_letter(char c) noexcept { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool is_digit(char c) noexcept { return c >= '0' && c <= '9'; }
char upper(char c) noexcept { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 32) : c; }

std::string describe_byte(char c) {
    const auto u = static_cast<unsigned char>(c);
    char buffer[24];
    if (u >= 33 && u < 127) {
        std::snprintf(buffer, sizeof buffer, "'%c'", c);
    } else {
        std::snprintf(buffer, sizeof buffer, "0x%02X", static_cast<unsigned>(u));
    }
    return buffer;
}

/// Parses a decimal number at @p pos ("-12", "+.5", "1385.640646"); advances @p pos.
double parse_number(std::string_view bytes, std::size_t& pos) {
    bool negative = false;
    if (bytes[pos] == '+' || bytes[pos] == '-') negative = bytes[pos++] == '-';
    std::uint64_t mantissa = 0;
    int exponent = 0;
    int digits = 0;
    for (; pos < bytes.size() && is_digit(bytes[pos]); ++pos) {
        if (digits < 18) {
            mantissa = mantissa * 10 + static_cast<unsigned>(bytes[pos] - '0');
            if (mantissa != 0) ++digits;
        } else {
            ++exponent;
        }
    }
    if (pos < bytes.size() && bytes[pos] == '.') {
        for (++pos; pos < bytes.size() && is_digit(bytes[pos]); ++pos) {
            if (digits < 18) {
                mantissa = mantissa * 10 + static_cast<unsigned>(bytes[pos] - '0');
                if (mantissa != 0) ++digits;
                --exponent;
            }
        }
    }
    // Dividing two exactly representable values rounds correctly (mantissa < 2^53, 10^k <= 10^22).
    double value = static_cast<double>(mantissa);
    static constexpr double powers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                        1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                        1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    if (exponent < 0) {
        value /= powers[std::min(-exponent, 22)];
    } else if (exponent > 0) {
        value *= powers[std::min(exponent, 22)];
    }
    return negative ? -value : value;
}

}  // namespace

void Diagnostics::problem(std::size_t offset, const std::string& what) {
    const std::string message = "byte " + std::to_string(offset) + ": " + what;
    if (strict_) throw InputError(file_, 0, 0, message);
    ++problems_;
    if (problems_ <= max_stored_warnings) warnings_.push_back(message);
}

void Diagnostics::warn(const std::string& what) { warnings_.push_back(what); }

std::vector<std::string> Diagnostics::take_warnings() {
    if (problems_ > max_stored_warnings) {
        warnings_.push_back(std::to_string(problems_ - max_stored_warnings) +
                            " further corrupt places skipped");
    }
    return std::move(warnings_);
}

bool Lexer::next(Command& command) {
    while (pos_ < bytes_.size()) {
        const char c = bytes_[pos_];
        if (c == escape) {
            skip_escape();
            continue;
        }
        if (pcl_mode_) {
            const auto at = bytes_.find(escape, pos_);
            pos_ = at == std::string_view::npos ? bytes_.size() : at;
            continue;
        }
        if (static_cast<unsigned char>(c) <= ' ' || c == ';' || c == ',') {
            ++pos_;
            continue;
        }
        if (!is_letter(c) || pos_ + 1 >= bytes_.size() || !is_letter(bytes_[pos_ + 1])) {
            skip_stray();
            continue;
        }
        command.name[0] = upper(c);
        command.name[1] = upper(bytes_[pos_ + 1]);
        command.offset = pos_;
        command.params.clear();
        command.text = {};
        command.pe.clear();
        pos_ += 2;
        saw_hpgl_ = true;
        if (command.is("IN") || command.is("DF")) terminator_ = '\x03';
        if (command.is("LB") || command.is("BL") || command.is("WD")) {
            read_label(command);
        } else if (command.is("DT")) {
            read_terminator_definition(command);
        } else if (command.is("SM")) {
            read_symbol_mode(command);
        } else if (command.is("PE")) {
            pos_ = decode_pe(bytes_, pos_, command.pe, diag_);
        } else {
            read_numbers(command);
        }
        return true;
    }
    return false;
}

void Lexer::skip_stray() {
    // Bytes outside ASCII where an instruction should start are corruption (for example 8-bit
    // data mangled by a text conversion). Printable text (comments, "X0=0;" notes some drivers
    // leave) is skipped up to the next separator with one summary warning.
    const std::size_t at = is_letter(bytes_[pos_]) && pos_ + 1 < bytes_.size() ? pos_ + 1 : pos_;
    if (static_cast<unsigned char>(bytes_[at]) >= 0x80) {
        diag_.problem(at, "unexpected byte " + describe_byte(bytes_[at]) +
                              " where an HP-GL instruction was expected");
        pos_ = at + 1;
        return;
    }
    if (stray_runs_++ == 0) first_stray_ = at;
    while (pos_ < bytes_.size() && bytes_[pos_] != ';' && bytes_[pos_] != '\n' &&
           bytes_[pos_] != escape && static_cast<unsigned char>(bytes_[pos_]) < 0x80)
        ++pos_;
}

void Lexer::finish() {
    if (stray_runs_ > 0) {
        diag_.warn(std::to_string(stray_runs_) +
                   " runs of text that are not HP-GL skipped (first at byte " +
                   std::to_string(first_stray_) + ")");
    }
}

void Lexer::read_numbers(Command& command) {
    while (pos_ < bytes_.size()) {
        const char c = bytes_[pos_];
        if (c == ' ' || c == ',' || c == '\t' || c == '\r' || c == '\n') {
            ++pos_;
        } else if (is_digit(c) || c == '+' || c == '-' || c == '.') {
            const std::size_t start = pos_;
            command.params.push_back(parse_number(bytes_, pos_));
            if (pos_ == start + 1 && !is_digit(c)) command.params.pop_back();  // lone sign or dot
        } else if (c == '"') {
            const auto end = bytes_.find('"', pos_ + 1);
            pos_ = end == std::string_view::npos ? bytes_.size() : end + 1;
        } else {
            if (c == ';') ++pos_;
            return;
        }
    }
}

void Lexer::read_label(Command& command) {
    const auto end = bytes_.find(terminator_, pos_);
    if (end == std::string_view::npos) {
        diag_.problem(command.offset, "label text is not terminated (terminator " +
                                          describe_byte(terminator_) + " missing)");
        command.text = bytes_.substr(pos_);
        pos_ = bytes_.size();
        return;
    }
    command.text = bytes_.substr(pos_, end - pos_);
    pos_ = end + 1;
}

void Lexer::read_terminator_definition(Command& command) {
    if (pos_ >= bytes_.size() || bytes_[pos_] == ';') {
        terminator_ = '\x03';
        if (pos_ < bytes_.size()) ++pos_;
        return;
    }
    terminator_ = bytes_[pos_];
    command.text = bytes_.substr(pos_, 1);
    ++pos_;
    read_numbers(command);  // optional ",mode"
}

void Lexer::read_symbol_mode(Command& command) {
    if (pos_ < bytes_.size()) {
        const auto c = static_cast<unsigned char>(bytes_[pos_]);
        if (c > ' ' && c != ';' && c < 127) {
            command.text = bytes_.substr(pos_, 1);
            ++pos_;
        }
    }
    if (pos_ < bytes_.size() && bytes_[pos_] == ';') ++pos_;
}

void Lexer::skip_escape() {
    ++pos_;  // ESC
    if (pos_ >= bytes_.size()) return;
    const char c = bytes_[pos_];
    if (c == '%') {
        std::size_t i = pos_ + 1;
        while (i < bytes_.size() && (is_digit(bytes_[i]) || bytes_[i] == '-' || bytes_[i] == '+'))
            ++i;
        if (i >= bytes_.size()) {
            pos_ = i;
            return;
        }
        const char mode = upper(bytes_[i]);
        pos_ = i + 1;
        if (mode == 'B') {
            pcl_mode_ = false;
        } else if (mode == 'A') {
            pcl_mode_ = true;
        } else if (mode == 'X') {
            skip_pjl_lines();
        }
        return;
    }
    if (c == '.') {  // HP RS-232 device control: ESC . X [params :]
        if (pos_ + 1 >= bytes_.size()) {
            pos_ = bytes_.size();
            return;
        }
        const char kind = bytes_[pos_ + 1];
        pos_ += 2;
        if (std::string_view("@HIMNST").find(kind) != std::string_view::npos) {
            const std::size_t limit = std::min(bytes_.size(), pos_ + 80);
            for (std::size_t i = pos_; i < limit && bytes_[i] != escape; ++i) {
                if (bytes_[i] == ':') {
                    pos_ = i + 1;
                    return;
                }
            }
        }
        return;
    }
    if (c >= '!' && c <= '/') {
        skip_pcl_parameterized();
        return;
    }
    if (c >= '0' && c <= '~') ++pos_;  // two-character escape: ESC E, ESC 9, ...
}

void Lexer::skip_pcl_parameterized() {
    const char group = bytes_[pos_++];
    char family = 0;
    if (pos_ < bytes_.size() && bytes_[pos_] >= '`' && bytes_[pos_] <= '~') family = bytes_[pos_++];
    while (pos_ < bytes_.size()) {
        const std::size_t start = pos_;
        while (pos_ < bytes_.size() && (is_digit(bytes_[pos_]) || bytes_[pos_] == '+' ||
                                        bytes_[pos_] == '-' || bytes_[pos_] == '.'))
            ++pos_;
        std::uint64_t count = 0;
        for (std::size_t i = start; i < pos_; ++i) {
            if (is_digit(bytes_[i]) && count < (std::uint64_t{1} << 40))
                count = count * 10 + static_cast<unsigned>(bytes_[i] - '0');
            if (bytes_[i] == '.') break;
        }
        if (pos_ >= bytes_.size()) return;
        const char parameter = bytes_[pos_];
        if (parameter < '@' || parameter > '~') return;  // malformed: resume at this byte
        ++pos_;
        const char kind = upper(parameter);
        const bool binary = kind == 'W' || (group == '&' && family == 'p' && kind == 'X');
        if (binary)
            pos_ = static_cast<std::size_t>(std::min<std::uint64_t>(bytes_.size(), pos_ + count));
        if (parameter >= '@' && parameter <= '^') return;  // upper case ends the escape
    }
}

void Lexer::skip_pjl_lines() {
    while (true) {
        while (pos_ < bytes_.size() &&
               (bytes_[pos_] == '\r' || bytes_[pos_] == '\n' || bytes_[pos_] == ' '))
            ++pos_;
        if (bytes_.substr(pos_, 4) != "@PJL" && bytes_.substr(pos_, 4) != "@pjl") return;
        auto end = bytes_.find('\n', pos_);
        if (end == std::string_view::npos) end = bytes_.size();
        std::string line(bytes_.substr(pos_, end - pos_));
        std::transform(line.begin(), line.end(), line.begin(), [](char ch) { return upper(ch); });
        if (line.find("ENTER") != std::string::npos && line.find("LANGUAGE") != std::string::npos) {
            pcl_mode_ =
                line.find("HPGL") == std::string::npos && line.find("HP-GL") == std::string::npos;
        }
        pos_ = end;
    }
}

}  // namespace dtm::io::hpgl
