// SPDX-License-Identifier: MIT
// Issue #17 (part 7, found by fuzz/ply_fuzz and fuzz/mesh_2dm_fuzz): the PLY and 2DM readers
// returned TINs with clockwise or degenerate faces and constrained edges that are no edge of any
// face; every algorithm downstream assumes counter-clockwise faces. They are refused now.
//
//   2 *           face 0 1 2 is counter-clockwise (kept)
//     | \         face 0 2 1 is clockwise, face 0 1 3 degenerate (3 on the line 0-1)
//   0 *--*--* 1   edge 1-2 holds a face; edge 0-4 would not (it is refused)
//        3
#include <gtest/gtest.h>

#include <string>

#include "dtm/core/error.hpp"
#include "dtm/io/formats/mesh_2dm.hpp"
#include "dtm/io/formats/ply.hpp"
#include "support/test_support.hpp"

namespace {

std::string ply(const std::string& faces,
                int face_count,
                const std::string& edges = "",
                int edge_count = 0) {
    return "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
           "property double z\nelement face " +
           std::to_string(face_count) + "\nproperty list uchar int vertex_indices\nelement edge " +
           std::to_string(edge_count) +
           "\nproperty int vertex1\nproperty int vertex2\nproperty uchar kind\nend_header\n"
           "0 0 1\n2 0 1\n0 2 1\n1 0 1\n" +
           faces + edges;
}

TEST(Regression, Issue0017PlyFacesMustBeCounterClockwiseAndEdgesOnFaces) {
    const dtm::test::ScratchDir dir;
    const auto read = [&](const std::string& text) {
        dtm::test::write_file(dir / "t.ply", text);
        return dtm::io::read_tin_ply(dir / "t.ply");
    };
    EXPECT_EQ(read(ply("3 0 1 2\n", 1)).tin.triangles.size(), 1u);
    EXPECT_EQ(read(ply("3 0 1 2\n", 1, "1 2 0\n", 1)).tin.constraints.size(), 1u);
    EXPECT_THROW(read(ply("3 0 2 1\n", 1)), dtm::InputError);
    EXPECT_THROW(read(ply("3 0 3 1\n", 1)), dtm::InputError);
    EXPECT_THROW(read(ply("3 0 1 2\n", 1, "0 3 0\n", 1)), dtm::InputError);
}

TEST(Regression, Issue0017TwoDmFacesMustBeCounterClockwise) {
    const dtm::test::ScratchDir dir;
    const std::string nodes = "MESH2D\nND 1 0 0 1\nND 2 2 0 1\nND 3 0 2 1\nND 4 1 0 1\n";
    dtm::test::write_file(dir / "ok.2dm", nodes + "E3T 1 1 2 3 1\n");
    EXPECT_EQ(dtm::io::read_2dm(dir / "ok.2dm").triangles.size(), 1u);
    dtm::test::write_file(dir / "cw.2dm", nodes + "E3T 1 1 3 2 1\n");
    EXPECT_THROW((void)dtm::io::read_2dm(dir / "cw.2dm"), dtm::InputError);
    dtm::test::write_file(dir / "flat.2dm", nodes + "E3T 1 1 4 2 1\n");
    EXPECT_THROW((void)dtm::io::read_2dm(dir / "flat.2dm"), dtm::InputError);
}

}  // namespace
