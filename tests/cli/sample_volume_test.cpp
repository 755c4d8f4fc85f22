// SPDX-License-Identifier: MIT
// The bundled sample's road: cut and embankment between the built survey (samples/sjtsk) and the
// natural ground before the road (natural_*: the same places with the natural heights,
// tools/dtm-sample). Triangulated with the same lines both give the same triangles, so the
// volume has an independent closed form triangle by triangle, which `dtm volume` must match to
// 1e-9.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "dtm/io/formats/ply.hpp"
#include "dtm/io/tin_file.hpp"
#include "support/analysis_fixtures.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

/// Integral of max(d, 0) over a triangle of plan area a with corner values d: the part where
/// d > 0 is a triangle (one positive corner p: a d_p^3 / (3 (d_p - d_q)(d_p - d_r))) or the
/// whole minus such a triangle of the negative corner.
double positive_integral(double a, double d0, double d1, double d2) {
    const auto one = [a](double p, double q, double r) {
        return a * p * p * p / (3.0 * (p - q) * (p - r));
    };
    const int positive = (d0 > 0) + (d1 > 0) + (d2 > 0);
    const double whole = a * (d0 + d1 + d2) / 3.0;
    if (positive == 0) return 0.0;
    if (positive == 3 || (d0 >= 0 && d1 >= 0 && d2 >= 0)) return whole;
    if (positive == 1) {
        if (d0 > 0) return d1 <= 0 && d2 <= 0 ? one(d0, d1, d2) : whole;
        if (d1 > 0) return d0 <= 0 && d2 <= 0 ? one(d1, d2, d0) : whole;
        return d0 <= 0 && d1 <= 0 ? one(d2, d0, d1) : whole;
    }
    // Two positive corners, one negative n: whole - (integral of min(d, 0)) = whole + one(-n...).
    const double n = d0 < 0 ? d0 : (d1 < 0 ? d1 : d2);
    const double q = d0 < 0 ? d1 : d0;
    const double r = d0 < 0 ? d2 : (d1 < 0 ? d2 : d1);
    return whole + one(-n, -q, -r);
}

TEST(CliSampleVolume, RoadCutAndEmbankmentMatchTheClosedFormTriangleByTriangle) {
    const dtm::test::ScratchDir dir;
    auto r = dtm::test::build_sample_tin(dir / "built.ply", false);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = dtm::test::build_sample_tin(dir / "natural.ply", true);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = dtm::test::run_dtm({"volume", (dir / "built.ply").string(), "--base",
                            (dir / "natural.ply").string(), "-o", (dir / "out").string(), "-q",
                            "--no-products"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string json = dtm::test::read_file(dir / "out" / "volume.json");

    const dtm::Tin built = dtm::io::read_tin_ply(dir / "built.ply").tin;
    const dtm::Tin natural = dtm::io::read_tin_ply(dir / "natural.ply").tin;
    ASSERT_EQ(built.triangles.size(), natural.triangles.size());
    std::map<std::pair<double, double>, double> ground;
    for (const dtm::Point3& p : natural.vertices) ground[{p.x, p.y}] = p.z;
    double fill = 0.0;
    double cut = 0.0;
    double changed = 0.0;
    for (const dtm::Triangle& t : built.triangles) {
        const dtm::Point3& a = built.vertices[t.v[0]];
        const dtm::Point3& b = built.vertices[t.v[1]];
        const dtm::Point3& c = built.vertices[t.v[2]];
        const double area = 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
        const double d0 = a.z - ground.at({a.x, a.y});
        const double d1 = b.z - ground.at({b.x, b.y});
        const double d2 = c.z - ground.at({c.x, c.y});
        fill += positive_integral(area, d0, d1, d2);
        cut += positive_integral(area, -d0, -d1, -d2);
        changed += (d0 != 0 || d1 != 0 || d2 != 0) ? area : 0.0;
    }
    EXPECT_GT(fill, 100.0);  // the embankment
    EXPECT_GT(cut, 100.0);   // the side-hill cut and the ditch
    EXPECT_NEAR(dtm::test::json_number(json, "volume", "fill"), fill, 1e-9 * fill);
    EXPECT_NEAR(dtm::test::json_number(json, "volume", "cut"), cut, 1e-9 * cut);
    const double compared = dtm::test::json_number(json, "area", "overlap");
    EXPECT_NEAR(compared - dtm::test::json_number(json, "area", "unchanged"), changed,
                1e-6 * changed);
}

}  // namespace
