// SPDX-License-Identifier: MIT
#include "support/pdf_tools.hpp"

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace dtm::test {
namespace {

std::string quoted(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

double attribute(const std::string& tag, const std::string& name) {
    const std::size_t at = tag.find(name + "=\"");
    return at == std::string::npos ? 0.0 : std::atof(tag.c_str() + at + name.size() + 2);
}

/// Undoes the XML escapes pdftotext -bbox writes.
std::string unescape(std::string s) {
    const std::pair<const char*, const char*> entities[] = {
        {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&apos;", "'"}, {"&amp;", "&"}};
    for (const auto& [from, to] : entities) {
        for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + 1)) {
            s.replace(at, std::string(from).size(), to);
        }
    }
    return s;
}

}  // namespace

std::string command_output(const std::string& command) {
    std::string out;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (pipe == nullptr) return out;
    char buffer[4096];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) out.append(buffer, n);
    ::pclose(pipe);
    return out;
}

bool have_tool(const char* tool) {
    return std::system((std::string("command -v ") + tool + " > /dev/null 2>&1").c_str()) == 0;
}

std::vector<std::string> pdf_words(const std::filesystem::path& pdf, const std::string& mode) {
    std::istringstream in(
        command_output("pdftotext " + mode + " " + quoted(pdf) + " - 2>/dev/null"));
    std::vector<std::string> words;
    std::string w;
    while (in >> w) words.push_back(w);
    return words;
}

std::vector<PdfWord> pdf_word_boxes(const std::filesystem::path& pdf) {
    const std::string xml = command_output("pdftotext -bbox " + quoted(pdf) + " - 2>/dev/null");
    std::vector<PdfWord> out;
    int page = 0;
    for (std::size_t at = 0; (at = xml.find('<', at)) != std::string::npos;) {
        const std::size_t end = xml.find('>', at);
        if (end == std::string::npos) break;
        const std::string tag = xml.substr(at, end - at + 1);
        if (tag.rfind("<page ", 0) == 0) ++page;
        if (tag.rfind("<word ", 0) == 0) {
            const std::size_t close = xml.find("</word>", end);
            PdfWord w;
            w.text = unescape(xml.substr(end + 1, close - end - 1));
            w.x_min = attribute(tag, "xMin");
            w.y_min = attribute(tag, "yMin");
            w.x_max = attribute(tag, "xMax");
            w.y_max = attribute(tag, "yMax");
            w.page = page;
            out.push_back(w);
        }
        at = end + 1;
    }
    return out;
}

std::pair<double, double> pdf_page_mm(const std::filesystem::path& pdf, int page) {
    const std::string p = std::to_string(page);
    const std::string info =
        command_output("pdfinfo -f " + p + " -l " + p + " " + quoted(pdf) + " 2>/dev/null");
    const std::size_t at = info.find("size:");
    if (at == std::string::npos) return {0.0, 0.0};
    double w = 0.0;
    double h = 0.0;
    if (std::sscanf(info.c_str() + at + 5, " %lf x %lf", &w, &h) != 2) return {0.0, 0.0};
    return {w * 25.4 / 72.0, h * 25.4 / 72.0};
}

}  // namespace dtm::test
