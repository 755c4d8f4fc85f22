// SPDX-License-Identifier: MIT
// HP-GL tokenizer and PE decoder: missing separators, labels and terminators, PCL/PJL and
// RS-232 wrappers, PE base-64 / base-32 / fractional / pen flags, corrupt bytes with offsets.
#include "io/formats/hpgl/hpgl_lexer.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "dtm/core/error.hpp"
#include "support/hpgl_plan_generator.hpp"

namespace {

using dtm::io::hpgl::Command;
using dtm::io::hpgl::Diagnostics;
using dtm::io::hpgl::Lexer;
using dtm::io::hpgl::PeItem;

struct Token {
    std::string name;
    std::vector<double> params;
    std::string text;
    std::vector<PeItem> pe;
};

std::vector<Token> tokens(std::string_view bytes,
                          bool strict = true,
                          std::vector<std::string>* warnings = nullptr) {
    Diagnostics diag("test.plt", strict);
    Lexer lexer(bytes, diag);
    Command c;
    std::vector<Token> out;
    while (lexer.next(c))
        out.push_back({std::string(c.name, 2), c.params, std::string(c.text), c.pe});
    lexer.finish();
    if (warnings != nullptr) *warnings = diag.take_warnings();
    return out;
}

std::string names(const std::vector<Token>& t) {
    std::string s;
    for (const auto& token : t) s += token.name + " ";
    return s;
}

TEST(HpglLexer, SplitsInstructionsWithoutSeparators) {
    const auto t = tokens("INSP2PA10,20PD30,-40.5PUpu");
    EXPECT_EQ(names(t), "IN SP PA PD PU PU ");
    EXPECT_EQ(t[1].params, std::vector<double>{2});
    EXPECT_EQ(t[2].params, (std::vector<double>{10, 20}));
    EXPECT_EQ(t[3].params, (std::vector<double>{30, -40.5}));
}

TEST(HpglLexer, ReadsBlankSeparatedParametersAndEmptyOnes) {
    const auto t = tokens("IP 0 0 11440 7700\nLT;;PW .25 , 3;PD1,2,;");
    EXPECT_EQ(names(t), "IP LT PW PD ");
    EXPECT_EQ(t[0].params, (std::vector<double>{0, 0, 11440, 7700}));
    EXPECT_TRUE(t[1].params.empty());
    EXPECT_EQ(t[2].params, (std::vector<double>{0.25, 3}));
    EXPECT_EQ(t[3].params, (std::vector<double>{1, 2}));
}

TEST(HpglLexer, DecimalParametersAreCorrectlyRounded) {
    const auto t = tokens("PD-1385.640646,2400.00000009;");
    EXPECT_EQ(t[0].params[0], -1385.640646);
    EXPECT_EQ(t[0].params[1], 2400.00000009);
}

TEST(HpglLexer, LabelRunsToTheTerminatorWhichDtChanges) {
    const auto t = tokens(
        "LB312.45\x03PA1,2;DT@,1;LBPU;SP2@DT;LB -8\x03"
        "DT#;LBa#INLBb\x03");
    EXPECT_EQ(names(t), "LB PA DT LB DT LB DT LB IN LB ");
    EXPECT_EQ(t[0].text, "312.45");
    EXPECT_EQ(t[3].text, "PU;SP2");  // instructions inside a label are text
    EXPECT_EQ(t[5].text, " -8");     // DT; restored ETX
    EXPECT_EQ(t[7].text, "a");
    EXPECT_EQ(t[9].text, "b");  // IN restored ETX
}

TEST(HpglLexer, UnterminatedLabelIsReportedAtItsInstruction) {
    EXPECT_THROW((void)tokens("IN;PA1,1;LB312.45"), dtm::InputError);
    std::vector<std::string> warnings;
    const auto t = tokens("IN;PA1,1;LB312.45", false, &warnings);
    ASSERT_EQ(t.size(), 3u);
    EXPECT_EQ(t[2].text, "312.45");
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("byte 9: label text is not terminated"), std::string::npos)
        << warnings[0];
}

TEST(HpglLexer, SymbolModeTakesOneCharacter) {
    const auto t = tokens("SM*PA1,2SM;PA3,4SMXPU");
    EXPECT_EQ(names(t), "SM PA SM PA SM PU ");
    EXPECT_EQ(t[0].text, "*");
    EXPECT_EQ(t[2].text, "");
    EXPECT_EQ(t[4].text, "X");
}

TEST(HpglLexer, SkipsPclAndPjlWrappersIncludingBinaryPayloads) {
    std::string bytes =
        "\x1b%-12345X@PJL JOB\r\n@PJL ENTER LANGUAGE=PCL\r\n\x1b"
        "E\x1b&l1O\x1b*b7W";
    bytes += std::string("PD\x00\xff\x1b;Q", 7);
    bytes +=
        "\x1b*rB\x1b%0BINSP1PA5,6\x1b%0APCL text PD9,9\x1b%1BPD7,8;\x1b"
        "E\x1b%-12345X@PJL EOJ\r\n";
    const auto t = tokens(bytes);
    EXPECT_EQ(names(t), "IN SP PA PD ");
    EXPECT_EQ(t[3].params, (std::vector<double>{7, 8}));
}

TEST(HpglLexer, PjlEnterLanguageHpgl2StartsHpglWithoutPclSwitch) {
    const auto t = tokens("\x1b%-12345X@PJL ENTER LANGUAGE=HPGL2\nINPA1,1");
    EXPECT_EQ(names(t), "IN PA ");
}

