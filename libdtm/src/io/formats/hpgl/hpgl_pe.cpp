// SPDX-License-Identifier: MIT
// HP-GL/2 PE (polyline encoded) decoder.
//
// PE packs coordinates into printable bytes. Each number is written least significant digit
// first; in the default 8-bit mode digits are base 64: a non-final digit is byte 63..126 (value
// byte - 63) and the final digit is byte 191..254 (value byte - 191). In 7-bit mode (flag '7')
// digits are base 32: non-final 63..94, final 95..126. The decoded integer carries the sign in
// its lowest bit (odd = negative) and the magnitude in the other bits. Flags come before a
// coordinate pair: ':' pen number follows, '<' the next pair is a pen-up move, '>' the number of
// fractional binary digits follows (coordinates are divided by 2^n), '=' the next pair is
// absolute; pairs are relative otherwise. PE ends at ';' or at the next instruction. Blanks,
// control characters, DEL and bytes 128-160 and 255 are ignored inside PE data, the eighth bit
// of a flag is disregarded, and so are eighth bits in 7-bit mode. One exception is reported:
// C2 or C3 followed by 80-BF is the trace of a UTF-8 re-encoding of 8-bit data (a plot opened
// and saved as text), which corrupts every number it touches.
// Reference: HP-GL/2 and HP RTL Reference Guide (Hewlett-Packard, 1997), chapter "PE".
#include "io/formats/hpgl/hpgl_pe.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

#include "io/formats/hpgl/hpgl_lexer.hpp"

namespace dtm::io::hpgl {
namespace {

constexpr unsigned char escape = 0x1B;

struct DigitSet {
    bool seven_bit = false;
    [[nodiscard]] bool non_final(unsigned char c) const noexcept {
        return seven_bit ? (c >= 63 && c <= 94) : (c >= 63 && c <= 126);
    }
    [[nodiscard]] bool final_digit(unsigned char c) const noexcept {
        return seven_bit ? (c >= 95 && c <= 126) : (c >= 191 && c <= 254);
    }
    [[nodiscard]] unsigned char fold(unsigned char c) const noexcept {
        return seven_bit ? static_cast<unsigned char>(c & 0x7F) : c;
    }
    [[nodiscard]] unsigned value(unsigned char c) const noexcept {
        if (seven_bit) return c >= 95 ? c - 95u : c - 63u;
        return c >= 191 ? c - 191u : c - 63u;
    }
    [[nodiscard]] unsigned shift() const noexcept { return seven_bit ? 5u : 6u; }
};

std::string byte_text(unsigned char c) {
    char buffer[16];
    std::snprintf(buffer, sizeof buffer, "0x%02X", static_cast<unsigned>(c));
    return buffer;
}

bool ignorable(unsigned char c) noexcept {
    return c <= ' ' || c == 127 || (c >= 128 && c <= 160) || c == 255;
}

/// 8-bit flags are read without their eighth bit (0xBD is '=').
unsigned char flag_of(unsigned char c) noexcept {
    const auto low = static_cast<unsigned char>(c & 0x7F);
    const bool is_flag = low == ':' || low == '<' || low == '>' || low == '=' || low == '7';
    return is_flag && (c == low || c >= 0xB7) ? low : 0;
}

/// True if a whole number (non-final digits then a final one) starts at @p pos.
bool number_follows(std::string_view bytes, std::size_t pos, DigitSet digits) {
    for (std::size_t i = pos; i < bytes.size(); ++i) {
        const auto c = digits.fold(static_cast<unsigned char>(bytes[i]));
        if (digits.final_digit(c)) return true;
        if (!digits.non_final(c)) return false;
    }
    return false;
}

class PeDecoder {
public:
    PeDecoder(std::string_view bytes, std::size_t pos, std::vector<PeItem>& out, Diagnostics& diag)
        : bytes_(bytes), pos_(pos), out_(out), diag_(diag) {}

