// SPDX-License-Identifier: MIT
// `--optimize CRITERION` on tin, grid, contour and build: locally optimal output with every
// breakline kept (--check), byte-identical for every thread count, the figures in --stats and
// --report, maxmin-angle = the plain CDT, and a bad name refused (exit 2).
#include <gtest/gtest.h>

#include <iomanip>
#include <sstream>

#include "dtm/algo/criteria.hpp"
#include "dtm/io/formats/ply.hpp"
#include "dtm/io/tin_file.hpp"
#include "support/terrain_fixtures.hpp"
#include "support/test_support.hpp"

namespace dtm {
namespace {

using test::run_dtm;
using test::ScratchDir;

/// Wavy terrain points and two breaklines (CSV x,y,z; lines as WKT-free CSV: id,x,y,z).
void write_inputs(const ScratchDir& dir) {
    std::ostringstream pts;
    pts << std::setprecision(17) << "x,y,z\n";
    for (const Point3& p : test::random_points(800, 8, test::sjtsk_e, test::sjtsk_n, 300)) {
        const double u = p.x - test::sjtsk_e;
        const double v = p.y - test::sjtsk_n;
        pts << p.x << ',' << p.y << ',' << 300 + 3 * std::sin(u / 25) + std::abs(v - 150) * 0.1
            << '\n';
    }
    test::write_file(dir / "points.csv", pts.str());
    std::ostringstream lines;
    lines << std::setprecision(17) << "id,x,y,z\n";
    lines << "1," << test::sjtsk_e + 20 << ',' << test::sjtsk_n + 150 << ",300\n";
    lines << "1," << test::sjtsk_e + 280 << ',' << test::sjtsk_n + 150 << ",301\n";
    lines << "2," << test::sjtsk_e + 150 << ',' << test::sjtsk_n + 20 << ",302\n";
    lines << "2," << test::sjtsk_e + 160 << ',' << test::sjtsk_n + 120 << ",303\n";
    test::write_file(dir / "lines.csv", lines.str());
}

std::vector<std::string> tin_args(const ScratchDir& dir, const std::string& out) {
    return {"tin", (dir / "points.csv").string(), "--breaklines", (dir / "lines.csv").string(),
            "-o",  (dir / out).string(),          "--check"};
}

TEST(OptimizeCli, EveryCriterionChecksAndIsThreadIndependent) {
    ScratchDir dir;
    write_inputs(dir);
    for (const Criterion c : all_criteria()) {
        const std::string name(criterion_name(c));
        auto one = tin_args(dir, name + "-1.ply");
        one.insert(one.end(), {"--optimize", name, "--threads", "1", "--stats"});
        const auto r1 = run_dtm(one);
        ASSERT_EQ(r1.exit_code, 0) << name << ": " << r1.err;
        if (c == Criterion::minmax_angle || c == Criterion::normals_angle ||
            c == Criterion::shortest_diagonal) {
            auto two = tin_args(dir, name + "-2.ply");
            two.insert(two.end(), {"--optimize", name, "--threads", "2"});
            const auto r2 = run_dtm(two);
            ASSERT_EQ(r2.exit_code, 0) << name << ": " << r2.err;
            EXPECT_EQ(test::read_file(dir / (name + "-1.ply")),
                      test::read_file(dir / (name + "-2.ply")))
                << name;
        }
        const Tin tin = io::read_tin_ply(dir / (name + "-1.ply")).tin;
        EXPECT_EQ(count_improvable_edges(tin, c), 0u) << name;
        EXPECT_GE(tin.constraints.size(), 2u);
        if (c == Criterion::delaunay) {
            EXPECT_EQ(r1.out.find("\"optimize\""), std::string::npos);
        } else {
            EXPECT_NE(r1.out.find("\"optimize\": {\"criterion\": \"" + name + "\""),
                      std::string::npos)
                << r1.out;
            EXPECT_NE(r1.out.find("\"improvable_after\": 0"), std::string::npos);
        }
    }
    // maxmin-angle is the CDT itself.
    EXPECT_EQ(test::read_file(dir / "maxmin-angle-1.ply"), test::read_file(dir / "delaunay-1.ply"));
    EXPECT_NE(test::read_file(dir / "normal-jump-1.ply"), test::read_file(dir / "delaunay-1.ply"));
}

TEST(OptimizeCli, ReportAndOtherCommands) {
    ScratchDir dir;
    write_inputs(dir);
    auto args = tin_args(dir, "t.ply");
    args.insert(args.end(), {"--optimize", "minmax-angle", "--report", (dir / "r.json").string()});
    ASSERT_EQ(run_dtm(args).exit_code, 0);
    EXPECT_NE(
        test::read_file(dir / "r.json").find("\"optimize\": {\"criterion\": \"minmax-angle\""),
        std::string::npos);
    // grid: the data-dependent surface differs from the Delaunay one.
    const std::string pts = (dir / "points.csv").string();
    ASSERT_EQ(run_dtm({"grid", pts, "-o", (dir / "d.tif").string(), "--cell", "5"}).exit_code, 0);
    ASSERT_EQ(run_dtm({"grid", pts, "-o", (dir / "n.tif").string(), "--cell", "5", "--optimize",
                       "normals-angle"})
                  .exit_code,
              0);
    EXPECT_NE(test::read_file(dir / "d.tif"), test::read_file(dir / "n.tif"));
    const auto contour = run_dtm({"contour", pts, "-o", (dir / "c.gpkg").string(), "--interval",
                                  "1", "--optimize", "normal-jump"});
    EXPECT_EQ(contour.exit_code, 0) << contour.err;
    const auto build =
        run_dtm({"build", pts, "-o", (dir / "out").string(), "--optimize", "maxmin-area"});
    EXPECT_EQ(build.exit_code, 0) << build.err;
    const auto bad = run_dtm({"tin", pts, "-o", (dir / "x.ply").string(), "--optimize", "best"});
    EXPECT_EQ(bad.exit_code, 2);
}

}  // namespace
}  // namespace dtm
