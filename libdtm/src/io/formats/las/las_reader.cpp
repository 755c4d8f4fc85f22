// SPDX-License-Identifier: MIT
// LAS point records (ASPRS LAS 1.4 R15, section 2.7): X, Y, Z are 32-bit integers at bytes 0, 4,
// 8 of every record, the coordinate being integer * scale + offset. Formats 0-5: classification
// in bits 0-4 of byte 15, withheld bit 7 of byte 15; formats 6-10: classification byte 16,
// withheld bit 2 of the flags byte 15. The records are read from the mapped file in one
// sequential pass (10^8 points: 2.4 GB of points in memory, the file's pages only streamed).
// Every record is accounted for: withheld (dropped: "should be considered deleted"), dropped by
// the class filter, thinned, or kept.
// Thinning (ReadOptions::thin = D): the plane is cut into D x D cells anchored at (0, 0) of the
// file's CRS, cell (floor(x / D), floor(y / D)); each cell keeps its lowest point (the first in
// file order among equal heights), placed where the cell's first point came in file order, so the
// result depends only on the file and D.
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "dtm/core/error.hpp"
#include "dtm/io/extension.hpp"
#include "dtm/io/formats/las.hpp"
#include "io/detail/file_bytes.hpp"
#include "io/formats/las/las_header.hpp"

namespace dtm::io {
namespace {

struct Cell {
    std::int64_t x;
    std::int64_t y;
    bool operator==(const Cell&) const = default;
};

struct CellHash {
    std::size_t operator()(const Cell& c) const noexcept {
        std::uint64_t h = static_cast<std::uint64_t>(c.x) * 0x9E3779B97F4A7C15ULL;
        h ^= static_cast<std::uint64_t>(c.y) + 0x7F4A7C159E3779B9ULL + (h << 6) + (h >> 2);
        return static_cast<std::size_t>(h ^ (h >> 31));
    }
};

/// Keeps the lowest point of each cell.
class Thinner {
public:
    Thinner(double cell, std::vector<Point3>& out) : cell_(cell), out_(out) {}

    /// False if the point's cell index does not fit 63 bits (a coordinate beyond 9e18 cells).
    bool add(const Point3& p) {
        const double cx = std::floor(p.x / cell_);
        const double cy = std::floor(p.y / cell_);
        constexpr double limit = 9.0e18;
        if (!(std::abs(cx) < limit && std::abs(cy) < limit)) return false;
        const Cell key{static_cast<std::int64_t>(cx), static_cast<std::int64_t>(cy)};
        const auto [it, fresh] = index_.try_emplace(key, out_.size());
        if (fresh) {
            out_.push_back(p);
        } else if (p.z < out_[it->second].z) {
            out_[it->second] = p;
        }
        return true;
    }

private:
    double cell_;
    std::vector<Point3>& out_;
    std::unordered_map<Cell, std::size_t, CellHash> index_;
};

void check_options(const ReadOptions& options) {
    for (const unsigned c : options.classes) {
        if (c > 255) {
            throw OptionError(
                "classes",
                "`classes`: expected classification codes 0 to 255, found " + std::to_string(c));
        }
    }
    if (!std::isfinite(options.thin) || options.thin < 0.0) {
        throw OptionError("thin", "`thin`: expected a cell size >= 0 (0: no thinning), found " +
                                      std::to_string(options.thin));
    }
}

std::string version_name(const las::Header& h) {
    return "LAS " + std::to_string(h.major) + "." + std::to_string(h.minor) + " point format " +
           std::to_string(h.format);
}

}  // namespace

bool is_las(const FileHead& head) { return head.bytes.starts_with("LASF"); }

ReadResult read_las_bytes(std::string_view data,
                          const InputFile& file,
                          const ReadOptions& options,
                          const Progress& progress) {
    check_options(options);
    if (file.role != InputRole::points) {
        throw InputError(file.path, 0, 0,
                         "a LAS point cloud is a survey point input, not a line or ring input");
    }
    const las::Bytes bytes(data, file.path);
    las::Header h = las::parse_header(bytes);
    std::array<bool, 256> keep{};
    keep.fill(options.classes.empty());
    for (const unsigned c : options.classes) keep[c] = true;
    const bool extended = h.format >= 6;
    const std::size_t class_byte = extended ? 16 : 15;

    ReadResult r;
    PointCloudCounts counts;
    counts.records = h.count;
    std::vector<Point3>& points = r.terrain.points;
    Thinner thinner(options.thin, points);
    const bool thin = options.thin > 0.0;
    if (!thin && options.classes.empty()) points.reserve(h.count);
    const unsigned char* record = bytes.at(h.point_offset);
    constexpr std::uint64_t chunk = std::uint64_t{1} << 20;
    for (std::uint64_t i = 0; i < h.count; ++i, record += h.record_length) {
        if (i % chunk == 0) {
            progress.report(static_cast<double>(i) / static_cast<double>(h.count), "reading LAS");
        }
        const unsigned flags = record[15];
        if (extended ? (flags & 0x04U) != 0 : (flags & 0x80U) != 0) {
            ++counts.withheld;
            continue;
        }
        const unsigned cls = extended ? record[class_byte] : (record[class_byte] & 0x1FU);
        if (!keep[cls]) {
            ++counts.class_filtered;
            continue;
        }
        const Point3 p{
            las::Bytes::load<std::int32_t>(record) * h.scale[0] + h.offset[0],
            las::Bytes::load<std::int32_t>(record + 4) * h.scale[1] + h.offset[1],
            las::Bytes::load<std::int32_t>(record + 8) * h.scale[2] + h.offset[2],
        };
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            bytes.fail(h.point_offset + i * h.record_length,
                       "point record " + std::to_string(i) +
                           " has a coordinate out of range after scale and offset");
        }
        if (!thin) {
            points.push_back(p);
        } else if (!thinner.add(p)) {
            bytes.fail(h.point_offset + i * h.record_length,
                       "point record " + std::to_string(i) + " is too far from (0, 0) for `thin` " +
                           std::to_string(options.thin));
        }
    }
    progress.report(1.0, "reading LAS");
    counts.thinned = h.count - counts.withheld - counts.class_filtered - points.size();
    InputSummary& s = r.summary;
    s.path = file.path;
    s.format = version_name(h);
    s.cloud = counts;
    s.warnings = std::move(h.warnings);
    if (counts.withheld > 0) {
        s.warnings.push_back(std::to_string(counts.withheld) +
                             " withheld point records (flagged as deleted) not used");
    }
    r.crs_wkt = std::move(h.crs_wkt);
    return r;
}

ReadResult read_las(const InputFile& file, const ReadOptions& options, const Progress& progress) {
    check_options(options);
    if (lower_extension(file.path) == "laz") {
        throw InputError(file.path, 0, 0, las::laz_message());
    }
    const detail::FileBytes bytes(file.path, detail::Access::sequential);
    return read_las_bytes(bytes.view(), file, options, progress);
}

}  // namespace dtm::io
