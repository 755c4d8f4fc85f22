// SPDX-License-Identifier: MIT
// products::distributed_tin with hard breaklines, a boundary cut by every seam and a hole
// straddling seams, a hole seed inside a closed breakline, and `max_edge`, on 1 to 64 in-process
// ranks (R-B2, R-B3, R-P1): the
// PLY bytes, with the constrained-edge element, of the serial load_inputs -> triangulate ->
// write_tin_ply path. Lines along the first seam, across every rank, a diagonal longer than any
// rank's region, lines crossing each other (split first), a line through survey points (its
// vertices merge with them), short hooks; uniform points, a cocircular lattice and S-JTSK
// magnitudes; random delays before every send.
#include "dtm/products/distributed_tin.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "dtm/algo/triangulate.hpp"
#include "dtm/dist/in_process.hpp"
#include "dtm/io/formats/ply.hpp"
#include "dtm/io/formats/tin_tiles.hpp"
#include "dtm/io/inputs.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

struct Case {
    std::string name;
    std::vector<dtm::Point3> points;
    double x0, y0, size;
};

std::vector<Case> cases() {
    std::vector<Case> out;
    std::mt19937_64 rng(20261204);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Case uniform{"uniform", {}, 0.0, 0.0, 1000.0};
    for (int i = 0; i < 4000; ++i) {
        const double x = 1000.0 * u(rng), y = 1000.0 * u(rng);
        uniform.points.push_back({x, y, 300.0 + 0.01 * x + 3.0 * std::sin(y / 90.0)});
    }
    out.push_back(uniform);
    Case lattice{"lattice", {}, 0.0, 0.0, 120.0};
    for (int i = 0; i <= 60; ++i) {
        for (int j = 0; j <= 60; ++j)
            lattice.points.push_back({i * 2.0, j * 2.0, 100.0 + (i * 7 + j * 13) % 17});
    }
    out.push_back(lattice);
    Case sjtsk{"sjtsk", {}, -751000.0, -1051000.0, 1000.0};
    for (int i = 0; i < 3000; ++i) {
        const double x = -751000.0 + std::round(u(rng) * 1e6) / 1000.0;
        const double y = -1051000.0 + std::round(u(rng) * 1e6) / 1000.0;
        sjtsk.points.push_back({x, y, 250.0 + 10.0 * u(rng)});
    }
    out.push_back(sjtsk);
    return out;
}

std::string points_csv(const Case& c) {
    std::string text = "x,y,z\n";
    char line[128];
    for (const dtm::Point3& p : c.points) {
        std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g\n", p.x, p.y, p.z);
        text += line;
    }
    return text;
}

std::string lines_csv(const Case& c) {
    const double x0 = c.x0, y0 = c.y0, w = c.size;
    const auto z = [&](double x, double y) {
        return 260.0 + (x - x0) / w * 20.0 + (y - y0) / w * 10.0;
    };
    std::vector<std::vector<std::array<double, 3>>> lines;
    const auto add = [&](std::vector<std::pair<double, double>> xy) {
        auto& line = lines.emplace_back();
        for (const auto& [x, y] : xy) line.push_back({x, y, z(x, y)});
    };
    std::vector<std::pair<double, double>> along, across,
        diagonal{{x0 + 3.0, y0 + 5.0}, {x0 + w - 4.0, y0 + w - 2.0}};
    for (int k = 0; k <= 40; ++k)
        along.emplace_back(x0 + w * 0.5, y0 + w * (0.02 + 0.96 * k / 40.0));
    for (int k = 0; k <= 50; ++k)
        across.emplace_back(x0 + w * (0.01 + 0.98 * k / 50.0), y0 + w * (0.3 + 0.01 * (k % 3)));
    add(along);
    add(across);
    add(diagonal);
    add({{x0 + w * 0.25, y0 + w * 0.05}, {x0 + w * 0.27, y0 + w * 0.95}});
    for (int k = 0; k < 10; ++k) {
        const double x = x0 + w * (0.05 + 0.09 * k), y = y0 + w * (0.1 + 0.08 * k);
        add({{x, y}, {x + w * 0.01, y + w * 0.004}, {x + w * 0.02, y - w * 0.003}});
    }
    auto& through = lines.emplace_back();  // through survey points: merged with them
    for (std::size_t i = 0; i < 6; ++i) {
        const dtm::Point3& p = c.points[i * c.points.size() / 6 + 3];
        through.push_back({p.x, p.y, p.z});
    }
    std::string text = "shapeid,x,y,z\n";
    char row[160];
    for (std::size_t i = 0; i < lines.size(); ++i) {
        for (const auto& p : lines[i]) {
            std::snprintf(row, sizeof row, "%zu,%.17g,%.17g,%.17g\n", i + 1, p[0], p[1], p[2]);
            text += row;
        }
    }
    return text;
}

