// SPDX-License-Identifier: MIT
// Delimited text reader: layout detection, located errors, polyline lists, reading in blocks and
// parsing in parallel chunks (against the one-block sequential pass), real PDAL variants.
#include "dtm/io/formats/csv.hpp"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "dtm/core/error.hpp"
#include "io/formats/csv/csv_detail.hpp"
#include "support/test_support.hpp"

namespace {

using dtm::io::InputFile;
using dtm::io::InputRole;
using dtm::io::ReadOptions;
using dtm::io::ReadResult;
using dtm::io::csv::Cuts;

ReadResult read(const std::filesystem::path& path,
                InputRole role = InputRole::points,
                ReadOptions options = {}) {
    return dtm::io::read_csv(InputFile{path, role}, options);
}

ReadResult parse(std::string_view text,
                 InputRole role = InputRole::points,
                 ReadOptions options = {}) {
    return dtm::io::parse_csv_text(text, InputFile{"mem.csv", role}, options);
}

std::string error_of(std::string_view text, ReadOptions options = {}) {
    try {
        (void)parse(text, InputRole::points, options);
    } catch (const dtm::InputError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(CsvReader, CzechListWithBomCrlfDecimalCommaAndQuotedCodes) {
    const ReadResult r = read(dtm::test::data_path("readers/czech_list.csv"));
    ASSERT_EQ(r.terrain.points.size(), 4u);
    EXPECT_DOUBLE_EQ(r.terrain.points[0].x, 1045123.12);  // by name: "X" is x, "Y" is y
    EXPECT_DOUBLE_EQ(r.terrain.points[0].y, 745123.45);
    EXPECT_DOUBLE_EQ(r.terrain.points[0].z, 312.45);
    ASSERT_EQ(r.labels.ids.size(), 4u);
    EXPECT_EQ(r.labels.ids[1], "4002");
    EXPECT_EQ(r.labels.codes[1], "plot; dreveny");
    EXPECT_EQ(r.labels.codes[2], "");
    EXPECT_EQ(r.summary.skipped_lines, 0u);
}

TEST(CsvReader, HeaderlessListWithIntegerFirstColumnIsIdXYZ) {
    const ReadResult r = read(dtm::test::data_path("readers/czech_list_noheader.txt"));
    ASSERT_EQ(r.terrain.points.size(), 4u);
    EXPECT_DOUBLE_EQ(r.terrain.points[3].x, 745118.75);
    EXPECT_DOUBLE_EQ(r.terrain.points[3].y, 1045112.25);
    EXPECT_DOUBLE_EQ(r.terrain.points[3].z, 312.20);
    EXPECT_EQ(r.labels.ids[3], "4004");
}

TEST(CsvReader, TabDelimiterWithDecimalComma) {
    const ReadResult r = read(dtm::test::data_path("readers/tab_decimal_comma.txt"));
    ASSERT_EQ(r.terrain.points.size(), 3u);
    EXPECT_DOUBLE_EQ(r.terrain.points[0].x, 100.5);
    EXPECT_DOUBLE_EQ(r.terrain.points[0].y, 200.25);
    EXPECT_DOUBLE_EQ(r.terrain.points[2].z, 12.0);
}

TEST(CsvReader, QuotedHeaderNamesExtraColumnsAndCodes) {
    const ReadResult r = read(dtm::test::data_path("readers/quoted_extra.csv"));
    ASSERT_EQ(r.terrain.points.size(), 3u);
    EXPECT_DOUBLE_EQ(r.terrain.points[1].x, 501.1);
    EXPECT_DOUBLE_EQ(r.terrain.points[1].y, 601.2);
    EXPECT_DOUBLE_EQ(r.terrain.points[1].z, 10.6);
    EXPECT_EQ(r.labels.codes[0], "TREE");
    EXPECT_EQ(r.labels.ids[2], "3");
}

TEST(CsvReader, PointCountFirstLineAndBlankRuns) {
    const ReadResult r = read(dtm::test::data_path("readers/count_line.xyz"));
    ASSERT_EQ(r.terrain.points.size(), 3u);
    EXPECT_EQ(r.terrain.points[2], (dtm::Point3{7.0, 8.0, 9.0}));
    EXPECT_TRUE(r.summary.warnings.empty());
}

TEST(CsvReader, PointCountMismatchIsAWarning) {
    const ReadResult r = parse("5\n1 2 3\n4 5 6\n");
    EXPECT_EQ(r.terrain.points.size(), 2u);
    ASSERT_EQ(r.summary.warnings.size(), 1u);
    EXPECT_NE(r.summary.warnings[0].find("declares 5"), std::string::npos);
}

TEST(CsvReader, ColumnsOptionOverridesTheOrder) {
    ReadOptions options;
    options.columns = "id,y,x,z,code";
    const ReadResult r = parse("A;1,5;2,5;3,5;k\nB;4;5;6;\n", InputRole::points, options);
    ASSERT_EQ(r.terrain.points.size(), 2u);
    EXPECT_EQ(r.terrain.points[0], (dtm::Point3{2.5, 1.5, 3.5}));
    EXPECT_EQ(r.labels.ids[0], "A");
    EXPECT_EQ(r.labels.codes[0], "k");
}

TEST(CsvReader, CommentsSignsExponentsAndSemicolonHeader) {
    const ReadResult r = parse("// exported\n# another comment\nE;N;Elev\n+1e2;-2.5E1;.5\n");
    ASSERT_EQ(r.terrain.points.size(), 1u);
    EXPECT_EQ(r.terrain.points[0], (dtm::Point3{100.0, -25.0, 0.5}));
}

TEST(CsvReader, BadNumberNamesFileLineColumnAndText) {
    const std::string what = error_of("x,y,z\n1,2,3\n4,5,oops\n");
    EXPECT_NE(what.find("mem.csv:3:5:"), std::string::npos) << what;
    EXPECT_NE(what.find("'oops'"), std::string::npos) << what;
    EXPECT_NE(what.find("expected a number"), std::string::npos) << what;
}

TEST(CsvReader, ShortLineIsAnErrorNamingTheLine) {
    const std::string what = error_of("x y z\n1 2 3\n4 5\n");
    EXPECT_NE(what.find("mem.csv:3:"), std::string::npos) << what;
    EXPECT_NE(what.find("expected at least 3 fields, found 2"), std::string::npos) << what;
}

TEST(CsvReader, InfinityAndNanAreNotNumbers) {
    EXPECT_NE(error_of("1 2 inf\n").find("'inf'"), std::string::npos);
    EXPECT_NE(error_of("1 2 nan\n").find("'nan'"), std::string::npos);
}

TEST(CsvReader, SkipBadLinesCountsThemAndKeepsTheRest) {
    ReadOptions options;
    options.skip_bad_lines = true;
    const ReadResult r =
        read(dtm::test::data_path("readers/malformed.csv"), InputRole::points, options);
    EXPECT_EQ(r.terrain.points.size(), 4u);
    EXPECT_EQ(r.summary.skipped_lines, 2u);
    ASSERT_EQ(r.summary.warnings.size(), 2u);
    EXPECT_NE(r.summary.warnings[0].find("line 4:"), std::string::npos);
    EXPECT_NE(r.summary.warnings[1].find("line 6:"), std::string::npos);
}

TEST(CsvReader, MalformedFileFailsAtTheFirstBadLine) {
    try {
        (void)read(dtm::test::data_path("readers/malformed.csv"));
        FAIL() << "expected an InputError";
    } catch (const dtm::InputError& e) {
        EXPECT_EQ(e.line(), 4u);
        EXPECT_EQ(e.column(), 11u);
        EXPECT_NE(std::string(e.what()).find("'abc'"), std::string::npos);
    }
}

TEST(CsvReader, UnterminatedQuoteIsLocated) {
    try {
        (void)read(dtm::test::data_path("readers/unclosed_quote.csv"));
        FAIL() << "expected an InputError";
    } catch (const dtm::InputError& e) {
        EXPECT_EQ(e.line(), 3u);
        EXPECT_NE(std::string(e.what()).find("closing quote"), std::string::npos);
    }
}

TEST(CsvReader, PointsWithoutZColumnAreRejected) {
    EXPECT_NE(error_of("x,y\n1,2\n").find("expected a z column"), std::string::npos);
}

TEST(CsvReader, UnknownColumnsWordIsRejected) {
    ReadOptions options;
    options.columns = "x,y,depth";
    EXPECT_NE(error_of("1 2 3\n", options).find("'depth'"), std::string::npos);
}

TEST(CsvReader, EmptyFileIsAnError) {
    EXPECT_NE(error_of("\n# only a comment\n").find("empty file"), std::string::npos);
}

/// A point list of about 12 MB (more than the parallel reader's chunk threshold): "id;Y;X;Z;code"
/// rows with comments, blank lines and CRLF ends, and bad rows at the given line numbers.
std::string large_point_list(const std::vector<std::size_t>& bad_lines) {
    std::string text = "id;x;y;z;code\r\n";
    std::size_t line = 1;
    for (std::size_t i = 0; text.size() < (std::size_t{12} << 20); ++i) {
        ++line;
        if (std::find(bad_lines.begin(), bad_lines.end(), line) != bad_lines.end()) {
            text += "P" + std::to_string(i) + ";-750000.5;oops;301.25;X\r\n";
        } else if (i % 997 == 0) {
            text += "# comment\r\n";
        } else if (i % 991 == 0) {
            text += "\r\n";
        } else {
            text += "P" + std::to_string(i) + ";" +
                    std::to_string(-750000.0 - 0.001 * static_cast<double>(i)) + ";" +
                    std::to_string(-1050000.0 + 0.002 * static_cast<double>(i)) + ";" +
                    std::to_string(300 + i % 7) + ";C" + std::to_string(i % 5) + "\r\n";
        }
    }
    return text;
}

/// Cuts small enough for the 12 MB list to span about 50 blocks of 16 chunks each.
constexpr Cuts small_cuts{std::size_t{256} << 10, std::size_t{16} << 10};

ReadResult parse_with_threads(std::string_view text,
                              int threads,
                              ReadOptions options,
                              Cuts cuts = {},
                              InputRole role = InputRole::points) {
    tbb::task_arena arena(threads);
    return arena.execute([&] {
        return dtm::io::csv::parse_csv_text(text, InputFile{"mem.csv", role}, options, {}, cuts);
    });
}

std::string error_with_threads(std::string_view text, int threads, Cuts cuts) {
    try {
        (void)parse_with_threads(text, threads, {}, cuts);
    } catch (const dtm::InputError& e) {
        return e.what();
    }
    return "(no error)";
}

bool same_points(const std::vector<dtm::Point3>& a, const std::vector<dtm::Point3>& b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(dtm::Point3)) == 0);
}

void expect_same_lines(const std::vector<dtm::Polyline>& a, const std::vector<dtm::Polyline>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_TRUE(same_points(a[i].points, b[i].points)) << "line " << i;
        EXPECT_EQ(a[i].closed, b[i].closed) << "line " << i;
        EXPECT_EQ(a[i].source, b[i].source) << "line " << i;
    }
}

