// SPDX-License-Identifier: MIT
// Keeps the regression folder honest: every other file in it is named issue_NNNN_..._test.cpp
// (see README.md). The first regression tests will sit next to this one.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

namespace {

TEST(RegressionFolder, TestsAreNamedAfterTheirIssue) {
    const std::filesystem::path folder = std::filesystem::path(DTM_SOURCE_DIR) / "tests/regression";
    const std::regex name(R"(issue_\d{4}_[a-z0-9_]+_test\.cpp)");
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        const std::string file = entry.path().filename().string();
        if (file == "README.md" || file == "regression_folder_test.cpp") continue;
        EXPECT_TRUE(std::regex_match(file, name)) << file << " (expected issue_NNNN_what_test.cpp)";
    }
}

}  // namespace
