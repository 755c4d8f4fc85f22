// SPDX-License-Identifier: MIT
// The methods lab on tiny sizes: every cell measured (or capped), the triangle counts in the
// results are the methods' own, a quadratic method is capped from its previous time, and the
// files (CSV with its columns, JSON, report.md, PNG and SVG plots) are written.
#include "dtm/lab/compare.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "dtm/core/error.hpp"
#include "dtm/methods/registry.hpp"
#include "support/test_support.hpp"

namespace dtm::lab {
namespace {

std::string read(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

const methods::MethodInfo* a_quadratic_method() {
    for (const methods::MethodInfo& m : methods::registry()) {
        if (m.quadratic && m.output == methods::Output::triangulation) return &m;
    }
    return nullptr;
}

TEST(Lab, CompareMeasuresCapsAndWrites) {
    CompareOptions o;
    o.methods = {"dc", "voronoi-dc"};
    const methods::MethodInfo* quadratic = a_quadratic_method();
    if (quadratic != nullptr) o.methods.emplace_back(quadratic->name);
    o.sizes = {300, 150, 600};  // unsorted on purpose
    o.distributions = {methods::Distribution::uniform, methods::Distribution::arc};
    o.repeat = 2;
    o.cap_seconds = 1e-12;  // any quadratic method is capped after its first size
    const CompareResult r = run_compare(o);
    ASSERT_EQ(r.cells.size(), o.methods.size() * 3 * 2);
    for (const Measurement& c : r.cells) {
        SCOPED_TRACE(c.method + " " + c.distribution + " " + std::to_string(c.n));
        if (c.quadratic && c.n > 150) {
            EXPECT_EQ(c.status, Status::capped);
            EXPECT_NE(c.note.find("estimated"), std::string::npos) << c.note;
            continue;
        }
        ASSERT_EQ(c.status, Status::ok) << c.note;
        EXPECT_EQ(c.seconds.size(), 2u);
        EXPECT_GT(c.mean_seconds, 0.0);
        // The triangle count recorded is the method's: here 2n - 2 - h of the generated set.
        const auto dist = *methods::parse_distribution(c.distribution);
        const auto pts = methods::generate_points(dist, c.n, o.seed);
        const methods::MethodResult direct =
            methods::find_method(c.method)->run(methods::MethodInput{pts, {}}, {}, {});
        EXPECT_EQ(c.triangles, direct.tin.triangles.size());
        EXPECT_EQ(c.vertices, direct.tin.vertices.size());
        EXPECT_EQ(c.angles.faces, c.triangles);
        EXPECT_GT(c.angles.min_mean, 0.0);
        EXPECT_LT(c.angles.min_mean, 60.0);
        EXPECT_GT(c.angles.max_mean, 60.0);
    }

    const test::ScratchDir dir;
    write_compare(r, dir.path() / "out");
    const std::string csv = read(dir.path() / "out" / "results.csv");
    std::string header;
    for (std::size_t i = 0; i < csv_columns().size(); ++i)
        header += (i ? "," : "") + csv_columns()[i];
    EXPECT_EQ(csv.substr(0, csv.find('\n')), header);
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), static_cast<long>(r.cells.size() + 1));
    EXPECT_NE(csv.find("\nvoronoi-dc,voronoi,0,arc,600,main,ok,"), std::string::npos);
    const std::string json = read(dir.path() / "out" / "results.json");
    EXPECT_EQ(json.front(), '{');
    EXPECT_NE(json.find("\"min_angle_histogram\""), std::string::npos);
    const std::string md = read(dir.path() / "out" / "report.md");
    EXPECT_NE(md.find("## Scaling summary (uniform)"), std::string::npos);
    EXPECT_NE(md.find("## arc"), std::string::npos);
    if (quadratic != nullptr) {
        EXPECT_NE(md.find("capped"), std::string::npos);
    }
    for (const char* ext : {".png", ".svg"}) {
        const auto plot = dir.path() / "out" / "plots" / (std::string("scaling_uniform") + ext);
        ASSERT_TRUE(std::filesystem::exists(plot)) << plot;
        const std::string bytes = read(plot);
        if (std::string(ext) == ".png") {
            EXPECT_EQ(bytes.substr(1, 3), "PNG");
        } else {
            EXPECT_NE(bytes.find("<svg"), std::string::npos);
        }
        EXPECT_TRUE(std::filesystem::exists(dir.path() / "out" / "plots" /
                                            (std::string("angles_arc_600_dc") + ext)));
    }
}

TEST(Lab, RefusalsAreRecordedAndUnknownMethodsRejected) {
    CompareOptions o;
    o.methods = {"no-such-method"};
    EXPECT_THROW((void)run_compare(o), UsageError);
    if (methods::find_method("enumerate") != nullptr) {
        o.methods = {"enumerate"};
        o.sizes = {100};
        o.distributions = {methods::Distribution::uniform};
        const CompareResult r = run_compare(o);
        ASSERT_EQ(r.cells.size(), 1u);
        EXPECT_EQ(r.cells[0].status, Status::refused);
    }
}

TEST(Lab, AngleStatisticsOfKnownTriangles) {
    methods::MethodResult r;
    r.tin.vertices = {{0, 0, 0}, {2, 0, 0}, {1, std::sqrt(3.0), 0}, {0, 2, 0}};
    r.tin.triangles = {Triangle{{0, 1, 2}, {}}, Triangle{{0, 2, 3}, {}}};
    const AngleStats s = angle_stats(r);
    EXPECT_EQ(s.faces, 2u);
    // Equilateral: 60/60; the second (0,0) (1,1.732) (0,2): angles 30, 75, 75... min 30, max 75.
    EXPECT_NEAR(s.min_min, 30.0, 1e-9);
    EXPECT_NEAR(s.max_max, 75.0, 1e-9);
    EXPECT_NEAR(s.min_mean, 45.0, 1e-9);
    EXPECT_NEAR(s.max_mean, 67.5, 1e-9);
    EXPECT_EQ(s.min_histogram[6], 1u);   // 30 degrees: bin [30, 35)
    EXPECT_EQ(s.min_histogram[12], 1u);  // 60 degrees
}

}  // namespace
}  // namespace dtm::lab