/// Everything a read gives: the points bit for bit, labels, lines, seeds, counts and warnings.
void expect_same(const ReadResult& a, const ReadResult& b) {
    EXPECT_TRUE(same_points(a.terrain.points, b.terrain.points));
    EXPECT_EQ(a.labels.ids, b.labels.ids);
    EXPECT_EQ(a.labels.codes, b.labels.codes);
    expect_same_lines(a.terrain.breaklines, b.terrain.breaklines);
    expect_same_lines(a.terrain.soft_breaklines, b.terrain.soft_breaklines);
    expect_same_lines(a.terrain.boundaries, b.terrain.boundaries);
    expect_same_lines(a.terrain.holes, b.terrain.holes);
    EXPECT_EQ(a.terrain.hole_seeds, b.terrain.hole_seeds);
    EXPECT_EQ(a.summary.skipped_lines, b.summary.skipped_lines);
    EXPECT_EQ(a.summary.warnings, b.summary.warnings);
    EXPECT_EQ(a.crs_wkt, b.crs_wkt);
}

TEST(CsvReader, LargeFileParsedInParallelEqualsTheSequentialPass) {
    ReadOptions skip;
    skip.skip_bad_lines = true;
    const std::string text = large_point_list({5, 90001, 180002, 250003});
    const ReadResult one = parse_with_threads(text, 1, skip);
    ASSERT_GT(one.terrain.points.size(), 200000u);
    EXPECT_EQ(one.summary.skipped_lines, 4u);
    ASSERT_EQ(one.summary.warnings.size(), 4u);
    EXPECT_NE(one.summary.warnings[3].find("skipped line 250003:"), std::string::npos)
        << one.summary.warnings[3];
    // One block in chunks; many blocks read one after the other; many blocks in chunks.
    for (const auto& [threads, cuts] :
         {std::pair{2, Cuts{}}, std::pair{1, small_cuts}, std::pair{2, small_cuts}}) {
        SCOPED_TRACE(std::to_string(threads) + " threads, blocks of " +
                     std::to_string(cuts.block_bytes));
        expect_same(one, parse_with_threads(text, threads, skip, cuts));
    }
}

