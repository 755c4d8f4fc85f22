// SPDX-License-Identifier: MIT
// The spellings of --hpgl-pens and --hpgl-height-pens (tools/dtm/hpgl_args.cpp).
#include "hpgl_args.hpp"

#include <gtest/gtest.h>

#include <string>

#include "dtm/core/error.hpp"

namespace {

using dtm::io::PenRole;

TEST(HpglArgs, PenRolesAndListsParseAndRejectNonsense) {
    const auto roles = dtm::cli::parse_pen_roles(
        "2=breakline, 3=boundary,4=hole,1=ignore,5=soft-breakline,6=points,7=soft");
    EXPECT_EQ(roles.size(), 7u);
    EXPECT_EQ(roles.at(2), PenRole::breakline);
    EXPECT_EQ(roles.at(5), PenRole::soft_breakline);
    EXPECT_EQ(roles.at(6), PenRole::points);
    EXPECT_EQ(roles.at(7), PenRole::soft_breakline);
    EXPECT_THROW((void)dtm::cli::parse_pen_roles("2=ridge"), dtm::UsageError);
    EXPECT_THROW((void)dtm::cli::parse_pen_roles("two=breakline"), dtm::UsageError);
    EXPECT_THROW((void)dtm::cli::parse_pen_roles("2"), dtm::UsageError);
    EXPECT_EQ(dtm::cli::parse_pen_list("5, 6"), (std::vector<int>{5, 6}));
    EXPECT_THROW((void)dtm::cli::parse_pen_list("5;6"), dtm::UsageError);
}

TEST(HpglArgs, MessagesNameTheFlagAndTheItem) {
    try {
        (void)dtm::cli::parse_pen_roles("2=breakline,3=ridge");
        FAIL() << "no exception";
    } catch (const dtm::UsageError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("--hpgl-pens: unknown role 'ridge'", 0), 0u)
            << e.what();
    }
}

}  // namespace
