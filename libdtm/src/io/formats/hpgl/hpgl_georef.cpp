// SPDX-License-Identifier: MIT
// Georeferencing of plotter coordinates.
//
// Scale: a plotter unit is 0.025 mm on paper, so at 1:S it is 0.025 * S / 1000 m on the ground;
// the plan's x axis is turned counter-clockwise by the rotation from grid east and plotter 0,0
// lands on the origin. Control points: with two, the similarity (scale, rotation, shift) through
// both is exact; with three or more, the six affine parameters minimise the squared ground
// residuals (normal equations on coordinates centred at their means, which keeps large projected
// coordinates such as S-JTSK well conditioned). Residuals and their RMS are reported.
// Reference: Ghilani, "Adjustment Computations", 6th ed., ch. 18 (2-D conformal and affine
// coordinate transformations).
#include "io/formats/hpgl/hpgl_georef.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>

#include "dtm/core/error.hpp"
#include "io/formats/hpgl/hpgl_plot.hpp"

namespace dtm::io::hpgl {
namespace {

std::string format(double v, int decimals) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
    return buffer;
}

/// Splits one CSV line into numbers; false if a field is not a number.
bool split_numbers(const std::string& line, std::vector<double>& values, std::size_t& bad_column) {
    values.clear();
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ',' || line[i] == ';' || line[i] == ' ' ||
                                   line[i] == '\t' || line[i] == '\r'))
            ++i;
        if (i >= line.size()) break;
        const char* begin = line.c_str() + i;
        char* end = nullptr;
        const double v = std::strtod(begin, &end);
        const std::size_t used = static_cast<std::size_t>(end - begin);
        const bool ends_field =
            i + used >= line.size() ||
            std::string_view(",; \t\r").find(line[i + used]) != std::string_view::npos;
        if (used == 0 || !ends_field || !std::isfinite(v)) {
            bad_column = i + 1;
            return false;
        }
        values.push_back(v);
        i += used;
    }
    return true;
}

}  // namespace

std::vector<ControlPoint> read_control_points(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in) throw InputError(file, 0, 0, "cannot open the control-point file");
    std::vector<ControlPoint> points;
    std::string line;
    std::vector<double> values;
    std::size_t number = 0;
    bool header = false;
    double to_units = 1.0;  // a header naming px_mm, py_mm: paper millimetres
    while (std::getline(in, line)) {
        ++number;
        if (number == 1 && line.size() >= 3 && line.compare(0, 3, "\xEF\xBB\xBF") == 0)
            line.erase(0, 3);
        const auto first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#') continue;
        std::size_t column = 0;
        if (!split_numbers(line, values, column)) {
            if (points.empty() && !header) {  // one header line before the data
                header = true;
                std::string lower = line;
                for (char& ch : lower)
                    ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
                if (lower.find("px_mm") != std::string::npos) to_units = units_per_mm;
                continue;
            }
            throw InputError(file, number, column, "expected four numbers px,py,E,N");
        }
        if (values.size() != 4) {
            throw InputError(
                file, number, 0,
                "expected four numbers px,py,E,N, found " + std::to_string(values.size()));
        }
        points.push_back({{values[0] * to_units, values[1] * to_units}, {values[2], values[3]}});
    }
    return points;
}