TEST(CsvReader, LargeFileReadInBlocksKeepsTheFirstTwentyWarningsInFileOrder) {
    ReadOptions skip;
    skip.skip_bad_lines = true;
    std::vector<std::size_t> bad;
    for (std::size_t line = 7; line < 250000; line += 8000) bad.push_back(line);
    const std::string text = large_point_list(bad);
    const ReadResult one = parse_with_threads(text, 1, skip);
    EXPECT_EQ(one.summary.skipped_lines, bad.size());
    ASSERT_EQ(one.summary.warnings.size(), 20u);
    EXPECT_NE(one.summary.warnings[19].find("skipped line 152007:"), std::string::npos)
        << one.summary.warnings[19];
    expect_same(one, parse_with_threads(text, 2, skip, small_cuts));
}

TEST(CsvReader, LargeFileParsedInParallelReportsTheFirstBadLine) {
    // Bad rows in a late chunk and an early one, then in two chunks of one small block: the
    // error names the earlier line.
    for (const auto& [bad, first] : {std::pair{std::vector<std::size_t>{240001, 120007}, 120007},
                                     std::pair{std::vector<std::size_t>{120900, 120007}, 120007}}) {
        const std::string text = large_point_list(bad);
        const std::string expected = "mem.csv:" + std::to_string(first) + ":";
        for (const int threads : {1, 2}) {
            for (const Cuts& cuts : {Cuts{}, small_cuts}) {
                const std::string what = error_with_threads(text, threads, cuts);
                EXPECT_NE(what.find(expected), std::string::npos)
                    << threads << " threads, blocks of " << cuts.block_bytes << ": " << what;
            }
        }
    }
}

