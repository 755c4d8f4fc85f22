// SPDX-License-Identifier: MIT
#include "dtm/io/formats/ply.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "dtm/core/error.hpp"
#include "dtm/io/tin_file.hpp"
#include "support/test_support.hpp"

namespace fs = std::filesystem;
using dtm::ConstrainedEdge;
using dtm::ConstraintKind;
using dtm::Tin;
using dtm::test::read_file;
using dtm::test::ScratchDir;
using dtm::test::write_file;

namespace {

/// A (cols x rows) grid of vertices split into counter-clockwise triangles, with awkward
/// coordinates: S-JTSK-like magnitudes, 0.1, negative zero and subnormals.
Tin grid_tin(std::uint32_t cols, std::uint32_t rows) {
    Tin tin;
    const double awkward[] = {0.1,
                              -750000.123456789,
                              -1050000.987654321,
                              std::numeric_limits<double>::denorm_min(),
                              -std::numeric_limits<double>::denorm_min() * 12345.0,
                              2.2250738585072009e-308,
                              -0.0,
                              1e300,
                              1.0 / 3.0};
    std::size_t k = 0;
    for (std::uint32_t r = 0; r < rows; ++r) {
        for (std::uint32_t c = 0; c < cols; ++c) {
            const double z = awkward[k++ % std::size(awkward)];
            tin.vertices.push_back({-750000.123456789 + c * 0.1, -1050000.987654321 + r * 0.7, z});
        }
    }
    for (std::uint32_t r = 0; r + 1 < rows; ++r) {
        for (std::uint32_t c = 0; c + 1 < cols; ++c) {
            const std::uint32_t a = r * cols + c, b = a + 1, d = a + cols, e = d + 1;
            tin.triangles.push_back({{a, b, e}, {}});
            tin.triangles.push_back({{a, e, d}, {}});
        }
    }
    tin.constraints = {ConstrainedEdge{0, 1, ConstraintKind::breakline},
                       ConstrainedEdge{1, 2, ConstraintKind::soft_breakline},
                       ConstrainedEdge{0, cols, ConstraintKind::boundary},
                       ConstrainedEdge{cols, cols + 1, ConstraintKind::hole}};
    return tin;
}

/// Neighbour links by brute force: triangles sharing the edge opposite v[i].
void set_neighbours_by_brute_force(Tin& tin) {
    for (auto& t : tin.triangles) {
        for (std::size_t i = 0; i < 3; ++i) {
            const auto a = t.v[(i + 1) % 3], b = t.v[(i + 2) % 3];
            t.n[i] = dtm::no_triangle;
            for (std::size_t u = 0; u < tin.triangles.size(); ++u) {
                const auto& o = tin.triangles[u];
                for (std::size_t j = 0; j < 3; ++j) {
                    if (o.v[j] == b && o.v[(j + 1) % 3] == a)
                        t.n[i] = static_cast<dtm::TriangleIndex>(u);
                }
            }
        }
    }
}

void expect_bit_identical(const Tin& expected, const Tin& actual) {
    ASSERT_EQ(expected.vertices.size(), actual.vertices.size());
    for (std::size_t i = 0; i < expected.vertices.size(); ++i) {
        const auto& e = expected.vertices[i];
        const auto& a = actual.vertices[i];
        EXPECT_EQ(std::bit_cast<std::uint64_t>(e.x), std::bit_cast<std::uint64_t>(a.x)) << i;
        EXPECT_EQ(std::bit_cast<std::uint64_t>(e.y), std::bit_cast<std::uint64_t>(a.y)) << i;
        EXPECT_EQ(std::bit_cast<std::uint64_t>(e.z), std::bit_cast<std::uint64_t>(a.z)) << i;
    }
    ASSERT_EQ(expected.triangles.size(), actual.triangles.size());
    for (std::size_t t = 0; t < expected.triangles.size(); ++t) {
        EXPECT_EQ(expected.triangles[t].v, actual.triangles[t].v) << "triangle " << t;
        EXPECT_EQ(expected.triangles[t].n, actual.triangles[t].n) << "neighbours of " << t;
    }
    EXPECT_EQ(expected.constraints, actual.constraints);
}

std::string error_of(const fs::path& path) {
    try {
        (void)dtm::io::read_tin_ply(path);
    } catch (const dtm::InputError& e) {
        return e.what();
    }
    return "no InputError";
}

const std::string wkt = R"(PROJCRS["S-JTSK / Krovak East North",BASEGEOGCRS["S-JTSK"]])";

}  // namespace

