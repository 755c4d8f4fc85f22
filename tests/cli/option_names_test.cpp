// SPDX-License-Identifier: MIT
// The library names options as `field`; tools/dtm shows its flags instead. Every `field` in the
// library's string literals must have a flag, or users would see the library's spelling.
#include "option_names.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "support/test_support.hpp"

namespace {

TEST(OptionNames, FieldsInBackquotesBecomeFlags) {
    EXPECT_EQ(dtm::cli::cli_text("`z_field`: expected a field named 'h'"),
              "--z-field: expected a field named 'h'");
    EXPECT_EQ(dtm::cli::cli_text("see `hpgl.pens`; no `default_crs` given"),
              "see --hpgl-pens; no --crs given");
    EXPECT_EQ(dtm::cli::cli_text("build: `out_dir` out is a file"), "build: -o out is a file");
}

TEST(OptionNames, OtherTextAndUnknownNamesAreKept) {
    EXPECT_EQ(dtm::cli::cli_text("expected `ND id x y z`"), "expected `ND id x y z`");
    EXPECT_EQ(dtm::cli::cli_text("`nope` and `z_field`"), "`nope` and --z-field");
    EXPECT_EQ(dtm::cli::cli_text("one ` quote"), "one ` quote");
    EXPECT_EQ(dtm::cli::cli_text(""), "");
    EXPECT_EQ(dtm::cli::flag_of("nope"), "");
}

TEST(OptionNames, EveryFieldTheLibraryNamesHasAFlag) {
    const std::filesystem::path root = std::filesystem::path(DTM_SOURCE_DIR) / "libdtm";
    // every string literal on lines of code (comments may speak of `field`), and in it every
    // `name` or `name.name`
    const std::regex literal(R"re("((?:[^"\\]|\\.)*)")re");
    const std::regex field(R"re(`([a-z_]+(\.[a-z_]+)?)`)re");
    std::set<std::string> missing;
    std::size_t seen = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
        const std::string ext = entry.path().extension().string();
        if (ext != ".cpp" && ext != ".hpp") continue;
        std::istringstream lines(dtm::test::read_file(entry.path()));
        std::string line;
        while (std::getline(lines, line)) {
            const std::size_t code = line.find_first_not_of(" \t");
            if (code == std::string::npos || line.compare(code, 2, "//") == 0) continue;
            for (std::sregex_iterator s(line.begin(), line.end(), literal), end; s != end; ++s) {
                const std::string text = (*s)[1].str();
                for (std::sregex_iterator f(text.begin(), text.end(), field); f != end; ++f) {
                    ++seen;
                    if (dtm::cli::flag_of((*f)[1].str()).empty()) missing.insert((*f)[1].str());
                }
            }
        }
    }
    EXPECT_GT(seen, 0U);
    for (const std::string& name : missing) ADD_FAILURE() << "no flag for `" << name << "`";
}

}  // namespace