Affine fit_control_points(const std::vector<ControlPoint>& points,
                          const std::filesystem::path& file) {
    if (points.size() < 2) {
        throw InputError(
            file, 0, 0,
            "at least 2 control points are needed, found " + std::to_string(points.size()));
    }
    const double n = static_cast<double>(points.size());
    Point2 mp{}, mg{};
    for (const auto& c : points) {
        mp.x += c.plotter.x / n;
        mp.y += c.plotter.y / n;
        mg.x += c.ground.x / n;
        mg.y += c.ground.y / n;
    }
    Affine t;
    if (points.size() == 2) {
        const double px = points[1].plotter.x - points[0].plotter.x,
                     py = points[1].plotter.y - points[0].plotter.y;
        const double gx = points[1].ground.x - points[0].ground.x,
                     gy = points[1].ground.y - points[0].ground.y;
        const double d = px * px + py * py;
        if (d == 0.0)
            throw InputError(file, 0, 0, "the two control points have the same plotter position");
        const double a = (gx * px + gy * py) / d,
                     b = (gy * px - gx * py) / d;  // (g / p) as complex numbers
        t = {0.0, a, -b, 0.0, b, a};
    } else {
        double sxx = 0, sxy = 0, syy = 0, sxe = 0, sye = 0, sxn = 0, syn = 0;
        for (const auto& c : points) {
            const double x = c.plotter.x - mp.x, y = c.plotter.y - mp.y;
            const double e = c.ground.x - mg.x, nn = c.ground.y - mg.y;
            sxx += x * x;
            sxy += x * y;
            syy += y * y;
            sxe += x * e;
            sye += y * e;
            sxn += x * nn;
            syn += y * nn;
        }
        const double det = sxx * syy - sxy * sxy;
        if (!(std::abs(det) > 1e-12 * (sxx * syy)) || sxx == 0.0 || syy == 0.0) {
            throw InputError(file, 0, 0,
                             "the control points are collinear: an affine transform is undefined");
        }
        t = {0.0, (sxe * syy - sye * sxy) / det, (sye * sxx - sxe * sxy) / det,
             0.0, (sxn * syy - syn * sxy) / det, (syn * sxx - sxn * sxy) / det};
    }
    t.e0 = mg.x - t.ex * mp.x - t.ey * mp.y;
    t.n0 = mg.y - t.nx * mp.x - t.ny * mp.y;
    return t;
}

Georeference make_georeference(const HpglOptions& options) {
    Georeference g;
    if (options.scale != 0.0 && !options.control_file.empty()) {
        throw OptionError("hpgl.scale",
                          "`hpgl.scale` and `hpgl.control_file` are alternatives: give one");
    }
    if (!options.control_file.empty()) {
        const auto points = read_control_points(options.control_file);
        g.transform = fit_control_points(points, options.control_file);
        double sum = 0.0;
        for (std::size_t i = 0; i < points.size(); ++i) {
            const Point2 p = g.transform.apply(points[i].plotter);
            const double r = std::hypot(p.x - points[i].ground.x, p.y - points[i].ground.y);
            sum += r * r;
            if (points.size() > 2) {
                g.notes.push_back("control point " + std::to_string(i + 1) + ": residual " +
                                  format(r, 4) + " m");
            }
        }
        g.notes.push_back(std::string(points.size() == 2 ? "similarity" : "affine") +
                          " transform from " + std::to_string(points.size()) +
                          " control points, RMS residual " +
                          format(std::sqrt(sum / static_cast<double>(points.size())), 4) + " m");
        return g;
    }
    if (options.scale != 0.0) {
        if (!(options.scale > 0.0) || !std::isfinite(options.scale)) {
            throw OptionError("hpgl.scale", "`hpgl.scale` must be positive");
        }
        const double r = options.rotation_deg * std::numbers::pi / 180.0;
        const double quarter = options.rotation_deg / 90.0;
        double c = std::cos(r), s = std::sin(r);
        if (quarter == std::round(quarter)) {  // exact for multiples of 90 degrees
            const long q = ((static_cast<long>(quarter) % 4) + 4) % 4;
            c = q == 0 ? 1.0 : q == 2 ? -1.0 : 0.0;
            s = q == 1 ? 1.0 : q == 3 ? -1.0 : 0.0;
        }
        const double m = options.scale / 1000.0 / units_per_mm;  // metres per plotter unit
        g.transform = {options.origin_e, m * c, -m * s, options.origin_n, m * s, m * c};
        return g;
    }
    const double mm = 1.0 / units_per_mm;
    g.transform = {0.0, mm, 0.0, 0.0, 0.0, mm};
    g.notes.push_back(
        "not georeferenced (no `hpgl.scale` or `hpgl.control_file`): coordinates are plotter "
        "millimetres on paper");
    return g;
}

}  // namespace dtm::io::hpgl