TEST(CsvReader, ProgressOfABlockwiseReadReachesTheEnd) {
    const std::string text = large_point_list({});
    double last = 0.0;
    bool in_range = true;
    const dtm::Progress progress([&](double fraction, std::string_view) {
        in_range = in_range && fraction >= 0.0 && fraction <= 1.0;
        last = std::max(last, fraction);
        return true;
    });
    tbb::task_arena arena(2);
    arena.execute([&] {
        (void)dtm::io::csv::parse_csv_text(text, InputFile{"mem.csv", InputRole::points}, {},
                                           progress, small_cuts);
    });
    EXPECT_TRUE(in_range);
    EXPECT_GT(last, 0.9);
}

/// A small headerless-or-not list with what a cut could break: a BOM, a comment, CRLF ends,
/// blank and comment lines, a row and a comment far longer than the small blocks, a bad row, and
/// no line end at the end. @p head comes first (after the BOM if @p bom).
std::string tricky_list(const std::string& head, bool bom) {
    std::string text = (bom ? "\xEF\xBB\xBF" : "") + head;
    for (int i = 0; i < 60; ++i) {
        const std::string id = std::to_string(100 + i);
        if (i == 25) {
            text += id + " 1.5 2.5 oops C\r\n";
        } else if (i % 11 == 3) {
            text += "\r\n";
        } else if (i % 13 == 5) {
            text += i == 31 ? "# " + std::string(5000, 'n') + "\r\n" : "// note\r\n";
        } else {
            text += id + " " + std::to_string(i) + ".25 " + std::to_string(2 * i) + ".5 " +
                    std::to_string(300 + i) + " " + (i == 40 ? std::string(3000, 'c') : "C") +
                    "\r\n";
        }
    }
    return text + "199 9.25 8.5 7 last";
}

