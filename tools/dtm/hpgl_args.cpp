// SPDX-License-Identifier: MIT
#include "hpgl_args.hpp"

#include <algorithm>
#include <array>
#include <string>
#include <utility>

#include "dtm/core/error.hpp"

namespace dtm::cli {
namespace {

constexpr std::array<std::pair<std::string_view, io::PenRole>, 8> role_names{{
    {"points", io::PenRole::points},
    {"breakline", io::PenRole::breakline},
    {"soft-breakline", io::PenRole::soft_breakline},
    {"soft_breakline", io::PenRole::soft_breakline},
    {"soft", io::PenRole::soft_breakline},
    {"boundary", io::PenRole::boundary},
    {"hole", io::PenRole::hole},
    {"ignore", io::PenRole::ignore},
}};

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

int parse_pen(std::string_view text, std::string_view option) {
    text = trim(text);
    int pen = 0;
    bool ok = !text.empty() && text.size() <= 6;
    for (const char c : text) {
        ok = ok && c >= '0' && c <= '9';
        if (ok) pen = pen * 10 + (c - '0');
    }
    if (!ok) {
        throw UsageError(std::string(option) + ": '" + std::string(text) + "' is not a pen number");
    }
    return pen;
}

/// "500" or "1:500".
double parse_scale(const std::string& text) {
    const std::string number = text.rfind("1:", 0) == 0 ? text.substr(2) : text;
    std::size_t used = 0;
    double value = 0.0;
    try {
        value = std::stod(number, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != number.size() || !(value > 0.0)) {
        throw CLI::ValidationError("--hpgl-scale",
                                   "expected the scale denominator, for example 500 or 1:500");
    }
    return value;
}

}  // namespace

std::map<int, io::PenRole> parse_pen_roles(std::string_view text) {
    std::map<int, io::PenRole> roles;
    while (!text.empty()) {
        const auto comma = text.find(',');
        const std::string_view item = trim(text.substr(0, comma));
        text = comma == std::string_view::npos ? std::string_view{} : text.substr(comma + 1);
        if (item.empty()) continue;
        const auto equals = item.find('=');
        if (equals == std::string_view::npos) {
            throw UsageError("--hpgl-pens: '" + std::string(item) +
                             "' is not PEN=ROLE (for example 2=breakline)");
        }
        const int pen = parse_pen(item.substr(0, equals), "--hpgl-pens");
        const std::string_view name = trim(item.substr(equals + 1));
        const auto found = std::find_if(role_names.begin(), role_names.end(),
                                        [&](const auto& entry) { return entry.first == name; });
        if (found == role_names.end()) {
            throw UsageError("--hpgl-pens: unknown role '" + std::string(name) +
                             "' (expected points, breakline, soft-breakline, boundary, hole or "
                             "ignore)");
        }
        roles[pen] = found->second;
    }
    return roles;
}

std::vector<int> parse_pen_list(std::string_view text) {
    std::vector<int> pens;
    while (!text.empty()) {
        const auto comma = text.find(',');
        const std::string_view item = trim(text.substr(0, comma));
        text = comma == std::string_view::npos ? std::string_view{} : text.substr(comma + 1);
        if (!item.empty()) pens.push_back(parse_pen(item, "--hpgl-height-pens"));
    }
    return pens;
}

void add_hpgl_options(CLI::App& app, io::HpglOptions& options) {
    const std::string group = "HPGL plans";
    app.add_option_function<std::string>(
           "--hpgl-pens",
           [&options](const std::string& text) {
               try {
                   options.pens = parse_pen_roles(text);
               } catch (const UsageError& e) {
                   throw CLI::ValidationError(e.what());
               }
           },
           "Roles of the lines drawn by each pen: PEN=ROLE,... with ROLE one of points, breakline, "
           "soft-breakline, boundary, hole, ignore (lines on other pens are ignored), e.g. "
           "2=breakline,3=boundary,4=hole,1=ignore")
        ->group(group);
    app.add_option_function<std::string>(
           "--hpgl-height-pens",
           [&options](const std::string& text) {
               try {
                   options.height_pens = parse_pen_list(text);
               } catch (const UsageError& e) {
                   throw CLI::ValidationError(e.what());
               }
           },
           "Pens whose integer labels are heights too, e.g. 5,6 (decimal labels are heights on "
           "every pen)")
        ->group(group);
    app.add_option(
           "--hpgl-marker-radius", options.marker_radius_mm,
           "Search radius in paper millimetres from a height label to its marker, and from a "
           "line vertex to a spot height (default 3)")
        ->check(CLI::NonNegativeNumber)
        ->group(group);
    app.add_option_function<std::string>(
           "--hpgl-scale",
           [&options](const std::string& text) { options.scale = parse_scale(text); },
           "Plan scale denominator (500 or 1:500); with --hpgl-origin and --hpgl-rotation")
        ->group(group);
    app.add_option_function<std::vector<double>>(
           "--hpgl-origin",
           [&options](const std::vector<double>& v) {
               options.origin_e = v.at(0);
               options.origin_n = v.at(1);
           },
           "Ground E,N of plotter 0,0 (default 0,0)")
        ->expected(2)
        ->delimiter(',')
        ->group(group);
    app.add_option(
           "--hpgl-rotation", options.rotation_deg,
           "Counter-clockwise angle in degrees of the plan's x axis from grid east (default 0)")
        ->group(group);
    app.add_option(
           "--hpgl-control", options.control_file,
           "CSV of control points px,py,E,N (px,py in plotter units, 40 per mm; paper mm with a "
           "px_mm,py_mm header): 2 points give a "
           "similarity, 3 or more a least-squares affine transform; excludes --hpgl-scale")
        ->check(CLI::ExistingFile)
        ->excludes("--hpgl-scale")
        ->group(group);
}

}  // namespace dtm::cli