    std::size_t run() {
        out_.clear();
        while (pos_ < bytes_.size()) {
            const auto raw = static_cast<unsigned char>(bytes_[pos_]);
            const auto c = digits_.fold(raw);
            if (raw == ';') return pos_ + 1;
            if (raw == escape) break;
            if (!have_x_ && flag_of(raw) != 0) {
                flag(flag_of(raw));
            } else if (digits_.non_final(c) || digits_.final_digit(c)) {
                if (!have_x_ && is_letter(raw) && !number_follows(bytes_, pos_, digits_)) break;
                coordinate();
            } else if (ignorable(raw) && !mangled()) {
                ++pos_;
            } else if (!have_x_ && is_letter(raw)) {
                break;  // a lower-case instruction after a 7-bit PE
            } else {
                report_invalid(raw);
                ++pos_;
            }
        }
        if (have_x_) diag_.problem(pos_, "PE data ends inside a coordinate pair");
        return pos_;
    }

private:
    /// C2/C3 then 80-BF: a UTF-8 re-encoded 8-bit byte.
    [[nodiscard]] bool mangled() const noexcept {
        if (pos_ == 0) return false;
        const auto before = static_cast<unsigned char>(bytes_[pos_ - 1]);
        const auto c = static_cast<unsigned char>(bytes_[pos_]);
        return (before == 0xC2 || before == 0xC3) && c >= 0x80 && c <= 0xBF;
    }

    void report_invalid(unsigned char c) {
        std::string what = "invalid byte " + byte_text(c) + " in PE (polyline encoded) data";
        if (mangled())
            what += " (after " + byte_text(static_cast<unsigned char>(bytes_[pos_ - 1])) +
                    ": the plot looks re-encoded as UTF-8)";
        diag_.problem(pos_, what);
    }

    static bool is_letter(unsigned char c) noexcept {
        return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
    }

    void flag(unsigned char c) {
        ++pos_;
        switch (c) {
            case ':': {
                double pen = 0.0;
                if (read_number(pen))
                    out_.push_back({PeItem::Kind::pen, false, 0.0, 0.0, static_cast<int>(pen)});
                break;
            }
            case '<':
                pen_up_ = true;
                break;
            case '=':
                absolute_ = true;
                break;
            case '7':
                digits_.seven_bit = true;
                break;
            default: {  // '>'
                double bits = 0.0;
                if (read_number(bits)) {
                    if (bits < 0.0 || bits > 52.0) {
                        diag_.problem(pos_, "PE fractional bits out of range");
                    } else {
                        fraction_ = std::ldexp(1.0, -static_cast<int>(bits));
                    }
                }
                break;
            }
        }
    }

    void coordinate() {
        double value = 0.0;
        if (!read_number(value)) {
            have_x_ = false;
            return;
        }
        value *= fraction_;
        if (!have_x_) {
            x_ = value;
            have_x_ = true;
            return;
        }
        have_x_ = false;
        out_.push_back(
            {pen_up_ ? PeItem::Kind::move : PeItem::Kind::draw, absolute_, x_, value, 0});
        pen_up_ = false;
        absolute_ = false;
    }

    /// Reads one signed number; false (after reporting) if it is malformed.
    bool read_number(double& result) {
        std::uint64_t magnitude = 0;
        unsigned shift = 0;
        while (pos_ < bytes_.size()) {
            const auto raw = static_cast<unsigned char>(bytes_[pos_]);
            const auto c = digits_.fold(raw);
            const bool last = digits_.final_digit(c);
            if (!last && !digits_.non_final(c)) {
                if (ignorable(raw) && !mangled()) {
                    ++pos_;
                    continue;
                }
                report_invalid(raw);
                return false;
            }
            if (shift > 60) {
                diag_.problem(pos_, "PE number too long");
                ++pos_;
                return false;
            }
            magnitude |= static_cast<std::uint64_t>(digits_.value(c)) << shift;
            shift += digits_.shift();
            ++pos_;
            if (last) {
                const auto size = static_cast<double>(magnitude >> 1);
                result = (magnitude & 1U) != 0 ? -size : size;
                return true;
            }
        }
        diag_.problem(pos_, "PE data ends inside a number");
        return false;
    }

    std::string_view bytes_;
    std::size_t pos_;
    std::vector<PeItem>& out_;
    Diagnostics& diag_;
    DigitSet digits_;
    double fraction_ = 1.0;
    bool pen_up_ = false;
    bool absolute_ = false;
    bool have_x_ = false;
    double x_ = 0.0;
};

}  // namespace

std::size_t decode_pe(std::string_view bytes,
                      std::size_t pos,
                      std::vector<PeItem>& out,
                      Diagnostics& diagnostics) {
    return PeDecoder(bytes, pos, out, diagnostics).run();
}

}  // namespace dtm::io::hpgl
