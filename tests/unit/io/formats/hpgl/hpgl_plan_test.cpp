// SPDX-License-Identifier: MIT
// The synthetic 1:500 height plan, in plain HP-GL and in PCL-wrapped PE-encoded HP-GL/2, read
// back under every georeferencing: every spot height at its ground position with its height, the
// breaklines with their heights, the soft line soft, the boundary and the building hole closed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <utility>

#include "dtm/io/formats/hpgl.hpp"
#include "support/hpgl_plan_generator.hpp"
#include "support/test_support.hpp"

namespace {

using dtm::Point2;
using dtm::Point3;
using dtm::io::PenRole;

constexpr double ground_tolerance = 1e-6;  // metres

enum class Encoding { plain, pcl };
enum class Georef { scale, scale_rotated, control_affine, control_similarity };

struct Case {
    Encoding encoding;
    Georef georef;
};

std::string name(const testing::TestParamInfo<Case>& info) {
    const char* enc = info.param.encoding == Encoding::plain ? "PlainHpgl" : "PclPeHpgl2";
    const char* geo[] = {"Scale", "ScaleRotated", "ControlAffine", "ControlSimilarity"};
    return std::string(enc) + geo[static_cast<int>(info.param.georef)];
}

class HpglPlan : public testing::TestWithParam<Case> {
protected:
    void SetUp() override {
        dtm::test::HpglPlanOptions o;
        o.rotation_deg = GetParam().georef == Georef::scale_rotated ? 33.5 : 0.0;
        if (GetParam().georef == Georef::control_affine ||
            GetParam().georef == Georef::control_similarity) {
            o.rotation_deg = -12.25;  // the control points carry it
        }
        plan_ = dtm::test::make_hpgl_plan(o);
        const auto path = scratch_ / "plan.plt";
        dtm::test::write_file(
            path, GetParam().encoding == Encoding::plain ? plan_.plain_hpgl : plan_.pcl_hpgl2);
        options_.hpgl.pens = {{2, PenRole::breakline},
                              {3, PenRole::boundary},
                              {4, PenRole::hole},
                              {1, PenRole::ignore}};
        switch (GetParam().georef) {
            case Georef::scale:
            case Georef::scale_rotated:
                options_.hpgl.scale = 500.0;
                options_.hpgl.origin_e = o.origin_e;
                options_.hpgl.origin_n = o.origin_n;
                options_.hpgl.rotation_deg = o.rotation_deg;
                break;
            case Georef::control_affine:
                dtm::test::write_file(scratch_ / "control.csv", plan_.control_csv);
                options_.hpgl.control_file = (scratch_ / "control.csv").string();
                break;
            case Georef::control_similarity:
                dtm::test::write_file(scratch_ / "control.csv", plan_.control_csv_two);
                options_.hpgl.control_file = (scratch_ / "control.csv").string();
                break;
        }
        result_ = dtm::io::read_hpgl({path, dtm::io::InputRole::points}, options_);
    }

    dtm::test::ScratchDir scratch_;
    dtm::test::HpglPlan plan_;
    dtm::io::ReadOptions options_;
    dtm::io::ReadResult result_;
};

double xy_distance(const Point3& a, const Point3& b) { return std::hypot(a.x - b.x, a.y - b.y); }

void expect_same_line(const std::vector<Point3>& got, const std::vector<Point3>& want) {
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < want.size(); ++i) {
        EXPECT_LE(xy_distance(got[i], want[i]), ground_tolerance) << "vertex " << i;
        EXPECT_NEAR(got[i].z, want[i].z, 1e-9) << "vertex " << i;
    }
}

TEST_P(HpglPlan, EverySpotHeightComesBackAtItsGroundPositionWithItsHeight) {
    const auto& points = result_.terrain.points;
    ASSERT_EQ(points.size(), plan_.spot_heights.size());
    for (const Point3& truth : plan_.spot_heights) {
        const auto nearest =
            std::min_element(points.begin(), points.end(), [&](const Point3& a, const Point3& b) {
                return xy_distance(a, truth) < xy_distance(b, truth);
            });
        EXPECT_LE(xy_distance(*nearest, truth), ground_tolerance);
        EXPECT_EQ(nearest->z, truth.z);  // the labelled decimal, correctly rounded
    }
    EXPECT_EQ(result_.summary.points, plan_.spot_heights.size());
}

TEST_P(HpglPlan, BreaklinesTakeSpotHeightsAndInterpolateBetweenThem) {
    const auto& lines = result_.terrain.breaklines;
    ASSERT_EQ(lines.size(), plan_.breaklines.size());
    for (std::size_t i = 0; i < lines.size(); ++i) {
        EXPECT_FALSE(lines[i].closed);
        expect_same_line(lines[i].points, plan_.breaklines[i]);
    }
}

TEST_P(HpglPlan, LineWithoutSpotHeightsBecomesSoftWithAWarning) {
    const auto& soft = result_.terrain.soft_breaklines;
    ASSERT_EQ(soft.size(), 1u);
    ASSERT_EQ(soft[0].points.size(), plan_.soft_breakline.size());
    for (std::size_t i = 0; i < soft[0].points.size(); ++i) {
        EXPECT_LE(std::hypot(soft[0].points[i].x - plan_.soft_breakline[i].x,
                             soft[0].points[i].y - plan_.soft_breakline[i].y),
                  ground_tolerance);
    }
    const auto& w = result_.summary.warnings;
    EXPECT_TRUE(std::any_of(w.begin(), w.end(),
                            [](const std::string& s) { return s.find("made soft") != s.npos; }));
}

