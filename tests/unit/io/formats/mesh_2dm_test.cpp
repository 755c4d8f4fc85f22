// SPDX-License-Identifier: MIT
#include "dtm/io/formats/mesh_2dm.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "dtm/algo/validate.hpp"
#include "dtm/core/error.hpp"
#include "support/test_support.hpp"
#include "support/tin_fixture.hpp"

namespace {

TEST(Mesh2dm, RoundTripKeepsCountsCoordinatesAndConnectivity) {
    const dtm::Tin tin = dtm::test::grid_tin(6);
    dtm::test::ScratchDir dir;
    dtm::io::write_2dm(tin, dir / "tin.2dm", {});
    const dtm::Tin back = dtm::io::read_2dm(dir / "tin.2dm");
    ASSERT_EQ(back.vertices.size(), tin.vertices.size());
    ASSERT_EQ(back.triangles.size(), tin.triangles.size());
    for (std::size_t i = 0; i < tin.vertices.size(); ++i) {
        EXPECT_EQ(back.vertices[i], tin.vertices[i]) << "vertex " << i;  // bit-exact
    }
    for (std::size_t i = 0; i < tin.triangles.size(); ++i) {
        EXPECT_EQ(back.triangles[i].v, tin.triangles[i].v) << "triangle " << i;
    }
}

TEST(Mesh2dm, ReadingGivesALinkedTin) {
    dtm::Tin tin = dtm::test::grid_tin(6);
    tin.constraints.clear();  // 2DM carries none
    dtm::test::ScratchDir dir;
    dtm::io::write_2dm(tin, dir / "tin.2dm", {});
    const dtm::Tin back = dtm::io::read_2dm(dir / "tin.2dm");
    EXPECT_TRUE(dtm::verify_topology(back).ok()) << dtm::verify_topology(back).text();
    std::size_t links = 0;
    for (const dtm::Triangle& t : back.triangles) {
        for (const auto n : t.n) links += n != dtm::no_triangle ? 1 : 0;
    }
    EXPECT_EQ(links, 2 * (3 * 5 * 5 - 2 * 5));  // twice the interior edges of a 5 x 5 cell grid
}

TEST(Mesh2dm, OverlappingElementsAreAnInputErrorNamingTheFile) {
    dtm::test::ScratchDir dir;
    dtm::test::write_file(
        dir / "bad.2dm",
        "MESH2D\nND 1 0 0 0\nND 2 1 0 0\nND 3 0 1 0\nE3T 1 1 2 3 1\nE3T 2 1 2 3 1\n");
    try {
        (void)dtm::io::read_2dm(dir / "bad.2dm");
        FAIL() << "no exception";
    } catch (const dtm::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("bad.2dm"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("same direction"), std::string::npos) << e.what();
    }
}

TEST(Mesh2dm, LargeTinSpanningSeveralWriteBlocksRoundTrips) {
    const dtm::Tin tin = dtm::test::grid_tin(200);  // 40,000 nodes: a few MiB of text
    dtm::test::ScratchDir dir;
    dtm::io::write_2dm(tin, dir / "tin.2dm", {});
    EXPECT_GT(std::filesystem::file_size(dir / "tin.2dm"), std::uintmax_t{2} << 20);
    const dtm::Tin back = dtm::io::read_2dm(dir / "tin.2dm");
    ASSERT_EQ(back.vertices.size(), tin.vertices.size());
    ASSERT_EQ(back.triangles.size(), tin.triangles.size());
    EXPECT_EQ(back.vertices.back(), tin.vertices.back());
    EXPECT_EQ(back.triangles.back().v, tin.triangles.back().v);
}

TEST(Mesh2dm, WritesMesh2dHeaderAndOneBasedIds) {
    const dtm::Tin tin = dtm::test::grid_tin(2);
    dtm::test::ScratchDir dir;
    dtm::io::write_2dm(tin, dir / "tin.2dm", {});
    std::istringstream text(dtm::test::read_file(dir / "tin.2dm"));
    std::string line;
    std::getline(text, line);
    EXPECT_EQ(line, "MESH2D");
    std::size_t nodes = 0;
    std::size_t elements = 0;
    while (std::getline(text, line)) {
        if (line.rfind("ND ", 0) == 0) {
            ++nodes;
            const std::string prefix = "ND " + std::to_string(nodes) + " ";
            EXPECT_EQ(line.substr(0, prefix.size()), prefix);
        } else if (line.rfind("E3T ", 0) == 0) {
            ++elements;
            EXPECT_EQ(line, elements == 1 ? "E3T 1 1 2 4 1" : "E3T 2 1 4 3 1");
        }
    }
    EXPECT_EQ(nodes, 4u);
    EXPECT_EQ(elements, 2u);
}

TEST(Mesh2dm, ReadRejectsElementWithUnknownNodeNamingTheLine) {
    dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "bad.2dm", "MESH2D\nND 1 0 0 0\nND 2 1 0 0\nE3T 1 1 2 9 1\n");
    try {
        (void)dtm::io::read_2dm(dir / "bad.2dm");
        FAIL() << "expected InputError";
    } catch (const dtm::InputError& e) {
        EXPECT_EQ(e.line(), 4u);
        EXPECT_NE(std::string(e.what()).find("unknown node 9"), std::string::npos) << e.what();
    }
}

TEST(Mesh2dm, ReadRejectsFileWithoutMesh2dHeader) {
    dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "bad.2dm", "ND 1 0 0 0\n");
    EXPECT_THROW((void)dtm::io::read_2dm(dir / "bad.2dm"), dtm::InputError);
}

}  // namespace
