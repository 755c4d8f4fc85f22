// SPDX-License-Identifier: MIT
#include "dtm/products/report.hpp"

#include <cpl_json.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "support/test_support.hpp"

namespace {

dtm::products::BuildReport sample_report() {
    dtm::products::BuildReport r;
    dtm::io::InputSummary in;
    in.path = "survey \"A\".csv";
    in.format = "csv";
    in.points = 10;
    in.warnings = {"line 3: tab\tinside"};
    r.inputs.push_back(in);
    r.skipped_lines = 2;
    r.crs_wkt = "EPSG:5514";
    r.accounting.survey_points = {10, 7, 2, 1};
    r.accounting.line_vertices = {4, 4, 0, 0};
    r.conflicts.push_back({{-750000.5, -1050000.25}, 301.0, 301.5});
    r.surface.vertex_count = 11;
    r.surface.triangle_count = 12;
    r.surface.planimetric_area = 100.0;
    r.surface.surface_area = 101.0;
    r.surface.extent.add(-750000.0, -1050000.0);
    r.surface.z_min = 300.0;
    r.surface.z_max = std::numeric_limits<double>::quiet_NaN();
    r.timings = {{"read", 0.5}, {"triangulate", 0.25}};
    r.outputs = {"tin.ply", "report.json"};
    return r;
}

CPLJSONObject parse(const std::string& text) {
    CPLJSONDocument doc;
    EXPECT_TRUE(doc.LoadMemory(text)) << text;
    return doc.GetRoot();
}

TEST(Report, IsValidJsonWithEscapedStrings) {
    const CPLJSONObject root = parse(dtm::products::report_json(sample_report()));
    ASSERT_TRUE(root.IsValid());
    const CPLJSONArray inputs = root.GetArray("inputs");
    ASSERT_EQ(inputs.Size(), 1);
    EXPECT_EQ(inputs[0].GetString("path"), "survey \"A\".csv");
    EXPECT_EQ(inputs[0].GetArray("warnings")[0].ToString(), "line 3: tab\tinside");
}

TEST(Report, PointAccountingAddsUpToEveryInputRecord) {
    const CPLJSONObject points =
        parse(dtm::products::report_json(sample_report())).GetObj("points");
    EXPECT_EQ(points.GetObj("survey_points").GetLong("merged_duplicates"), 2);
    EXPECT_EQ(points.GetObj("survey_points").GetLong("outside_boundary_or_in_hole"), 1);
    EXPECT_EQ(points.GetLong("skipped_bad_lines"), 2);
    EXPECT_EQ(points.GetLong("total_accounted"), 10 + 4 + 2);
}

TEST(Report, CrsConflictsAreaAndTimingsAreReported) {
    const CPLJSONObject root = parse(dtm::products::report_json(sample_report()));
    EXPECT_EQ(root.GetObj("crs").GetString("authority"), "EPSG:5514");
    EXPECT_EQ(root.GetObj("conflicts").GetLong("count"), 1);
    EXPECT_DOUBLE_EQ(root.GetObj("conflicts").GetArray("items")[0].GetDouble("difference"), 0.5);
    EXPECT_DOUBLE_EQ(root.GetObj("area").GetDouble("ratio"), 1.01);
    EXPECT_DOUBLE_EQ(root.GetObj("timings_seconds").GetDouble("total"), 0.75);
    // NaN cannot be written in JSON: it becomes null.
    EXPECT_EQ(root.GetObj("z_range").GetObj("max").GetType(), CPLJSONObject::Type::Null);
}

}  // namespace
