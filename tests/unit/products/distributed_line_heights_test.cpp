// SPDX-License-Identifier: MIT
// 2-D lines in a distributed run (products/detail/distributed_lines): breakline and boundary
// vertices given without heights take the z of the survey point at their position, the first in
// input order over all ranks (a point repeated with another height near the end of the file,
// so on another rank), as resolve_line_heights() does serially: the serial PLY bytes on 1 to 16
// in-process ranks; a breakline vertex on no survey point gives the serial error on every rank,
// a ring vertex on none (its height would come from the surface) the refusal.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "dtm/algo/triangulate.hpp"
#include "dtm/dist/in_process.hpp"
#include "dtm/io/formats/ply.hpp"
#include "dtm/io/inputs.hpp"
#include "dtm/products/distributed_tin.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using dtm::io::InputRole;

std::vector<dtm::Point3> survey_points() {
    std::mt19937_64 rng(20261207);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<dtm::Point3> points;
    for (int i = 0; i < 3000; ++i) {
        const double x = -751000.0 + std::round(u(rng) * 1e6) / 1000.0;
        const double y = -1051000.0 + std::round(u(rng) * 1e6) / 1000.0;
        points.push_back({x, y, 250.0 + 10.0 * u(rng)});
    }
    return points;
}

std::string xyz_text(const std::vector<dtm::Point3>& points) {
    std::string text = "x,y,z\n";
    char row[128];
    for (const dtm::Point3& p : points) {
        std::snprintf(row, sizeof row, "%.17g,%.17g,%.17g\n", p.x, p.y, p.z);
        text += row;
    }
    return text;
}

/// 2-D lines (shapeid,x,y) through the given points.
std::string lines_2d(const std::vector<std::vector<dtm::Point3>>& lines) {
    std::string text = "shapeid,x,y\n";
    char row[128];
    for (std::size_t i = 0; i < lines.size(); ++i) {
        for (const dtm::Point3& p : lines[i]) {
            std::snprintf(row, sizeof row, "%zu,%.17g,%.17g\n", i + 1, p.x, p.y);
            text += row;
        }
    }
    return text;
}

/// A closed star-shaped ring through the survey points nearest to 12 directions from the centre.
std::vector<dtm::Point3> ring_on_points(const std::vector<dtm::Point3>& points) {
    const double cx = -750500.0, cy = -1050500.0;
    std::vector<dtm::Point3> ring;
    for (int k = 0; k < 12; ++k) {
        const double a = 2.0 * std::numbers::pi * k / 12.0;
        const double tx = cx + 420.0 * std::cos(a), ty = cy + 420.0 * std::sin(a);
        ring.push_back(*std::min_element(points.begin(), points.end(), [&](auto& p, auto& q) {
            return std::hypot(p.x - tx, p.y - ty) < std::hypot(q.x - tx, q.y - ty);
        }));
    }
    ring.push_back(ring.front());
    return ring;
}

std::string serial_ply(const fs::path& dir,
                       const std::vector<dtm::io::InputFile>& files,
                       dtm::DuplicateRule rule = dtm::DuplicateRule::first) {
    dtm::io::LoadOptions load;
    load.files = files;
    dtm::TriangulateOptions options;
    options.duplicates = rule;
    const auto serial = dtm::triangulate(dtm::io::load_inputs(load).terrain, options);
    dtm::io::write_tin_ply(serial.tin, dir / "serial.ply", {});
    return dtm::test::read_file(dir / "serial.ply");
}

void run_distributed(int ranks,
                     const std::vector<dtm::io::InputFile>& files,
                     const fs::path& out,
                     dtm::DuplicateRule rule = dtm::DuplicateRule::first) {
    dtm::products::DistributedTinOptions options;
    options.source.duplicates = rule;
    options.source.input = files.front();
    options.source.lines.assign(files.begin() + 1, files.end());
    options.output = out;
    dtm::dist::run_in_process(
        ranks, [&](dtm::dist::Comm& comm) { dtm::products::distributed_tin(comm, options, {}); },
        {ranks == 7 ? 200U : 0U, 9});
}

TEST(DistributedLineHeights, TwoDLinesTakeTheFirstSurveyPointsHeightOnAnyRankCount) {
    const dtm::test::ScratchDir dir;
    std::vector<dtm::Point3> points = survey_points();
    const std::vector<dtm::Point3> line_a{points[5], points[100], points[2000], points[2999]};
    const std::vector<dtm::Point3> line_b{points[7], points[1500], points[40]};
    points.push_back({points[5].x, points[5].y, 999.0});  // later: not the height the line takes
    points.push_back({points[1500].x, points[1500].y, 1.0});
    dtm::test::write_file(dir / "points.csv", xyz_text(points));
    dtm::test::write_file(dir / "lines.csv", lines_2d({line_a, line_b}));
    dtm::test::write_file(dir / "boundary.csv", lines_2d({ring_on_points(points)}));
    const std::vector<dtm::io::InputFile> files{{dir / "points.csv", InputRole::points},
                                                {dir / "lines.csv", InputRole::breaklines},
                                                {dir / "boundary.csv", InputRole::boundary}};
    // With the mean rule a line vertex's height enters the merged vertex's: the first point's
    // z and the repeat's give different PLYs.
    for (const auto rule : {dtm::DuplicateRule::first, dtm::DuplicateRule::mean}) {
        const std::string expected = serial_ply(dir.path(), files, rule);
        ASSERT_NE(expected.find("element edge"), std::string::npos);
        for (const int ranks : {1, 2, 3, 7, 16}) {
            const fs::path out = dir / ("dist-" + std::to_string(ranks) + ".ply");
            run_distributed(ranks, files, out, rule);
            EXPECT_TRUE(dtm::test::read_file(out) == expected)
                << ranks << " ranks, rule " << static_cast<int>(rule);
        }
    }
}

TEST(DistributedLineHeights, AVertexOnNoSurveyPointGivesTheSerialErrorOrTheRefusal) {
    const dtm::test::ScratchDir dir;
    const std::vector<dtm::Point3> points = survey_points();
    dtm::test::write_file(dir / "points.csv", xyz_text(points));
    dtm::test::write_file(dir / "off.csv",
                          lines_2d({{points[3], {-750500.25, -1050500.25, 0.0}, points[9]}}));
    std::vector<dtm::Point3> ring = ring_on_points(points);
    ring[4].x += 0.125;
    dtm::test::write_file(dir / "ring.csv", lines_2d({ring}));
    const std::vector<dtm::io::InputFile> off{{dir / "points.csv", InputRole::points},
                                              {dir / "off.csv", InputRole::breaklines}};
    std::string serial_message;
    try {
        (void)serial_ply(dir.path(), off);
    } catch (const dtm::InputError& e) {
        serial_message = e.what();
    }
    ASSERT_NE(serial_message.find("has no height"), std::string::npos);
    try {
        run_distributed(3, off, dir / "off.ply");
        ADD_FAILURE() << "no error";
    } catch (const dtm::InputError& e) {
        EXPECT_EQ(std::string(e.what()), serial_message);
    }
    EXPECT_FALSE(fs::exists(dir / "off.ply"));
    try {
        run_distributed(
            3, {{dir / "points.csv", InputRole::points}, {dir / "ring.csv", InputRole::boundary}},
            dir / "ring.ply");
        ADD_FAILURE() << "no refusal";
    } catch (const dtm::UsageError& e) {
        EXPECT_NE(std::string(e.what()).find("not taken by a distributed run yet"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
