// SPDX-License-Identifier: MIT
#include "support/las_fixture.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <string_view>
#include <type_traits>

namespace dtm::test {
namespace {

constexpr std::array<unsigned, 11> record_length{20, 28, 26, 34, 57, 63, 30, 36, 38, 59, 67};

template <class T>
void put(std::string& out, std::size_t at, T value) {
    using U = std::conditional_t<
        sizeof(T) == 1, std::uint8_t,
        std::conditional_t<sizeof(T) == 2, std::uint16_t,
                           std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>>;
    const auto u = std::bit_cast<U>(value);
    if (out.size() < at + sizeof(T)) out.resize(at + sizeof(T), '\0');
    for (std::size_t i = 0; i < sizeof(T); ++i) {
        out[at + i] = static_cast<char>((u >> (8 * i)) & 0xFFU);
    }
}

void put_text(std::string& out, std::size_t at, std::string_view text, std::size_t width) {
    if (out.size() < at + width) out.resize(at + width, '\0');
    std::memcpy(out.data() + at, text.data(), std::min(text.size(), width));
}

std::string vlr(std::string_view user, std::uint16_t id, std::string_view data, bool extended) {
    std::string out;
    put_text(out, 2, user, 16);
    put<std::uint16_t>(out, 18, id);
    if (extended) {
        put<std::uint64_t>(out, 20, data.size());
        put_text(out, 28, "dtm test", 32);
    } else {
        put<std::uint16_t>(out, 20, static_cast<std::uint16_t>(data.size()));
        put_text(out, 22, "dtm test", 32);
    }
    out.append(data);
    return out;
}

}  // namespace

std::string las_bytes(const LasSpec& s) {
    const std::uint16_t header_size = s.minor >= 4 ? 375 : s.minor == 3 ? 235 : 227;
    std::string vlrs;
    std::uint32_t vlr_count = 0;
    if (!s.wkt.empty() && !s.wkt_as_evlr) {
        vlrs += vlr("LASF_Projection", 2112, s.wkt + std::string(1, '\0'), false);
        ++vlr_count;
    }
    if (s.epsg != 0) {
        std::string keys;
        const std::array<std::uint16_t, 12> k{
            1, 1, 0, 2, 1024, 0, 1, 1, 3072, 0, 1, static_cast<std::uint16_t>(s.epsg)};
        for (std::size_t i = 0; i < k.size(); ++i) put<std::uint16_t>(keys, 2 * i, k[i]);
        vlrs += vlr("LASF_Projection", 34735, keys, false);
        ++vlr_count;
    }
    const unsigned length = record_length[s.format] + s.extra_bytes;
    std::string out;
    put_text(out, 0, "LASF", 4);
    put<std::uint8_t>(out, 24, 1);
    put<std::uint8_t>(out, 25, static_cast<std::uint8_t>(s.minor));
    put_text(out, 26, "dtm test", 32);
    put_text(out, 58, "las_fixture", 32);
    put<std::uint16_t>(out, 94, header_size);
    put<std::uint32_t>(out, 96, static_cast<std::uint32_t>(header_size + vlrs.size()));
    put<std::uint32_t>(out, 100, vlr_count);
    put<std::uint8_t>(out, 104, static_cast<std::uint8_t>(s.format | (s.compressed ? 0x80U : 0U)));
    put<std::uint16_t>(out, 105, static_cast<std::uint16_t>(length));
    const auto n = static_cast<std::uint32_t>(s.records.size());
    if (s.minor < 4 || s.legacy_count) put<std::uint32_t>(out, 107, n);
    for (std::size_t i = 0; i < 3; ++i) {
        put<double>(out, 131 + 8 * i, s.scale[i]);
        put<double>(out, 155 + 8 * i, s.offset[i]);
    }
    out.resize(header_size, '\0');
    if (s.minor >= 4) put<std::uint64_t>(out, 247, s.records.size());
    out += vlrs;
    const bool extended = s.format >= 6;
    for (const LasRecord& r : s.records) {
        const std::size_t at = out.size();
        out.resize(at + length, '\0');
        put<std::int32_t>(out, at, r.x);
        put<std::int32_t>(out, at + 4, r.y);
        put<std::int32_t>(out, at + 8, r.z);
        put<std::uint8_t>(out, at + 14, 0x11);  // return 1 of 1
        if (extended) {
            put<std::uint8_t>(out, at + 15, static_cast<std::uint8_t>(r.withheld ? 0x04U : 0U));
            put<std::uint8_t>(out, at + 16, static_cast<std::uint8_t>(r.classification));
        } else {
            put<std::uint8_t>(
                out, at + 15,
                static_cast<std::uint8_t>((r.classification & 0x1FU) | (r.withheld ? 0x80U : 0U)));
        }
    }
    if (s.minor >= 4 && !s.wkt.empty() && s.wkt_as_evlr) {
        put<std::uint64_t>(out, 235, out.size());
        put<std::uint32_t>(out, 243, 1);
        out += vlr("LASF_Projection", 2112, s.wkt, true);
    }
    return out;
}

}  // namespace dtm::test
