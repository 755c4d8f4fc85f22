// SPDX-License-Identifier: MIT
// The LAS public header block and variable length records (ASPRS LAS 1.4 R15, sections 2.4-2.6),
// parsed from the file's bytes with every read bounds-checked: errors name the byte offset.
#pragma once

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace dtm::io::las {

/// Little-endian reads from the file's bytes; a read past the end is an InputError naming the
/// file and the byte offset.
class Bytes {
public:
    Bytes(std::string_view data, const std::filesystem::path& path) : data_(data), path_(path) {}

    template <class T>
    [[nodiscard]] T get(std::size_t at, const char* what) const {
        need(at, sizeof(T), what);
        return load<T>(reinterpret_cast<const unsigned char*>(data_.data()) + at);
    }
    /// Checks that @p size bytes from @p at are in the file.
    void need(std::size_t at, std::size_t size, const char* what) const;
    [[nodiscard]] std::string_view text(std::size_t at, std::size_t size, const char* what) const;
    [[nodiscard]] std::size_t size() const noexcept { return data_.size(); }
    [[nodiscard]] const unsigned char* at(std::size_t offset) const noexcept {
        return reinterpret_cast<const unsigned char*>(data_.data()) + offset;
    }
    [[noreturn]] void fail(std::size_t at, const std::string& what) const;
    [[nodiscard]] const std::filesystem::path& path() const noexcept { return path_; }

    template <class T>
    static T load(const unsigned char* p) noexcept {
        static_assert(sizeof(T) == 1 || sizeof(T) == 2 || sizeof(T) == 4 || sizeof(T) == 8);
        using U = std::conditional_t<
            sizeof(T) == 1, std::uint8_t,
            std::conditional_t<sizeof(T) == 2, std::uint16_t,
                               std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>>;
        U u = 0;
        for (std::size_t i = 0; i < sizeof(T); ++i) u |= static_cast<U>(U{p[i]} << (8 * i));
        return std::bit_cast<T>(u);
    }

private:
    std::string_view data_;
    const std::filesystem::path& path_;
};

struct Header {
    unsigned major = 1;
    unsigned minor = 2;
    std::uint16_t header_size = 0;
    std::uint32_t point_offset = 0;
    unsigned format = 0;  ///< point data record format, 0-10
    std::uint16_t record_length = 0;
    std::uint64_t count = 0;  ///< point records (the 1.4 64-bit count where there is one)
    std::array<double, 3> scale{};
    std::array<double, 3> offset{};
    std::string crs_wkt;  ///< from the OGC WKT record, else the GeoTIFF keys' EPSG code
    std::vector<std::string> warnings;
};

/// Shortest record of each point data record format (the standard fields only; extra bytes may
/// follow).
inline constexpr std::array<std::uint16_t, 11> min_record_length{20, 28, 26, 34, 57, 63,
                                                                 30, 36, 38, 59, 67};

/// Parses the header and the (extended) variable length records, and checks that the point
/// records fit in the file. @throws InputError (file, byte offset); for a LAZ file, the reason
/// it is not read and how to decompress it.
[[nodiscard]] Header parse_header(const Bytes& bytes);

/// The message for a LAZ (compressed LAS) file, which dtm does not read.
[[nodiscard]] std::string laz_message();

}  // namespace dtm::io::las