class PlyRoundTrip : public ::testing::TestWithParam<bool> {};

TEST_P(PlyRoundTrip, VerticesAreBitIdenticalAndTopologyIsRestored) {
    const ScratchDir dir;
    Tin tin = grid_tin(13, 7);
    set_neighbours_by_brute_force(tin);
    dtm::io::write_tin(tin, dir / "tin.ply", {.crs_wkt = wkt, .ascii = GetParam()});
    const dtm::io::LoadedTin loaded = dtm::io::read_tin_ply(dir / "tin.ply");
    expect_bit_identical(tin, loaded.tin);
    EXPECT_EQ(loaded.crs_wkt, wkt);
}

TEST_P(PlyRoundTrip, EmptyTinRoundTrips) {
    const ScratchDir dir;
    dtm::io::write_tin(Tin{}, dir / "empty.ply", {.crs_wkt = {}, .ascii = GetParam()});
    const dtm::io::LoadedTin loaded = dtm::io::read_tin_ply(dir / "empty.ply");
    EXPECT_TRUE(loaded.tin.vertices.empty());
    EXPECT_TRUE(loaded.tin.triangles.empty());
    EXPECT_TRUE(loaded.crs_wkt.empty());
}

TEST_P(PlyRoundTrip, TruncatedFileIsAnInputErrorNamingTheFile) {
    const ScratchDir dir;
    const Tin tin = grid_tin(5, 4);
    dtm::io::write_tin(tin, dir / "whole.ply", {.crs_wkt = {}, .ascii = GetParam()});
    const std::string bytes = read_file(dir / "whole.ply");
    const std::size_t body = bytes.find("end_header\n") + 11;
    // Cut inside the header, the vertices, the faces and the edges.
    for (const std::size_t size :
         {body - 5, body + 30, (body + bytes.size()) / 2, bytes.size() - 3}) {
        write_file(dir / "cut.ply", bytes.substr(0, size));
        const std::string message = error_of(dir / "cut.ply");
        EXPECT_NE(message.find("cut.ply"), std::string::npos) << "size " << size << ": " << message;
    }
}

INSTANTIATE_TEST_SUITE_P(Encodings,
                         PlyRoundTrip,
                         ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& param_info) {
                             return param_info.param ? "Ascii" : "Binary";
                         });

TEST(PlyWriter, AsciiHeaderDeclaresTheDtmLayout) {
    const ScratchDir dir;
    dtm::io::write_tin(grid_tin(2, 2), dir / "t.ply",
                       {.crs_wkt = "GEOGCRS[\"x\",\n    ID[1]]", .ascii = true});
    const std::string text = read_file(dir / "t.ply");
    const std::string expected_header =
        "ply\nformat ascii 1.0\ncomment generated by dtm " DTM_VERSION
        "\n"
        "comment crs GEOGCRS[\"x\",ID[1]]\n"
        "element vertex 4\nproperty double x\nproperty double y\n"
        "property double z\nelement face 2\n"
        "property list uchar int vertex_indices\nelement edge 4\n"
        "property int vertex1\nproperty int vertex2\n"
        "property uchar kind\nend_header\n";
    EXPECT_EQ(text.substr(0, expected_header.size()), expected_header);
    EXPECT_NE(text.find("\n3 0 1 3\n3 0 3 2\n0 1 0\n1 2 1\n0 2 2\n2 3 3\n"), std::string::npos)
        << text;
}