/// A closed ring (shapeid,x,y,z) around (cx, cy): radius r, wobbling, at height z.
std::string ring_csv(double cx, double cy, double r, double z) {
    std::string text = "shapeid,x,y,z\n";
    char row[160];
    for (int k = 0; k <= 36; ++k) {
        const double a = 2.0 * 3.141592653589793 * (k % 36) / 36.0;
        const double rr = r * (1.0 + 0.08 * std::sin(5.0 * (k % 36)));
        std::snprintf(row, sizeof row, "1,%.17g,%.17g,%.17g\n", cx + rr * std::cos(a),
                      cy + rr * std::sin(a), z);
        text += row;
    }
    return text;
}

/// The bytes write_tin_ply writes for the tiled TIN at @p manifest put together.
std::string reassembled_ply(const fs::path& manifest, const fs::path& dir) {
    const dtm::io::LoadedTin tin = dtm::io::read_tin_tiles(manifest);
    dtm::io::write_tin_ply(tin.tin, dir / "reassembled.ply", {.crs_wkt = tin.crs_wkt});
    return dtm::test::read_file(dir / "reassembled.ply");
}

TEST(DistributedTin, BreaklinesBoundaryHolesAndSeedsGiveTheSerialPlyBytesOnAnyRankCount) {
    for (const Case& c : cases()) {
        const dtm::test::ScratchDir dir;
        dtm::test::write_file(dir / "points.csv", points_csv(c));
        dtm::test::write_file(dir / "lines.csv", lines_csv(c));
        // A boundary cut by every seam, a hole straddling the first ones.
        const double mid = c.size / 2.0;
        dtm::test::write_file(dir / "boundary.csv",
                              ring_csv(c.x0 + mid, c.y0 + mid, 0.44 * c.size, 270.0));
        dtm::test::write_file(dir / "hole.csv",
                              ring_csv(c.x0 + mid, c.y0 + 0.55 * c.size, 0.12 * c.size, 265.0));
        // A closed breakline around a pond whose inside a hole seed removes; a second seed in
        // the hole, already removed.
        dtm::test::write_file(dir / "pond.csv", ring_csv(c.x0 + 0.27 * c.size, c.y0 + 0.72 * c.size,
                                                         0.07 * c.size, 268.0));
        char seeds[200];
        std::snprintf(seeds, sizeof seeds, "x,y,z\n%.17g,%.17g,0\n%.17g,%.17g,0\n",
                      c.x0 + 0.27 * c.size, c.y0 + 0.72 * c.size, c.x0 + mid, c.y0 + 0.55 * c.size);
        dtm::test::write_file(dir / "seeds.csv", seeds);
        const std::vector<dtm::io::InputFile> lines{
            {dir / "lines.csv", dtm::io::InputRole::breaklines},
            {dir / "pond.csv", dtm::io::InputRole::breaklines},
            {dir / "boundary.csv", dtm::io::InputRole::boundary},
            {dir / "hole.csv", dtm::io::InputRole::holes},
            {dir / "seeds.csv", dtm::io::InputRole::holes}};
        dtm::io::LoadOptions load;
        load.files = {{dir / "points.csv", dtm::io::InputRole::points}};
        load.files.insert(load.files.end(), lines.begin(), lines.end());
        const dtm::TriangulateResult serial =
            dtm::triangulate(dtm::io::load_inputs(load).terrain, dtm::TriangulateOptions{});
        ASSERT_GT(serial.stats.intersections, 2U) << c.name;
        ASSERT_GT(serial.tin.constraints.size(), 100U) << c.name;
        ASSERT_GT(serial.stats.removed_triangles, serial.tin.triangles.size() / 4) << c.name;
        dtm::io::write_tin_ply(serial.tin, dir / "serial.ply", {});
        const std::string expected = dtm::test::read_file(dir / "serial.ply");
        for (const int ranks : {1, 2, 3, 7, 16, 64}) {
            const unsigned jitter = ranks == 7 ? 200U : 0U;  // random delays before every send
            dtm::products::DistributedTinOptions options;
            options.source.input = {dir / "points.csv", dtm::io::InputRole::points};
            options.source.lines = lines;
            options.output = dir / ("dist-" + std::to_string(ranks) + ".ply");
            dtm::dist::run_in_process(
                ranks,
                [&](dtm::dist::Comm& comm) { dtm::products::distributed_tin(comm, options, {}); },
                {jitter, 3});
            EXPECT_TRUE(dtm::test::read_file(options.output) == expected)
                << c.name << " on " << ranks << " ranks";
            // The tiled TIN put together is the same TIN: the same PLY bytes.
            options.output = dir / ("tiles-" + std::to_string(ranks) + ".json");
            dtm::dist::run_in_process(
                ranks,
                [&](dtm::dist::Comm& comm) { dtm::products::distributed_tin(comm, options, {}); },
                {jitter, 5});
            EXPECT_EQ(reassembled_ply(options.output, dir / ""), expected)
                << c.name << " tiled on " << ranks << " ranks";
        }
    }
}

