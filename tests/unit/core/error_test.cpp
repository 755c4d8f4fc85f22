// SPDX-License-Identifier: MIT
#include "dtm/core/error.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

TEST(InputError, MessageNamesFileLineAndColumnWhereGiven) {
    EXPECT_STREQ(dtm::InputError("a.csv", 3, 7, "expected a number").what(),
                 "a.csv:3:7: expected a number");
    EXPECT_STREQ(dtm::InputError("a.csv", 3, 0, "x").what(), "a.csv:3: x");
    EXPECT_STREQ(dtm::InputError("a.csv", 0, 0, "x").what(), "a.csv: x");
    EXPECT_STREQ(dtm::InputError("no file").what(), "no file");
    const dtm::InputError e("b.txt", 2, 1, "y");
    EXPECT_EQ(e.file(), "b.txt");
    EXPECT_EQ(e.line(), 2U);
    EXPECT_EQ(e.column(), 1U);
}

TEST(OptionError, IsAUsageErrorCarryingTheFieldName) {
    try {
        throw dtm::OptionError("z_field", "`z_field`: expected a field named 'h'");
    } catch (const dtm::UsageError& e) {
        const auto* option = dynamic_cast<const dtm::OptionError*>(&e);
        ASSERT_NE(option, nullptr);
        EXPECT_EQ(option->field(), "z_field");
        EXPECT_STREQ(e.what(), "`z_field`: expected a field named 'h'");
    }
}

}  // namespace