TEST(CsvReader, BlocksAndChunksCutAnywhereGiveTheOnePassResult) {
    ReadOptions skip;
    skip.skip_bad_lines = true;
    // A header; no header after a BOM (data from byte 3); a point-count line.
    for (const std::string& text : {tricky_list("# survey\r\nid x y z code\r\n", true),
                                    tricky_list("", true), tricky_list("61\n", false)}) {
        const ReadResult one = parse_with_threads(text, 1, skip);
        ASSERT_EQ(one.terrain.points.size(), 50u);
        ASSERT_EQ(one.summary.skipped_lines, 1u);
        ASSERT_EQ(one.labels.codes.back(), "last");
        const std::string error = error_with_threads(text, 1, {});
        ASSERT_NE(error.find("expected a number for"), std::string::npos) << error;
        for (const std::size_t block : {1, 2, 5, 16, 100, 1000, 4000}) {
            for (const std::size_t chunk : {1, 7, 64}) {
                for (const int threads : {1, 2}) {
                    SCOPED_TRACE("blocks of " + std::to_string(block) + ", chunks of " +
                                 std::to_string(chunk) + ", " + std::to_string(threads) +
                                 " threads");
                    expect_same(one, parse_with_threads(text, threads, skip, Cuts{block, chunk}));
                    EXPECT_EQ(error, error_with_threads(text, threads, Cuts{block, chunk}));
                }
            }
        }
    }
}

TEST(CsvReader, PolylinesAndSeedsReadInBlocksGiveTheOnePassResult) {
    const std::string by_id =
        "shapeid,x,y,z\n1,0,0,1\n1,5,0,2\n1,5,5,3\n1,0,0,1\n\n2,7,7,1\n"
        "2,8,9,2\n# comment\n3,1,1,1\n3,2,2,2\n3,3,1,3\n4,9,9,9\n";
    const std::string by_blank =
        "0 0 1\n10 0 1\n10 10 1\n\n20 20 2\n30 20 2\n30 30 2\n\n\n"
        "40 40 4\n50 40 4\n";
    const std::string seeds = "10.5,20.5\n30,40\n\n50,60\n";
    for (const auto& [text, role] :
         {std::pair{by_id, InputRole::breaklines}, std::pair{by_id, InputRole::boundary},
          std::pair{by_blank, InputRole::boundary}, std::pair{by_blank, InputRole::soft_breaklines},
          std::pair{seeds, InputRole::holes}}) {
        const ReadResult one = parse_with_threads(text, 1, {}, {}, role);
        for (const std::size_t block : {1, 3, 17, 64}) {
            SCOPED_TRACE("blocks of " + std::to_string(block));
            expect_same(one, parse_with_threads(text, 2, {}, Cuts{block, 1}, role));
        }
    }
}

TEST(CsvReader, FileReadInBlocksEqualsTheTextInMemory) {
    const std::string text = tricky_list("# survey\r\nid x y z code\r\n", true);
    dtm::test::ScratchDir dir;
    dtm::test::write_file(dir / "tricky.xyz", text);
    ReadOptions skip;
    skip.skip_bad_lines = true;
    const InputFile file{dir / "tricky.xyz", InputRole::points};
    const ReadResult whole = dtm::io::read_csv(file, skip);
    const ReadResult in_memory = parse(text, InputRole::points, skip);
    EXPECT_EQ(whole.terrain.points.size(), 50u);
    EXPECT_TRUE(same_points(whole.terrain.points, in_memory.terrain.points));
    EXPECT_EQ(whole.labels.ids, in_memory.labels.ids);
    for (const std::size_t block : {1, 64, 1000}) {
        SCOPED_TRACE("blocks of " + std::to_string(block));
        expect_same(whole, dtm::io::csv::read_csv(file, skip, {}, Cuts{block, 64}));
    }
}

/// Reads @p text, at most @p most bytes a call.
dtm::io::csv::Blocks::Fill fill_from(const std::string& text, std::size_t most) {
    return [&text, most, at = std::size_t{0}](char* to, std::size_t bytes) mutable {
        const std::size_t n = std::min({bytes, most, text.size() - at});
        std::copy_n(text.data() + at, n, to);
        at += n;
        return n;
    };
}

/// The input in blocks of @p block bytes, read @p most bytes at a time.
std::vector<std::string> blocks_of(const std::string& text, std::size_t block, std::size_t most) {
    dtm::io::csv::Blocks blocks(fill_from(text, most), block, 0);
    std::vector<std::string> out;
    std::size_t offset = 0;
    for (std::string_view b = blocks.next(); !b.empty(); b = blocks.next()) {
        EXPECT_EQ(blocks.offset(), offset);
        EXPECT_TRUE(blocks.at_end() || b.back() == '\n') << "a block cut inside a line";
        offset += b.size();
        out.emplace_back(b);
    }
    EXPECT_TRUE(blocks.at_end());
    return out;
}