TEST_P(HpglPlan, BoundaryAndBuildingHoleAreClosedRingsWithHeights) {
    ASSERT_EQ(result_.terrain.boundaries.size(), 1u);
    ASSERT_EQ(result_.terrain.holes.size(), 1u);
    EXPECT_TRUE(result_.terrain.boundaries[0].closed);
    EXPECT_TRUE(result_.terrain.holes[0].closed);
    expect_same_line(result_.terrain.boundaries[0].points, plan_.boundary);
    expect_same_line(result_.terrain.holes[0].points, plan_.hole);
    EXPECT_EQ(result_.summary.boundaries, 1u);
    EXPECT_EQ(result_.summary.holes, 1u);
}

TEST_P(HpglPlan, ParcelNumbersAndFrameAreNotTerrain) {
    // 30 spot heights only: the integer parcel labels are not heights, the pen 1 frame is ignored.
    EXPECT_EQ(result_.terrain.points.size(), 30u);
    const auto& w = result_.summary.warnings;
    EXPECT_TRUE(std::any_of(w.begin(), w.end(), [](const std::string& s) {
        return s.find("37 labels, 30 spot heights (30 on markers)") != s.npos;
    }));
    EXPECT_TRUE(std::any_of(w.begin(), w.end(), [](const std::string& s) {
        return s.find("pen:lines 1:1") != s.npos;
    }));
}

INSTANTIATE_TEST_SUITE_P(Encodings,
                         HpglPlan,
                         testing::Values(Case{Encoding::plain, Georef::scale},
                                         Case{Encoding::plain, Georef::scale_rotated},
                                         Case{Encoding::plain, Georef::control_affine},
                                         Case{Encoding::plain, Georef::control_similarity},
                                         Case{Encoding::pcl, Georef::scale},
                                         Case{Encoding::pcl, Georef::scale_rotated},
                                         Case{Encoding::pcl, Georef::control_affine},
                                         Case{Encoding::pcl, Georef::control_similarity}),
                         name);

TEST(HpglPlanReader, IntegerLabelsOnHeightPensAreHeights) {
    dtm::test::ScratchDir scratch;
    const auto plan = dtm::test::make_hpgl_plan();
    dtm::test::write_file(scratch / "plan.plt", plan.plain_hpgl);
    dtm::io::ReadOptions options;
    options.hpgl.height_pens = {1};
    const auto result =
        dtm::io::read_hpgl({scratch / "plan.plt", dtm::io::InputRole::points}, options);
    // The parcel numbers are integers on pen 1: now heights too, at their own label positions.
    EXPECT_EQ(result.terrain.points.size(), plan.spot_heights.size() + plan.parcel_labels);
    const auto& w = result.summary.warnings;
    EXPECT_TRUE(std::any_of(w.begin(), w.end(), [&](const std::string& s) {
        return s.find(std::to_string(plan.parcel_labels) + " height labels have no marker") !=
               s.npos;
    }));
}

TEST(HpglPlanReader, WithoutGeoreferencingCoordinatesArePlotterMillimetres) {
    dtm::test::ScratchDir scratch;
    const auto plan = dtm::test::make_hpgl_plan();
    dtm::test::write_file(scratch / "plan.plt", plan.pcl_hpgl2);
    const auto result = dtm::io::read_hpgl({scratch / "plan.plt", dtm::io::InputRole::points}, {});
    ASSERT_EQ(result.terrain.points.size(), plan.spot_heights.size());
    // The first spot height is plotted at 2000, 2000 plotter units = 50 mm, 50 mm.
    EXPECT_TRUE(
        std::any_of(result.terrain.points.begin(), result.terrain.points.end(),
                    [](const Point3& p) { return p.x == 50.0 && p.y == 50.0 && p.z == 300.0; }));
    const auto& w = result.summary.warnings;
    EXPECT_TRUE(std::any_of(w.begin(), w.end(), [](const std::string& s) {
        return s.find("not georeferenced") != s.npos;
    }));
}

}  // namespace

namespace {

// tests/data/hpgl holds the generated plan for the CLI and for users to try
// (`dtm info tests/data/hpgl/plan_500_pcl_pe.plt --hpgl-pens 2=breakline,3=boundary,4=hole
// --hpgl-scale 500 --hpgl-origin=-745000,-1045000`). DTM_UPDATE_GOLDEN=1 rewrites them.
TEST(HpglPlanFixtures, CommittedFilesAreTheGeneratorsOutput) {
    const auto plan = dtm::test::make_hpgl_plan();
    const std::pair<const char*, const std::string*> files[] = {
        {"hpgl/plan_500_plain.plt", &plan.plain_hpgl},
        {"hpgl/plan_500_pcl_pe.plt", &plan.pcl_hpgl2},
        {"hpgl/plan_500_control.csv", &plan.control_csv}};
    const bool update = std::getenv("DTM_UPDATE_GOLDEN") != nullptr;
    for (const auto& [name, bytes] : files) {
        if (update) dtm::test::write_file(dtm::test::data_path(name), *bytes);
        EXPECT_EQ(dtm::test::read_file(dtm::test::data_path(name)), *bytes) << name;
    }
}

}  // namespace