TEST(PlyWriter, BinaryBodyHasTheExactSize) {
    const ScratchDir dir;
    const Tin tin = grid_tin(10, 10);
    dtm::io::write_tin(tin, dir / "t.ply", {});
    const std::string bytes = read_file(dir / "t.ply");
    ASSERT_NE(bytes.find("format binary_little_endian 1.0\n"), std::string::npos);
    const std::size_t body = bytes.find("end_header\n") + 11;
    EXPECT_EQ(bytes.size() - body,
              tin.vertices.size() * 24 + tin.triangles.size() * 13 + tin.constraints.size() * 9);
}

TEST(PlyWriter, UnknownExtensionIsAUsageErrorListingTheKnownOnes) {
    const ScratchDir dir;
    try {
        dtm::io::write_tin(grid_tin(2, 2), dir / "t.xyz", {});
        FAIL() << "no exception";
    } catch (const dtm::UsageError& e) {
        EXPECT_NE(std::string(e.what()).find(".ply"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(dir / "t.xyz"));
}

TEST(PlyWriter, ExtensionIsMatchedCaseInsensitively) {
    const ScratchDir dir;
    // 3 x 2: the fixture's constrained edge 1-2 is an edge of a face only from 3 columns on.
    dtm::io::write_tin(grid_tin(3, 2), dir / "T.PLY", {});
    EXPECT_EQ(dtm::io::read_tin_ply(dir / "T.PLY").tin.vertices.size(), 6u);
}

TEST(PlyWriter, FailedWriteLeavesTheExistingTargetUntouched) {
    const ScratchDir dir;
    write_file(dir / "tin.ply", "previous result");
    Tin broken = grid_tin(40, 40);
    broken.triangles.back().v[2] = 99999;  // fails after most of the body is written
    EXPECT_THROW(dtm::io::write_tin(broken, dir / "tin.ply", {}), dtm::Error);
    EXPECT_EQ(read_file(dir / "tin.ply"), "previous result");
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir.path())) ++files;
    EXPECT_EQ(files, 1u) << "a temporary file was left behind";
}

TEST(PlyReader, ToleratesForeignCommentsAndCrlf) {
    const ScratchDir dir;
    write_file(dir / "t.ply",
               "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\nobj_info x\r\n"
               "element vertex 3\r\nproperty double x\r\nproperty double y\r\nproperty double z\r\n"
               "element face 1\r\nproperty list uchar int vertex_indices\r\nend_header\r\n"
               "0 0 1\r\n1 0 2\r\n0 1 3\r\n3 0 1 2\r\n");
    const auto loaded = dtm::io::read_tin_ply(dir / "t.ply");
    ASSERT_EQ(loaded.tin.triangles.size(), 1u);
    EXPECT_EQ(loaded.tin.vertices[2].z, 3.0);
    EXPECT_TRUE(loaded.tin.constraints.empty());
    EXPECT_TRUE(loaded.crs_wkt.empty());
}

TEST(PlyReader, UnsupportedFormatNamesTheFileAndHeaderLine) {
    const ScratchDir dir;
    write_file(dir / "big.ply", "ply\nformat binary_big_endian 1.0\nend_header\n");
    const std::string message = error_of(dir / "big.ply");
    EXPECT_NE(message.find("big.ply:2"), std::string::npos) << message;
    EXPECT_NE(message.find("binary_big_endian"), std::string::npos) << message;
}

TEST(PlyReader, UnknownPropertyNamesTheFileAndHeaderLine) {
    const ScratchDir dir;
    write_file(dir / "color.ply",
               "ply\nformat ascii 1.0\nelement vertex 1\nproperty double x\nproperty double y\n"
               "property double z\nproperty uchar red\nend_header\n0 0 0 255\n");
    const std::string message = error_of(dir / "color.ply");
    EXPECT_NE(message.find("color.ply:7"), std::string::npos) << message;
    EXPECT_NE(message.find("red"), std::string::npos) << message;
}