TEST(DistributedTin, MaxEdgePeelsTheSerialBorderOnAnyRankCount) {
    for (const Case& c : cases()) {
        const dtm::test::ScratchDir dir;
        dtm::test::write_file(dir / "points.csv", points_csv(c));
        dtm::test::write_file(dir / "lines.csv", lines_csv(c));
        const double max_edge = c.size * 0.015;
        dtm::io::LoadOptions load;
        load.files = {{dir / "points.csv", dtm::io::InputRole::points},
                      {dir / "lines.csv", dtm::io::InputRole::breaklines}};
        dtm::TriangulateOptions triangulate;
        triangulate.max_edge = max_edge;
        const dtm::TriangulateResult serial =
            dtm::triangulate(dtm::io::load_inputs(load).terrain, triangulate);
        if (c.name != "lattice") {
            EXPECT_GT(serial.stats.removed_triangles, 20U) << c.name;
        }
        dtm::io::write_tin_ply(serial.tin, dir / "serial.ply", {});
        const std::string expected = dtm::test::read_file(dir / "serial.ply");
        for (const int ranks : {1, 2, 3, 7, 16, 64}) {
            dtm::products::DistributedTinOptions options;
            options.source.input = {dir / "points.csv", dtm::io::InputRole::points};
            options.source.lines = {{dir / "lines.csv", dtm::io::InputRole::breaklines}};
            options.source.max_edge = max_edge;
            options.output = dir / ("dist-" + std::to_string(ranks) + ".ply");
            dtm::dist::run_in_process(ranks, [&](dtm::dist::Comm& comm) {
                dtm::products::distributed_tin(comm, options, {});
            });
            EXPECT_TRUE(dtm::test::read_file(options.output) == expected)
                << c.name << " on " << ranks << " ranks";
        }
    }
}

}  // namespace

