// SPDX-License-Identifier: MIT
#include "hpgl_args.hpp"

#include <string>

#include "dtm/core/error.hpp"

namespace dtm::cli {
namespace {

/// "500" or "1:500".
double parse_scale(const std::string& text)
{
    const std::string number = text.rfind("1:", 0) == 0 ? text.substr(2) : text;
    std::size_t used = 0;
    double value = 0.0;
    try {
        value = std::stod(number, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != number.size() || !(value > 0.0)) {
        throw CLI::ValidationError("--hpgl-scale", "expected the scale denominator, for example 500 or 1:500");
    }
    return value;
}

}  // namespace

void add_hpgl_options(CLI::App& app, io::HpglOptions& options)
{
    const std::string group = "HPGL plans";
    app.add_option_function<std::string>(
           "--hpgl-pens",
           [&options](const std::string& text) {
               try {
                   options.pens = io::parse_pen_roles(text);
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
                   options.height_pens = io::parse_pen_list(text);
               } catch (const UsageError& e) {
                   throw CLI::ValidationError(e.what());
               }
           },
           "Pens whose integer labels are heights too, e.g. 5,6 (decimal labels are heights on every pen)")
        ->group(group);
    app.add_option("--hpgl-marker-radius", options.marker_radius_mm,
                   "Search radius in paper millimetres from a height label to its marker, and from a "
                   "line vertex to a spot height (default 3)")
        ->check(CLI::NonNegativeNumber)
        ->group(group);
    app.add_option_function<std::string>(
           "--hpgl-scale", [&options](const std::string& text) { options.scale = parse_scale(text); },
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
    app.add_option("--hpgl-rotation", options.rotation_deg,
                   "Counter-clockwise angle in degrees of the plan's x axis from grid east (default 0)")
        ->group(group);
    app.add_option("--hpgl-control", options.control_file,
                   "CSV of control points px,py,E,N (px,py in plotter units, 40 per mm; paper mm with a "
                   "px_mm,py_mm header): 2 points give a "
                   "similarity, 3 or more a least-squares affine transform; excludes --hpgl-scale")
        ->check(CLI::ExistingFile)
        ->excludes("--hpgl-scale")
        ->group(group);
}

}  // namespace dtm::cli
