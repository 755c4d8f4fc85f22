// SPDX-License-Identifier: MIT
// 2-D lines in a distributed run (products/detail/distributed_lines, distributed_ring_heights):
// breakline and boundary vertices given without heights take the z of the survey point at their
// position, the first in input order over all ranks (a point repeated with another height near
// the end of the file, so on another rank), as resolve_line_heights() does serially; boundary and
// hole vertices on no survey point take the height of a first surface of the points and
// breaklines (inside it, and beyond its hull: the nearest vertex); the serial PLY bytes on 1 to
// 16 in-process ranks. A breakline vertex on no survey point gives the serial error on every rank.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
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

/// The distributed PLY equals the serial one for each rule, on 1, 2, 3, 7 (with random send
/// delays) and 16 ranks.
void expect_serial_bytes(const fs::path& dir,
                         const std::vector<dtm::io::InputFile>& files,
                         std::initializer_list<dtm::DuplicateRule> rules) {
    for (const auto rule : rules) {
        const std::string expected = serial_ply(dir, files, rule);
        ASSERT_NE(expected.find("element face"), std::string::npos);
        for (const int ranks : {1, 2, 3, 7, 16}) {
            const fs::path out = dir / ("dist-" + std::to_string(ranks) + ".ply");
            run_distributed(ranks, files, out, rule);
            EXPECT_TRUE(dtm::test::read_file(out) == expected)
                << ranks << " ranks, rule " << static_cast<int>(rule);
        }
    }
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
    ASSERT_NE(serial_ply(dir.path(), files).find("element edge"), std::string::npos);
    expect_serial_bytes(dir.path(), files, {dtm::DuplicateRule::first, dtm::DuplicateRule::mean});
}

/// A closed 2-D ring (shapeid,x,y) of 24 vertices around (cx, cy), radius r, wobbling.
std::string ring_2d(double cx, double cy, double r) {
    std::string text = "shapeid,x,y\n";
    char row[128];
    for (int k = 0; k <= 24; ++k) {
        const double a = 2.0 * std::numbers::pi * (k % 24) / 24.0;
        const double rr = r * (1.0 + 0.1 * std::sin(3.0 * (k % 24)));
        std::snprintf(row, sizeof row, "1,%.17g,%.17g\n", cx + rr * std::cos(a),
                      cy + rr * std::sin(a));
        text += row;
    }
    return text;
}

TEST(DistributedLineHeights, RingsOffTheSurveyPointsTakeTheFirstSurfacesHeights) {
    const dtm::test::ScratchDir dir;
    const std::vector<dtm::Point3> points = survey_points();
    dtm::test::write_file(dir / "points.csv", xyz_text(points));
    // A breakline shapes the first surface; the boundary reaches beyond the hull of the points
    // (its vertices there take the nearest vertex's z), the hole straddles seams.
    dtm::test::write_file(dir / "lines.csv", lines_2d({{points[5], points[100], points[2000]}}));
    dtm::test::write_file(dir / "boundary.csv", ring_2d(-750500.0, -1050500.0, 530.0));
    dtm::test::write_file(dir / "hole.csv", ring_2d(-750500.0, -1050450.0, 120.0));
    const std::vector<dtm::io::InputFile> files{{dir / "points.csv", InputRole::points},
                                                {dir / "lines.csv", InputRole::breaklines},
                                                {dir / "boundary.csv", InputRole::boundary},
                                                {dir / "hole.csv", InputRole::holes}};
    expect_serial_bytes(dir.path(), files, {dtm::DuplicateRule::first, dtm::DuplicateRule::max});
}

