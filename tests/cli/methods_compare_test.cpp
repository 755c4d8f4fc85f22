// SPDX-License-Identifier: MIT
// `dtm methods compare` from the command line: a tiny run writes its report, CSV, JSON and
// plots; bad lists are usage errors (exit 2).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/test_support.hpp"

using dtm::test::run_dtm;
using dtm::test::RunResult;
using dtm::test::ScratchDir;

TEST(MethodsCompare, TinyRunWritesEverything) {
    const ScratchDir dir;
    const RunResult r =
        run_dtm({"methods", "compare", "--methods", "dc,voronoi-topological", "--n", "200,400",
                 "--dist", "uniform,gauss", "--repeat", "2", "-o", "lab", "-q"},
                dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("8 cells measured"), std::string::npos) << r.out;
    for (const char* f :
         {"results.csv", "results.json", "report.md", "plots/scaling_uniform.png",
          "plots/scaling_gauss.svg", "plots/angles_gauss_400_voronoi-topological.png"}) {
        EXPECT_TRUE(std::filesystem::exists(dir / "lab" / f)) << f;
    }
}

TEST(MethodsCompare, BadListsAreUsageErrors) {
    const ScratchDir dir;
    EXPECT_EQ(
        run_dtm({"methods", "compare", "--dist", "square", "-o", "x", "-q"}, dir.path()).exit_code,
        2);
    EXPECT_EQ(run_dtm({"methods", "compare", "--methods", "nope", "--n", "10", "-o", "x", "-q"},
                      dir.path())
                  .exit_code,
              2);
    EXPECT_EQ(run_dtm({"methods", "compare", "--n", "ten", "-o", "x", "-q"}, dir.path()).exit_code,
              2);
    EXPECT_FALSE(std::filesystem::exists(dir / "x" / "report.md"));
}