TEST(HpglLexer, SkipsRs232DeviceControlEscapes) {
    const auto t = tokens("\x1b.(;\x1b.I81;;17:\x1b.N;19:IN;SC;PU;");
    EXPECT_EQ(names(t), "IN SC PU ");
}

TEST(HpglLexer, StrayTextIsSkippedWithOneWarning) {
    std::vector<std::string> warnings;
    const auto t = tokens("IN;\r\nX0=0;Y0=0;\r\nSP1;", true, &warnings);
    EXPECT_EQ(names(t), "IN SP ");
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("2 runs of text"), std::string::npos);
}

TEST(HpglLexer, EightBitByteWhereAnInstructionBelongsIsAnErrorWithItsOffset) {
    try {
        (void)tokens("IN;SP1;\xC3\xA9PA1,1;");
        FAIL() << "no error";
    } catch (const dtm::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("test.plt"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("byte 7: unexpected byte 0xC3"), std::string::npos)
            << e.what();
    }
    std::vector<std::string> warnings;
    const auto t = tokens("IN;SP1;\xC3\xA9PA1,1;", false, &warnings);
    EXPECT_EQ(names(t), "IN SP PA ");
    EXPECT_EQ(warnings.size(), 2u);
}

TEST(HpglPe, DecodesAutocadBase64Data) {
    // From hpgl-autocad-hpgl2/test1-Model.plt: pen-up absolute to (2077, 2210), then an absolute
    // draw to (909, 1042): 'y'=58 '?'=0 0xC0=1 -> 58 + 1 * 4096 = 4154 -> +2077, and so on.
    const auto t = tokens(
        "PE<=y?\xC0"
        "CD\xC0=Y\xDB"
        "c\xDFPUSP0;");
    ASSERT_EQ(names(t), "PE PU SP ");
    ASSERT_EQ(t[0].pe.size(), 2u);
    EXPECT_EQ(t[0].pe[0].kind, PeItem::Kind::move);
    EXPECT_TRUE(t[0].pe[0].absolute);
    EXPECT_EQ(t[0].pe[0].x, 2077);
    EXPECT_EQ(t[0].pe[0].y, 2210);
    EXPECT_EQ(t[0].pe[1].kind, PeItem::Kind::draw);
    EXPECT_TRUE(t[0].pe[1].absolute);
    EXPECT_EQ(t[0].pe[1].x, 909);
    EXPECT_EQ(t[0].pe[1].y, 1042);
}

TEST(HpglPe, RoundTripsEncodedValuesInBothModesWithFlags) {
    using dtm::test::encode_pe_number;
    const std::vector<long long> values{0, 1, -1, 31, -32, 63, 64, -4095, 123456789, -987654321};
    for (const bool seven : {false, true}) {
        std::string bytes = "PE";
        if (seven) bytes += "7";
        bytes += ">" + encode_pe_number(2, seven) + ":" + encode_pe_number(3, seven);
        for (std::size_t i = 0; i + 1 < values.size(); i += 2) {
            bytes += (i == 0 ? "<=" : "") + encode_pe_number(values[i], seven) +
                     encode_pe_number(values[i + 1], seven);
        }
        const auto t = tokens(bytes + ";SP1");
        ASSERT_EQ(names(t), "PE SP ");
        const auto& pe = t[0].pe;
        ASSERT_EQ(pe.size(), 1 + values.size() / 2);
        EXPECT_EQ(pe[0].kind, PeItem::Kind::pen);
        EXPECT_EQ(pe[0].pen, 3);
        EXPECT_EQ(pe[1].kind, PeItem::Kind::move);
        EXPECT_TRUE(pe[1].absolute);
        EXPECT_FALSE(pe[2].absolute);
        for (std::size_t i = 0; i + 1 < values.size(); i += 2) {
            EXPECT_EQ(pe[1 + i / 2].x, static_cast<double>(values[i]) / 4.0) << seven;
            EXPECT_EQ(pe[1 + i / 2].y, static_cast<double>(values[i + 1]) / 4.0) << seven;
        }
    }
}

TEST(HpglPe, MangledAutocadPlotIsAnErrorWithByteOffset) {
    // The bytes of hpgl-autocad-hpgl2/test-Model.PLT around its first PE: C3 80 is a UTF-8
    // re-encoding of the 8-bit digit C0; 0x80 is no PE digit.
    const std::string bytes =
        "SP1PE<=y?\xC3\x80"
        "CD\xC3\x80;";
    try {
        (void)tokens(bytes);
        FAIL() << "no error";
    } catch (const dtm::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("byte 10: invalid byte 0x80 in PE"), std::string::npos)
            << e.what();
    }
}

TEST(HpglLexer, ArbitraryBytesNeverCrashAndOnlyRaiseInputError) {
    std::mt19937 random(7);
    for (int round = 0; round < 2000; ++round) {
        std::string bytes(static_cast<std::size_t>(random() % 200), '\0');
        for (char& c : bytes)
            c = static_cast<char>(random() % 4 == 0 ? "PEDUALB;,\x1b%0-7<=>:"[random() % 19]
                                                    : random());
        EXPECT_NO_THROW((void)tokens(bytes, false));
        try {
            (void)tokens(bytes, true);
        } catch (const dtm::InputError& e) {
            EXPECT_NE(std::string(e.what()).find("byte "), std::string::npos);
        }
    }
}

}  // namespace