TEST(DistributedLineHeights, RingVerticesEquallyNearTwoVerticesTakeTheLowerNumbersHeight) {
    const dtm::test::ScratchDir dir;
    std::vector<dtm::Point3> lattice;  // rows of a 40 x 40 lattice, heights differing
    for (int i = 0; i < 40; ++i) {
        for (int j = 0; j < 40; ++j)
            lattice.push_back({j * 2.0, i * 2.0, 100.0 + (i * 7 + j * 13) % 17});
    }
    dtm::test::write_file(dir / "points.csv", xyz_text(lattice));
    // Beyond the hull, each vertex halfway between two lattice points (and one on a cell's
    // centre inside: on the diagonal the TIN chose, interpolated).
    std::string ring = "shapeid,x,y\n";
    for (const auto& [x, y] : std::vector<std::pair<double, double>>{
             {-1.5, 3.0}, {41.0, -2.5}, {81.0, 39.0}, {35.0, 80.5}, {-1.5, 3.0}}) {
        ring += "1," + std::to_string(x) + "," + std::to_string(y) + "\n";
    }
    dtm::test::write_file(dir / "boundary.csv", ring);
    dtm::test::write_file(dir / "hole.csv", "shapeid,x,y\n1,21,21\n1,29,21\n1,25,27\n1,21,21\n");
    const std::vector<dtm::io::InputFile> files{{dir / "points.csv", InputRole::points},
                                                {dir / "boundary.csv", InputRole::boundary},
                                                {dir / "hole.csv", InputRole::holes}};
    const std::string expected = serial_ply(dir.path(), files);
    for (const int ranks : {2, 3, 7, 16}) {
        const fs::path out = dir / ("tie-" + std::to_string(ranks) + ".ply");
        run_distributed(ranks, files, out);
        EXPECT_TRUE(dtm::test::read_file(out) == expected) << ranks << " ranks";
    }
}

TEST(DistributedLineHeights, SoftBreaklinesTakeTheFirstSurfacesHeightsOnAnyRankCount) {
    const dtm::test::ScratchDir dir;
    const std::vector<dtm::Point3> points = survey_points();
    dtm::test::write_file(dir / "points.csv", xyz_text(points));
    // A hard line through survey points; soft 2-D lines crossing it, crossing each other, one
    // vertex on a survey point, one beyond the hull (mutation check: a soft height 1 ulp off
    // fails 10 of 10).
    dtm::test::write_file(dir / "hard.csv", lines_2d({{points[5], points[100], points[2000]}}));
    const double x0 = -751000.0, y0 = -1051000.0;
    const std::vector<std::vector<dtm::Point3>> soft{
        {{x0 + 20.0, y0 + 500.25, 0}, {x0 + 500.5, y0 + 510.0, 0}, {x0 + 990.0, y0 + 480.5, 0}},
        {{x0 + 480.0, y0 - 30.0, 0}, points[7], {x0 + 515.5, y0 + 990.0, 0}},
        {{x0 + 100.0, y0 + 100.0, 0}, {x0 + 900.0, y0 + 900.0, 0}}};
    dtm::test::write_file(dir / "soft.csv", lines_2d(soft));
    // A soft line ending exactly on a hard 3-D segment: its end takes the segment's height.
    dtm::test::write_file(dir / "hard3d.csv",
                          "shapeid,x,y,z\n1,-750900,-1050700,270\n1,-750100,-1050700,280\n");
    dtm::test::write_file(dir / "tee.csv",
                          "shapeid,x,y\n1,-750600,-1050900.5\n1,-750600,-1050700\n");
    const std::vector<dtm::io::InputFile> files{{dir / "points.csv", InputRole::points},
                                                {dir / "hard.csv", InputRole::breaklines},
                                                {dir / "hard3d.csv", InputRole::breaklines},
                                                {dir / "soft.csv", InputRole::soft_breaklines},
                                                {dir / "tee.csv", InputRole::soft_breaklines}};
    expect_serial_bytes(dir.path(), files, {dtm::DuplicateRule::first, dtm::DuplicateRule::mean});
}

TEST(DistributedLineHeights, ABreaklineVertexOnNoSurveyPointGivesTheSerialError) {
    const dtm::test::ScratchDir dir;
    const std::vector<dtm::Point3> points = survey_points();
    dtm::test::write_file(dir / "points.csv", xyz_text(points));
    dtm::test::write_file(dir / "off.csv",
                          lines_2d({{points[3], {-750500.25, -1050500.25, 0.0}, points[9]}}));
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
}

}  // namespace