TEST(CsvBlocks, BlocksEndAtLineEndsGrowForLongLinesAndAddUpToTheInput) {
    const std::string text = "a\nbb\n" + std::string(50, 'x') + "\n\nccc\r\nd";
    for (std::size_t block = 1; block <= 12; ++block) {
        for (const std::size_t most : {std::size_t{1}, std::size_t{3}, text.size()}) {
            const std::vector<std::string> blocks = blocks_of(text, block, most);
            std::string joined;
            for (const std::string& b : blocks) joined += b;
            EXPECT_EQ(joined, text) << "blocks of " << block << ", reads of " << most;
            const std::string long_line = "\n" + std::string(50, 'x') + "\n";
            EXPECT_TRUE(std::any_of(blocks.begin(), blocks.end(), [&](const std::string& b) {
                return ("\n" + b).find(long_line) != std::string::npos;
            })) << "the long line split";
        }
    }
    EXPECT_EQ(blocks_of("", 4, 4).size(), 0u);
    EXPECT_EQ(blocks_of("no line end", 4, 4), std::vector<std::string>{"no line end"});
}

TEST(CsvBlocks, ExtendAddsTheFollowingLines) {
    const std::string text = "1\n22\n333\n4444\n";
    dtm::io::csv::Blocks blocks(fill_from(text, text.size()), 4, text.size());
    EXPECT_EQ(blocks.next(), "1\n");
    EXPECT_EQ(blocks.extend(), "1\n22\n");
    EXPECT_EQ(blocks.extend(), "1\n22\n333\n");
    EXPECT_FALSE(blocks.at_end());
    EXPECT_EQ(blocks.extend(), text);
    EXPECT_TRUE(blocks.at_end());
    EXPECT_EQ(blocks.extend(), text);
    EXPECT_TRUE(blocks.next().empty());
}

TEST(CsvReader, PolylinesGroupedByShapeIdClosingRepeatedFirstVertex) {
    const ReadResult r = read(dtm::test::data_path("readers/polylines.csv"), InputRole::breaklines);
    ASSERT_EQ(r.terrain.breaklines.size(), 2u);
    EXPECT_EQ(r.terrain.breaklines[0].points.size(), 3u);
    EXPECT_FALSE(r.terrain.breaklines[0].closed);
    EXPECT_EQ(r.terrain.breaklines[1].points.size(), 3u);
    EXPECT_TRUE(r.terrain.breaklines[1].closed);
    EXPECT_NE(r.terrain.breaklines[0].source.find("polylines.csv:2"), std::string::npos);
    ASSERT_EQ(r.summary.warnings.size(), 1u);  // shape 3 has one vertex
    EXPECT_NE(r.summary.warnings[0].find("too short"), std::string::npos);
}

TEST(CsvReader, SoftBreaklinesWithoutZCarryNaN) {
    const ReadResult r = parse("1,0.5,0\n1,5,5.5\n2,1.5,1\n2,2,3\n", InputRole::soft_breaklines);
    ASSERT_EQ(r.terrain.soft_breaklines.size(), 2u);
    EXPECT_TRUE(std::isnan(r.terrain.soft_breaklines[0].points[0].z));
}

TEST(CsvReader, HolesWithoutLineIdAreSeeds) {
    const ReadResult r = parse("10.5,20.5\n30,40\n", InputRole::holes);
    ASSERT_EQ(r.terrain.hole_seeds.size(), 2u);
    EXPECT_EQ(r.terrain.hole_seeds[1], (dtm::Point2{30.0, 40.0}));
    EXPECT_TRUE(r.terrain.holes.empty());
}

TEST(CsvReader, BoundaryWithoutLineIdIsOneClosedRingPerBlankSeparatedBlock) {
    const ReadResult r =
        parse("0 0 1\n10 0 1\n10 10 1\n\n20 20 2\n30 20 2\n30 30 2\n", InputRole::boundary);
    ASSERT_EQ(r.terrain.boundaries.size(), 2u);
    EXPECT_TRUE(r.terrain.boundaries[0].closed);
    EXPECT_EQ(r.terrain.boundaries[1].points.size(), 3u);
}

TEST(CsvReader, LatLonColumnsReportWgs84) {
    const ReadResult r = read(dtm::test::data_path("readers/gnss_latlon.csv"));
    ASSERT_EQ(r.terrain.points.size(), 3u);
    EXPECT_DOUBLE_EQ(r.terrain.points[0].x, 14.4214);  // x = longitude
    EXPECT_DOUBLE_EQ(r.terrain.points[0].y, 50.0875);
    EXPECT_EQ(r.crs_wkt, "EPSG:4326");
    EXPECT_EQ(r.labels.ids[1], "B");
}

