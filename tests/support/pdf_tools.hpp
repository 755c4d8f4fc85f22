// SPDX-License-Identifier: MIT
/// @file
/// @brief Test helpers around poppler-utils and GDAL's command-line tools, the independent
/// readers of the PDFs dtm draws: words as pdftotext reads them (with their boxes), page sizes
/// from pdfinfo, gdalinfo's report.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace dtm::test {

/// stdout of a shell command (empty if it cannot be run).
[[nodiscard]] std::string command_output(const std::string& command);
/// True when @p tool is on PATH.
[[nodiscard]] bool have_tool(const char* tool);

/// The whitespace-separated words of `pdftotext MODE FILE -` (MODE "", "-raw" or "-layout").
[[nodiscard]] std::vector<std::string> pdf_words(const std::filesystem::path& pdf,
                                                 const std::string& mode = "");

/// A word of `pdftotext -bbox` with its box in PDF points (top-left origin, y down).
struct PdfWord {
    std::string text;
    double x_min = 0.0;
    double y_min = 0.0;
    double x_max = 0.0;
    double y_max = 0.0;
    int page = 1;
};
[[nodiscard]] std::vector<PdfWord> pdf_word_boxes(const std::filesystem::path& pdf);

/// Page size in millimetres from `pdfinfo -f P -l P` (0, 0 when unreadable).
[[nodiscard]] std::pair<double, double> pdf_page_mm(const std::filesystem::path& pdf, int page = 1);

}  // namespace dtm::test