namespace {

/// Runs distributed_tin on @p ranks in-process ranks.
dtm::products::DistributedTinResult run_tin(int ranks,
                                            const dtm::products::DistributedTinOptions& o) {
    dtm::products::DistributedTinResult result;
    dtm::dist::run_in_process(ranks, [&](dtm::dist::Comm& comm) {
        auto r = dtm::products::distributed_tin(comm, o, {});
        if (comm.rank() == 0) result = r;
    });
    return result;
}

TEST(DistributedTin, TooBigForOnePlyGivesTheTiledTinWhichReplacesTheOldOneWhole) {
    const Case c = cases()[2];  // S-JTSK magnitudes
    const dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "points.csv", points_csv(c));
    dtm::products::DistributedTinOptions options;
    options.source.input = {dir / "points.csv", dtm::io::InputRole::points};
    options.source.default_crs = "EPSG:5514";
    options.output = dir / "tin.ply";
    const std::string serial = [&] {
        run_tin(1, options);
        return dtm::test::read_file(dir / "tin.ply");
    }();
    fs::remove(dir / "tin.ply");
    // Beyond the PLY's limit (lowered here) the run writes tin.json and its tiles instead.
    options.ply_limit = 1000;
    const auto first = run_tin(4, options);
    EXPECT_EQ(first.written, dir / "tin.json");
    EXPECT_FALSE(fs::exists(dir / "tin.ply"));
    ASSERT_EQ(first.tiles.size(), 4U);
    for (const std::string& t : first.tiles) EXPECT_TRUE(fs::exists(dir / t)) << t;
    EXPECT_EQ(reassembled_ply(dir / "tin.json", dir / ""), serial);
    // A second run on 3 ranks: new tiles, the old ones gone, the same TIN.
    const auto second = run_tin(3, options);
    ASSERT_EQ(second.tiles.size(), 3U);
    for (const std::string& t : first.tiles) EXPECT_FALSE(fs::exists(dir / t)) << t;
    EXPECT_EQ(reassembled_ply(dir / "tin.json", dir / ""), serial);
    // Every subcommand reads the manifest through the reader table.
    dtm::io::LoadOptions load;
    load.files = {{dir / "tin.json", dtm::io::InputRole::points}};
    const dtm::io::LoadedInputs loaded = dtm::io::load_inputs(load);
    ASSERT_TRUE(loaded.tin.has_value());
    EXPECT_EQ(loaded.tin->triangles.size(), second.triangles);
}

TEST(DistributedTin, ABrokenTiledTinNamesWhatIsWrong) {
    const Case c = cases()[0];
    const dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "points.csv", points_csv(c));
    dtm::products::DistributedTinOptions options;
    options.source.input = {dir / "points.csv", dtm::io::InputRole::points};
    options.output = dir / "tin.json";
    const auto r = run_tin(3, options);
    const std::string manifest = dtm::test::read_file(dir / "tin.json");
    const auto message = [&](const std::string& text) {
        dtm::test::write_file(dir / "tin.json", text);
        try {
            (void)dtm::io::read_tin_tiles(dir / "tin.json");
        } catch (const dtm::InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    std::string text = manifest;
    text.replace(text.find("\"vertices\": 4000"), 16, "\"vertices\": 4001");
    EXPECT_NE(message(text).find("vertex 4000 is in no tile"), std::string::npos) << message(text);
    text = manifest;
    text.replace(text.find("dtm-tin-tiles"), 13, "dtm-tin-tilez");
    EXPECT_NE(message(text).find("not a valid tiled TIN manifest"), std::string::npos);
    const fs::path tile = dir / r.tiles[1];
    fs::rename(tile, dir / "moved.ply");
    EXPECT_NE(message(manifest).find(r.tiles[1] + " is missing"), std::string::npos)
        << message(manifest);
    fs::rename(dir / "moved.ply", tile);
    EXPECT_EQ(message(manifest), "no error");
    // A tile alone is a dtm PLY any subcommand reads: a piece of the surface.
    EXPECT_GT(dtm::io::read_tin_ply(tile).tin.triangles.size(), 100U);
}

}  // namespace