TEST(CsvReader, GeometryColumnIsDetected) {
    EXPECT_TRUE(dtm::io::csv_has_geometry_column("id,WKT\n1,\"POINT (1 2)\"\n"));
    EXPECT_FALSE(dtm::io::csv_has_geometry_column("id,x,y,z\n1,2,3,4\n"));
}

// Every PDAL text variant either parses to the right counts or fails with a located error.
struct Variant {
    const char* file;
    std::size_t points;  ///< 0: must fail with a located InputError
};

class PdalTextVariants : public ::testing::TestWithParam<Variant> {};

TEST_P(PdalTextVariants, ParsesToTheRightCountOrFailsLocated) {
    const std::string rel = std::string("points-pdal-text-variants/") + GetParam().file;
    if (!dtm::test::shared_data_available(rel)) GTEST_SKIP() << "shared data absent: " << rel;
    const auto path = dtm::test::shared_data_path(rel);
    if (GetParam().points == 0) {
        try {
            (void)read(path);
            FAIL() << "expected an InputError";
        } catch (const dtm::InputError& e) {
            EXPECT_EQ(e.file(), path);
            EXPECT_GT(e.line(), 0u);
        }
        return;
    }
    const ReadResult r = read(path);
    EXPECT_EQ(r.terrain.points.size(), GetParam().points);
    for (const auto& p : r.terrain.points) EXPECT_TRUE(std::isfinite(p.z));
}

INSTANTIATE_TEST_SUITE_P(Files,
                         PdalTextVariants,
                         ::testing::Values(Variant{"autzen-bmx-largersample.txt", 103},
                                           Variant{"autzen-point-format-3.txt", 106},
                                           Variant{"autzen.pts", 10},
                                           Variant{"badheader.txt", 0},
                                           Variant{"crlf_test.txt", 10},
                                           Variant{"data.xyz", 400},
                                           Variant{"decimate_file_grid.txt", 81},
                                           Variant{"missingheader.txt", 5},
                                           Variant{"quoted.txt", 9},
                                           Variant{"utm17_1.txt", 10},
                                           Variant{"utm17_2.txt", 10},
                                           Variant{"utm17_3.txt", 11}));

TEST(CsvReaderRealData, AutzenPointFormat3MapsXYZAmongColourColumns) {
    const std::string rel = "points-pdal-text-variants/autzen-point-format-3.txt";
    if (!dtm::test::shared_data_available(rel)) GTEST_SKIP();
    const ReadResult r = read(dtm::test::shared_data_path(rel));
    ASSERT_FALSE(r.terrain.points.empty());
    EXPECT_EQ(r.terrain.points[0], (dtm::Point3{636083.30, 849398.65, 407.35}));
}

TEST(CsvReaderRealData, HurdvillePolylineAndSeedFiles) {
    const std::string dir = "points-breaklines-pputils-hurdville/";
    if (!dtm::test::shared_data_available(dir + "lines.csv")) GTEST_SKIP();
    const auto p = [&](const char* f) { return dtm::test::shared_data_path(dir + f); };
    const ReadResult lines = read(p("lines.csv"), InputRole::soft_breaklines);
    EXPECT_EQ(lines.terrain.soft_breaklines.size(), 156u);
    std::size_t vertices = 0;
    for (const auto& l : lines.terrain.soft_breaklines) vertices += l.points.size() + l.closed;
    EXPECT_EQ(vertices, 3805u);
    const ReadResult lines3d = read(p("lines3d.csv"), InputRole::breaklines);
    EXPECT_EQ(lines3d.terrain.breaklines.size(), 157u);
    const ReadResult boundary = read(p("boundary.csv"), InputRole::boundary);
    ASSERT_EQ(boundary.terrain.boundaries.size(), 1u);
    EXPECT_TRUE(boundary.terrain.boundaries[0].closed);
    EXPECT_EQ(boundary.terrain.boundaries[0].points.size(), 1416u);  // 1417 rows, last repeats
    const ReadResult holes = read(p("holes.csv"), InputRole::holes);
    EXPECT_EQ(holes.terrain.hole_seeds.size(), 16u);
    const ReadResult nodes = read(p("nodes.csv"));
    EXPECT_EQ(nodes.terrain.points.size(), 5552u);
}

}  // namespace