TEST(PlyReader, FloatCoordinatesAreRejectedRatherThanConverted) {
    const ScratchDir dir;
    write_file(dir / "f.ply",
               "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n");
    EXPECT_NE(error_of(dir / "f.ply").find("f.ply:4"), std::string::npos);
}

TEST(PlyReader, FaceIndexOutOfRangeIsAnInputError) {
    const ScratchDir dir;
    write_file(dir / "t.ply",
               "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
               "property double z\nelement face 1\nproperty list uchar int vertex_indices\n"
               "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
    const std::string message = error_of(dir / "t.ply");
    EXPECT_NE(message.find("t.ply:13"), std::string::npos) << message;
    EXPECT_NE(message.find("vertex 7"), std::string::npos) << message;
}

TEST(PlyReader, MissingFileIsAnInputError) {
    const ScratchDir dir;
    EXPECT_NE(error_of(dir / "absent.ply").find("absent.ply"), std::string::npos);
}

TEST(PlyReader, NotAPlyFileIsAnInputError) {
    const ScratchDir dir;
    write_file(dir / "points.ply", "1 2 3\n4 5 6\n");
    EXPECT_NE(error_of(dir / "points.ply").find("not a PLY file"), std::string::npos);
}

TEST(PlyReader, FacesSharingAnEdgeInTheSameDirectionAreAnInputError) {
    const ScratchDir dir;
    // Faces 0-1-2 and 0-1-3 both run 0 -> 1: one of them is clockwise or they overlap.
    write_file(dir / "t.ply",
               "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
               "property double z\nelement face 2\nproperty list uchar int vertex_indices\n"
               "end_header\n0 0 0\n1 0 0\n0 1 0\n1 -1 0\n3 0 1 2\n3 0 1 3\n");
    EXPECT_NE(error_of(dir / "t.ply").find("same direction"), std::string::npos);
}

namespace {

TEST(PlyTile, VertexIdsRoundTripInBothEncodingsBeyond32Bits) {
    const ScratchDir dir;
    const Tin tin = grid_tin(3, 3);
    std::vector<std::uint64_t> ids;
    for (std::size_t i = 0; i < tin.vertices.size(); ++i)
        ids.push_back((std::uint64_t{5} << 32) + 7 * i);
    for (const bool ascii : {false, true}) {
        dtm::io::TinWriteOptions options;
        options.ascii = ascii;
        options.vertex_ids = ids;
        dtm::io::write_tin_ply(tin, dir / "tile.ply", options);
        const dtm::io::LoadedTin back = dtm::io::read_tin_ply(dir / "tile.ply");
        EXPECT_EQ(back.vertex_ids, ids) << (ascii ? "ascii" : "binary");
        EXPECT_EQ(back.tin.triangles.size(), tin.triangles.size());
    }
    EXPECT_TRUE(dtm::io::read_tin_ply([&] {
                    dtm::io::write_tin_ply(tin, dir / "plain.ply", {});
                    return dir / "plain.ply";
                }())
                    .vertex_ids.empty());
}

TEST(PlyTile, AVertexIdElementOfAnotherCountNamesTheHeaderLine) {
    const ScratchDir dir;
    write_file(dir / "t.ply",
               "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
               "property double z\nelement face 1\nproperty list uchar int vertex_indices\n"
               "element edge 0\nproperty int vertex1\nproperty int vertex2\n"
               "element vertex_id 2\nproperty uint high\nproperty uint low\n"
               "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n0 1\n0 2\n");
    const std::string message = error_of(dir / "t.ply");
    EXPECT_NE(message.find("t.ply:12"), std::string::npos) << message;
    EXPECT_NE(message.find("vertex_id has 2 entries for 3 vertices"), std::string::npos) << message;
}

}  // namespace
