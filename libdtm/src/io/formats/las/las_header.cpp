// SPDX-License-Identifier: MIT
// LAS public header block and variable length records (ASPRS LAS Specification 1.4 R15, 2019;
// 1.2 and 1.3 are prefixes of the same layout). Offsets of the header fields: version 24/25,
// header size 94, offset to point data 96, number of VLRs 100, point data record format 104
// (bits 6-7 set by LASzip for compressed data), record length 105, legacy point count 107,
// scale 131, offset 155; 1.4 adds the first EVLR 235, the EVLR count 243 and the 64-bit point
// count 247. A VLR is a 54-byte header (user id 2, record id 18, length 20) and its data; an EVLR
// has a 60-byte header with a 64-bit length. CRS records (user id "LASF_Projection"): 2112 OGC
// WKT; 34735 the GeoTIFF GeoKeyDirectory, whose ProjectedCSTypeGeoKey (3072) or
// GeographicTypeGeoKey (2048) is an EPSG code.
#include "io/formats/las/las_header.hpp"

#include <cmath>
#include <limits>

#include "dtm/core/error.hpp"
#include "dtm/io/formats/crs.hpp"

namespace dtm::io::las {

void Bytes::need(std::size_t at, std::size_t size, const char* what) const {
    if (at > data_.size() || size > data_.size() - at) {
        fail(at, std::string("expected ") + what + " (" + std::to_string(size) +
                     " bytes), found the end of the file (" + std::to_string(data_.size()) +
                     " bytes; truncated?)");
    }
}

std::string_view Bytes::text(std::size_t at, std::size_t size, const char* what) const {
    need(at, size, what);
    std::string_view s = data_.substr(at, size);
    const std::size_t nul = s.find('\0');
    return nul == std::string_view::npos ? s : s.substr(0, nul);
}

void Bytes::fail(std::size_t at, const std::string& what) const {
    throw InputError(path_, 0, 0, "LAS byte " + std::to_string(at) + ": " + what);
}

std::string laz_message() {
    return "this is LAZ (LASzip-compressed LAS), which dtm does not read: no LAZ decompression "
           "library is available as a Debian package here, and dtm does not reimplement LASzip; "
           "decompress it first, e.g. `laszip -i in.laz -o out.las` or `pdal translate in.laz "
           "out.las`, and give dtm the .las";
}

namespace {

constexpr std::uint16_t wkt_record = 2112;
constexpr std::uint16_t geokey_record = 34735;
constexpr std::uint16_t laszip_record = 22204;

struct Crs {
    std::string wkt;
    unsigned projected = 0;   ///< ProjectedCSTypeGeoKey
    unsigned geographic = 0;  ///< GeographicTypeGeoKey
    bool user_defined = false;
};

void read_geokeys(const Bytes& b, std::size_t at, std::uint64_t length, Crs& crs) {
    if (length < 8) b.fail(at, "expected a GeoKeyDirectory of at least 8 bytes");
    const auto keys = b.get<std::uint16_t>(at + 6, "the GeoKey count");
    if (8 + std::uint64_t{keys} * 8 > length) {
        b.fail(at + 6, "the GeoKeyDirectory announces " + std::to_string(keys) +
                           " keys, more than its record of " + std::to_string(length) +
                           " bytes holds");
    }
    for (std::size_t k = 0; k < keys; ++k) {
        const std::size_t e = at + 8 + k * 8;
        const auto id = b.get<std::uint16_t>(e, "a GeoKey id");
        const auto location = b.get<std::uint16_t>(e + 2, "a GeoKey location");
        const auto value = b.get<std::uint16_t>(e + 6, "a GeoKey value");
        if (location != 0 || (id != 3072 && id != 2048)) continue;
        if (value == 32767) {
            crs.user_defined = true;
        } else if (id == 3072) {
            crs.projected = value;
        } else {
            crs.geographic = value;
        }
    }
}

/// One VLR or EVLR whose data is [at, at + length).
void read_record(
    const Bytes& b, std::size_t header_at, std::size_t at, std::uint64_t length, Crs& crs) {
    const std::string_view user = b.text(header_at + 2, 16, "a record's user id");
    const auto id = b.get<std::uint16_t>(header_at + 18, "a record id");
    if (length > b.size() || at > b.size() - length) {
        b.fail(header_at, "a variable length record of " + std::to_string(length) +
                              " bytes from byte " + std::to_string(at) +
                              " runs past the end of the file (" + std::to_string(b.size()) +
                              " bytes)");
    }
    if (user == "laszip encoded" && id == laszip_record) b.fail(header_at, laz_message());
    if (user != "LASF_Projection") return;
    if (id == wkt_record) {
        crs.wkt = std::string(b.text(at, static_cast<std::size_t>(length), "the WKT record"));
    } else if (id == geokey_record) {
        read_geokeys(b, at, length, crs);
    }
}

void read_records(const Bytes& b, const Header& h, std::uint32_t vlr_count, Crs& crs) {
    std::size_t at = h.header_size;
    for (std::uint32_t i = 0; i < vlr_count; ++i) {
        const auto length = b.get<std::uint16_t>(at + 20, "a variable length record header");
        b.need(at, 54, "a variable length record header");
        read_record(b, at, at + 54, length, crs);
        at += 54 + std::size_t{length};
    }
    if (h.minor < 4 || h.header_size < 375) return;
    const auto evlr_at = b.get<std::uint64_t>(235, "the start of the first EVLR");
    const auto evlr_count = b.get<std::uint32_t>(243, "the number of EVLRs");
    if (evlr_at == 0 || evlr_count == 0) return;
    if (evlr_at > b.size()) {
        b.fail(235, "the first extended VLR is said to start at byte " + std::to_string(evlr_at) +
                        ", past the end of the file (" + std::to_string(b.size()) + " bytes)");
    }
    auto e = static_cast<std::size_t>(evlr_at);
    for (std::uint32_t i = 0; i < evlr_count; ++i) {
        const auto length = b.get<std::uint64_t>(e + 20, "an extended VLR header");
        b.need(e, 60, "an extended VLR header");
        read_record(b, e, e + 60, length, crs);
        e += 60 + static_cast<std::size_t>(length);
    }
}

void set_crs(Header& h, const Crs& crs) {
    std::string definition = crs.wkt;
    if (definition.empty() && crs.projected != 0) {
        definition = "EPSG:" + std::to_string(crs.projected);
    } else if (definition.empty() && crs.geographic != 0) {
        definition = "EPSG:" + std::to_string(crs.geographic);
    }
    if (definition.empty()) {
        if (crs.user_defined) {
            h.warnings.push_back(
                "the GeoTIFF keys hold a user-defined CRS (code 32767), not an EPSG code: no CRS "
                "taken from the file");
        }
        return;
    }
    try {
        h.crs_wkt = crs_to_wkt(definition);
    } catch (const UsageError& e) {
        h.warnings.push_back("the file's CRS could not be read (" + std::string(e.what()) +
                             "): no CRS taken from the file");
    }
}

}  // namespace

Header parse_header(const Bytes& b) {
    if (b.text(0, 4, "the LAS signature 'LASF'") != "LASF") {
        b.fail(0, "expected the LAS signature 'LASF'");
    }
    Header h;
    h.major = b.get<std::uint8_t>(24, "the version");
    h.minor = b.get<std::uint8_t>(25, "the version");
    if (h.major != 1 || h.minor > 4) {
        b.fail(24, "expected LAS version 1.0 to 1.4, found " + std::to_string(h.major) + "." +
                       std::to_string(h.minor));
    }
    h.header_size = b.get<std::uint16_t>(94, "the header size");
    const unsigned needed = h.minor >= 4 ? 375U : h.minor == 3 ? 235U : 227U;
    if (h.header_size < needed) {
        b.fail(94, "expected a header of at least " + std::to_string(needed) + " bytes for LAS 1." +
                       std::to_string(h.minor) + ", found " + std::to_string(h.header_size));
    }
    b.need(0, h.header_size, "the public header block");
    h.point_offset = b.get<std::uint32_t>(96, "the offset to the point data");
    const auto vlr_count = b.get<std::uint32_t>(100, "the number of VLRs");
    const auto format_byte = b.get<std::uint8_t>(104, "the point data record format");
    if ((format_byte & 0xC0U) != 0) b.fail(104, laz_message());
    h.format = format_byte;
    if (h.format > 10) {
        b.fail(104,
               "expected a point data record format 0 to 10, found " + std::to_string(h.format));
    }
    h.record_length = b.get<std::uint16_t>(105, "the point data record length");
    if (h.record_length < min_record_length[h.format]) {
        b.fail(105, "expected records of at least " + std::to_string(min_record_length[h.format]) +
                        " bytes for point format " + std::to_string(h.format) + ", found " +
                        std::to_string(h.record_length));
    }
    const auto legacy = b.get<std::uint32_t>(107, "the legacy point count");
    h.count = legacy;
    if (h.minor >= 4) {
        const auto count = b.get<std::uint64_t>(247, "the point count");
        if (count != 0) h.count = count;
        if (legacy != 0 && count != 0 && legacy != count) {
            h.warnings.push_back("the legacy point count (" + std::to_string(legacy) +
                                 ") differs from the LAS 1.4 count (" + std::to_string(count) +
                                 "): the 1.4 count is used");
        }
    }
    const char* axes[] = {"X", "Y", "Z"};
    for (std::size_t i = 0; i < 3; ++i) {
        h.scale[i] = b.get<double>(131 + 8 * i, "a scale factor");
        h.offset[i] = b.get<double>(155 + 8 * i, "an offset");
        if (!std::isfinite(h.scale[i]) || h.scale[i] == 0.0) {
            b.fail(131 + 8 * i, std::string("expected a finite non-zero ") + axes[i] +
                                    " scale factor, found " + std::to_string(h.scale[i]));
        }
        if (!std::isfinite(h.offset[i])) {
            b.fail(155 + 8 * i, std::string("expected a finite ") + axes[i] + " offset");
        }
    }
    if (h.point_offset < h.header_size || h.point_offset > b.size()) {
        b.fail(96, "the point data is said to start at byte " + std::to_string(h.point_offset) +
                       ", outside the file (header " + std::to_string(h.header_size) +
                       " bytes, file " + std::to_string(b.size()) + " bytes)");
    }
    const std::size_t room = b.size() - h.point_offset;
    if (h.count > room / h.record_length) {
        b.fail(h.point_offset, "the header announces " + std::to_string(h.count) +
                                   " point records of " + std::to_string(h.record_length) +
                                   " bytes, but only " + std::to_string(room / h.record_length) +
                                   " fit in the file (" + std::to_string(b.size()) +
                                   " bytes; truncated?)");
    }
    Crs crs;
    read_records(b, h, vlr_count, crs);
    set_crs(h, crs);
    return h;
}

}  // namespace dtm::io::las
