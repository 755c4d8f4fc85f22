// SPDX-License-Identifier: MIT
// JsonWriter: block and inline layouts, mixed; empty containers; escapes; numbers.
#include "dtm/io/json_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace {

using dtm::io::JsonWriter;
using Layout = JsonWriter::Layout;

TEST(JsonWriter, BlocksIndentTwoSpacesPerLevel) {
    JsonWriter json;
    json.begin_object();
    json.value("a", std::size_t{1});
    json.begin_object("b");
    json.value("c", "x");
    json.end();
    json.begin_array("empty");
    json.end();
    json.end();
    EXPECT_EQ(json.str(),
              "{\n  \"a\": 1,\n  \"b\": {\n    \"c\": \"x\"\n  },\n  \"empty\": []\n}\n");
}

TEST(JsonWriter, InlineContainersStayOnOneLineInsideBlocks) {
    JsonWriter json;
    json.begin_object({}, Layout::inline_);
    json.begin_array("inputs");
    for (int i = 0; i < 2; ++i) {
        json.begin_object({}, Layout::inline_);
        json.value("n", static_cast<std::size_t>(i));
        json.begin_array("xy", Layout::inline_);
        json.value({}, 1.5);
        json.value({}, -2.0);
        json.end();
        json.null("crs");
        json.end();
    }
    json.end();
    json.end();
    EXPECT_EQ(json.str(),
              "{\"inputs\": [\n  {\"n\": 0, \"xy\": [1.5, -2], \"crs\": null},\n"
              "  {\"n\": 1, \"xy\": [1.5, -2], \"crs\": null}\n]}\n");
}

TEST(JsonWriter, BooleansAreJsonLiterals) {
    JsonWriter json;
    json.begin_array({}, Layout::inline_);
    json.value({}, true);
    json.value({}, false);
    json.value({}, "true");
    json.end();
    EXPECT_EQ(json.str(), "[true, false, \"true\"]\n");
}

TEST(JsonWriter, StringsAreEscapedAndNumbersReadBackExactly) {
    EXPECT_EQ(dtm::io::json_string("a\"b\\c\nd\te\rf\x01"), "\"a\\\"b\\\\c\\nd\\te\\rf\\u0001\"");
    EXPECT_EQ(dtm::io::json_string("Příbram"), "\"Příbram\"");
    EXPECT_EQ(dtm::io::json_number(0.1), "0.1");
    EXPECT_EQ(dtm::io::json_number(-750180.123), "-750180.123");
    EXPECT_EQ(std::stod(dtm::io::json_number(1.0 / 3.0)), 1.0 / 3.0);
    EXPECT_EQ(dtm::io::json_number(std::numeric_limits<double>::quiet_NaN()), "null");
    EXPECT_EQ(dtm::io::json_number(-INFINITY), "null");
}

}  // namespace
