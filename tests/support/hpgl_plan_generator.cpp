// SPDX-License-Identifier: MIT
#include "support/hpgl_plan_generator.hpp"

#include <cmath>
#include <cstdio>
#include <numbers>

namespace dtm::test {
namespace {

constexpr long long spacing = 800;  // 20 mm
constexpr long long first = 2000;   // 50 mm
constexpr long long arm = 40;       // cross half-length, 1 mm

struct Spot {
    long long x, y;
    long long cm;  // height in centimetres
    int style;     // 0 symbol, 1 circle, 2 cross, 3 cross drawn as four arms from its centre
    bool comma;
};

std::string text(long long v) { return std::to_string(v); }

std::string height_text(const Spot& s) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%lld%c%02lld", s.cm / 100, s.comma ? ',' : '.',
                  s.cm % 100);
    return buffer;
}

std::string number17(double v) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    return buffer;
}

struct Layout {
    int cols, rows;
    std::vector<Spot> spots;
    long long frame_x, frame_y;  // upper-right frame corner
    [[nodiscard]] const Spot& at(int i, int j) const {
        return spots[static_cast<std::size_t>(j * cols + i)];
    }
    [[nodiscard]] std::pair<long long, long long> xy(int i, int j) const {
        return {at(i, j).x, at(i, j).y};
    }
};

using Vertex = std::pair<long long, long long>;

Layout make_layout(const HpglPlanOptions& o) {
    Layout l{o.columns, o.rows, {}, 0, 0};
    for (int j = 0; j < o.rows; ++j) {
        for (int i = 0; i < o.columns; ++i) {
            const long long cm = 30000 + 37 * i + 53 * j + (i * 7 + j * 3) % 10;
            l.spots.push_back(
                {first + spacing * i, first + spacing * j, cm, (i + 2 * j) % 4, (i + j) % 3 == 1});
        }
    }
    l.frame_x = first + spacing * (o.columns - 1) + 1000;
    l.frame_y = first + spacing * (o.rows - 1) + 1000;
    return l;
}

std::vector<Vertex> row_breakline(const Layout& l) {
    std::vector<Vertex> v;
    for (int i = 0; i < l.cols; ++i) {
        const auto [x, y] = l.xy(i, 1);
        v.push_back({x, y});
        if (i + 1 < l.cols) {
            v.push_back({x + 300, y});
            v.push_back({x + 550, y});
        }
    }
    return v;
}

std::vector<Vertex> column_breakline(const Layout& l) {
    std::vector<Vertex> v;
    for (int j = 2; j < l.rows; ++j) {
        const auto [x, y] = l.xy(1, j);
        v.push_back({x, y});
        if (j + 1 < l.rows) v.push_back({x, y + 400});
    }
    return v;
}

std::vector<Vertex> soft_line() {
    return {{first + 400, first + 300}, {first + 800, first + 350}, {first + 1200, first + 300}};
}

std::vector<Vertex> boundary_ring(const Layout& l) {
    std::vector<Vertex> v;
    for (int i = 0; i < l.cols; ++i) v.push_back(l.xy(i, 0));
    for (int j = 1; j < l.rows; ++j) v.push_back(l.xy(l.cols - 1, j));
    for (int i = l.cols - 2; i >= 0; --i) v.push_back(l.xy(i, l.rows - 1));
    for (int j = l.rows - 2; j >= 1; --j) v.push_back(l.xy(0, j));
    return v;
}

std::vector<Vertex> hole_ring(const Layout& l) {
    const auto a = l.xy(2, 2);
    return {a, {a.first + 400, a.second}, l.xy(3, 2), l.xy(3, 3), l.xy(2, 3)};
}

/// Height of a vertex: the spot height on it, else linear along the polyline between them.
std::vector<double> line_heights(const Layout& l, const std::vector<Vertex>& v, bool closed) {
    std::vector<double> z(v.size(), std::nan(""));
    for (std::size_t k = 0; k < v.size(); ++k) {
        for (const Spot& s : l.spots) {
            if (s.x == v[k].first && s.y == v[k].second) z[k] = static_cast<double>(s.cm) / 100.0;
        }
    }
    const std::size_t n = v.size();
    const std::size_t end = closed ? n + 1 : n;
    for (std::size_t k = 0; k < end; ++k) {
        if (!std::isnan(z[k % n])) continue;
        std::size_t a = k - 1, b = k + 1;
        while (std::isnan(z[b % n])) ++b;
        const auto d = [&](std::size_t p, std::size_t q) {
            return std::hypot(static_cast<double>(v[q % n].first - v[p % n].first),
                              static_cast<double>(v[q % n].second - v[p % n].second));
        };
        const double total = d(a, k) + d(k, b);
        z[k % n] = z[a % n] + (z[b % n] - z[a % n]) * d(a, k) / total;
    }
    return z;
}

std::string plain_polyline(const std::vector<Vertex>& v, bool close) {
    std::string s = "PU" + text(v[0].first) + "," + text(v[0].second) + ";PD";
    for (std::size_t k = 1; k < v.size(); ++k)
        s += (k > 1 ? "," : "") + text(v[k].first) + "," + text(v[k].second);
    if (close) s += "," + text(v[0].first) + "," + text(v[0].second);
    return s + ";PU;";
}

/// PE: pen-up absolute move to the first vertex, relative draws to the others.
std::string pe_polyline(const std::vector<Vertex>& v,
                        bool close,
                        bool seven_bit,
                        int fraction_bits) {
    const long long f = 1LL << fraction_bits;
    std::string s = "PE";
    if (seven_bit) s += "7";
    if (fraction_bits > 0) s += ">" + encode_pe_number(fraction_bits, seven_bit);
    s += "<=" + encode_pe_number(v[0].first * f, seven_bit) +
         encode_pe_number(v[0].second * f, seven_bit);
    std::vector<Vertex> path(v.begin() + 1, v.end());
    if (close) path.push_back(v[0]);
    Vertex at = v[0];
    for (const Vertex& p : path) {
        s += encode_pe_number((p.first - at.first) * f, seven_bit) +
             encode_pe_number((p.second - at.second) * f, seven_bit);
        at = p;
    }
    return s;
}

std::string plain_marker(const Spot& s) {
    const std::string xy = text(s.x) + "," + text(s.y);
    if (s.style == 0) return "PU;SM*;PA" + xy + ";SM;";
    if (s.style == 1) return "PU;PA" + xy + ";CI20;";
    if (s.style == 3) {
        std::string arms = "PU;";
        for (const auto& [dx, dy] :
             {Vertex{arm, 0}, Vertex{-arm, 0}, Vertex{0, arm}, Vertex{0, -arm}}) {
            arms += "PU" + xy + ";PD" + text(s.x + dx) + "," + text(s.y + dy) + ";";
        }
        return arms + "PU;";
    }
    return "PU" + text(s.x - arm) + "," + text(s.y) + ";PD" + text(s.x + arm) + "," + text(s.y) +
           ";PU" + text(s.x) + "," + text(s.y - arm) + ";PD" + text(s.x) + "," + text(s.y + arm) +
           ";PU;";
}

std::string pe_marker(const Spot& s) {
    const std::string xy = text(s.x) + "," + text(s.y);
    if (s.style == 0) return "PUSM*PA" + xy + "SM;";
    if (s.style == 1) return "PUPA" + xy + "CI20";
    if (s.style == 3) {
        const auto e = [](long long v) { return encode_pe_number(v); };
        return "PE<=" + e(s.x) + e(s.y) + e(arm) + e(0) + "<" + e(-arm) + e(0) + e(-arm) + e(0) +
               "<" + e(arm) + e(0) + e(0) + e(arm) + "<" + e(0) + e(-arm) + e(0) + e(-arm) +
               ";PU";  // PE leaves the pen down
    }
    return "PE<=" + encode_pe_number(s.x - arm) + encode_pe_number(s.y) +
           encode_pe_number(2 * arm) + encode_pe_number(0) + "<" + encode_pe_number(-arm) +
           encode_pe_number(-arm) + encode_pe_number(0) + encode_pe_number(2 * arm) + ";PU";
}

std::vector<std::pair<Vertex, std::string>> parcel_numbers(const Layout& l) {
    std::vector<std::pair<Vertex, std::string>> out;
    int number = 101;
    for (int j = 0; j + 1 < l.rows; j += 2) {
        for (int i = 0; i + 1 < l.cols; i += 2) {
            out.push_back(
                {{l.at(i, j).x + spacing / 2, l.at(i, j).y + spacing / 2}, text(number++)});
        }
    }
    return out;
}

std::string write_plain(const Layout& l) {
    std::string s = "IN;IP;SC;SP1;DI1,0;SI0.15,0.2;";
    s += plain_polyline(
        {{1000, 1000}, {l.frame_x, 1000}, {l.frame_x, l.frame_y}, {1000, l.frame_y}}, true);
    for (const Spot& spot : l.spots) {
        s += plain_marker(spot) + "PA" + text(spot.x + 60) + "," + text(spot.y + 40) + ";LB" +
             height_text(spot) + "\x03\n";
    }
    for (const auto& [at, label] : parcel_numbers(l))
        s += "PA" + text(at.first) + "," + text(at.second) + ";LB" + label + "\x03";
    s += "PA1200," + text(l.frame_y - 300) + ";LBVYSKOVY PLAN 1:500\x03\n";
    s += "SP2;" + plain_polyline(row_breakline(l), false) +
         plain_polyline(column_breakline(l), false) + plain_polyline(soft_line(), false) + "\n";
    s += "SP3;" + plain_polyline(boundary_ring(l), true) + "\nSP4;" +
         plain_polyline(hole_ring(l), true);
    return s + "SP0;\n";
}

std::string write_pcl(const Layout& l) {
    std::string s = "\x1b%-12345X@PJL JOB NAME=\"height plan\"\r\n@PJL ENTER LANGUAGE=PCL\r\n";
    s += "\x1b"
         "E\x1b&l1O\x1b*t300R\x1b*r1A\x1b*b6W";
    s += std::string("PD\xff\x00\x1b;", 6);  // raster bytes: skipped by count, never parsed
    s += "\x1b*rB\x1b%1BBPINPS" + text(l.frame_x + 1000) + "," + text(l.frame_y + 1000) +
         "RO0SP1PW0.25DI1,0SI0.15,0.2";
    s += pe_polyline({{1000, 1000}, {l.frame_x, 1000}, {l.frame_x, l.frame_y}, {1000, l.frame_y}},
                     true, false, 0) +
         ";";
    std::size_t k = 0;
    for (const Spot& spot : l.spots) {
        s += pe_marker(spot) + "PA" + text(spot.x + 60) + "," + text(spot.y + 40);
        s += (k++ % 4 == 3) ? "DT@,1;LB" + height_text(spot) + "@DT;"
                            : "LB" + height_text(spot) + "\x03";
    }
    for (const auto& [at, label] : parcel_numbers(l))
        s += "PA" + text(at.first) + "," + text(at.second) + "LB" + label + "\x03";
    s += "PA1200," + text(l.frame_y - 300) + "LBVYSKOVY PLAN 1:500\x03";
    s += "SP2" + pe_polyline(row_breakline(l), false, false, 1) + ";" +
         pe_polyline(column_breakline(l), false, true, 0) + ";" +
         pe_polyline(soft_line(), false, false, 0);  // no ';': ended by the next instruction
    s += "SP3" + pe_polyline(boundary_ring(l), true, false, 0) + ";";
    s += "PE:" + encode_pe_number(4) + pe_polyline(hole_ring(l), true, false, 0).substr(2) + ";";
    return s +
           "PUSP0PG;\x1b%0A\x1b"
           "E\x1b%-12345X@PJL EOJ\r\n\x1b%-12345X";
}

}  // namespace

std::string encode_pe_number(long long value, bool seven_bit) {
    unsigned long long u = value < 0 ? static_cast<unsigned long long>(-value) * 2 + 1
                                     : static_cast<unsigned long long>(value) * 2;
    const unsigned base = seven_bit ? 32 : 64;
    std::string s;
    while (true) {
        const auto digit = static_cast<unsigned>(u % base);
        u /= base;
        if (u == 0) {
            s += static_cast<char>((seven_bit ? 95 : 191) + digit);
            return s;
        }
        s += static_cast<char>(63 + digit);
    }
}

Point2 HpglPlan::to_ground(Point2 p) const {
    const double m = options.scale / 1000.0 / 40.0;
    const double r = options.rotation_deg * std::numbers::pi / 180.0;
    const double c = std::cos(r), s = std::sin(r);
    return {options.origin_e + m * (c * p.x - s * p.y), options.origin_n + m * (s * p.x + c * p.y)};
}

HpglPlan make_hpgl_plan(const HpglPlanOptions& options) {
    HpglPlan plan;
    plan.options = options;
    const Layout l = make_layout(options);
    const auto ground3 = [&](const std::vector<Vertex>& v, bool closed) {
        const auto z = line_heights(l, v, closed);
        std::vector<Point3> out;
        for (std::size_t k = 0; k < v.size(); ++k) {
            const Point2 g =
                plan.to_ground({static_cast<double>(v[k].first), static_cast<double>(v[k].second)});
            out.push_back({g.x, g.y, z[k]});
        }
        return out;
    };
    for (const Spot& s : l.spots) {
        const Point2 g = plan.to_ground({static_cast<double>(s.x), static_cast<double>(s.y)});
        plan.spot_heights.push_back({g.x, g.y, static_cast<double>(s.cm) / 100.0});
    }
    plan.breaklines = {ground3(row_breakline(l), false), ground3(column_breakline(l), false)};
    for (const Vertex& v : soft_line()) {
        plan.soft_breakline.push_back(
            plan.to_ground({static_cast<double>(v.first), static_cast<double>(v.second)}));
    }
    plan.boundary = ground3(boundary_ring(l), true);
    plan.hole = ground3(hole_ring(l), true);
    plan.parcel_labels = parcel_numbers(l).size();
    plan.labels = l.spots.size() + plan.parcel_labels + 1;
    plan.plain_hpgl = write_plain(l);
    plan.pcl_hpgl2 = write_pcl(l);
    const std::vector<Point2> corners{
        {1000, 1000},
        {static_cast<double>(l.frame_x), 1000},
        {static_cast<double>(l.frame_x), static_cast<double>(l.frame_y)},
        {1000, static_cast<double>(l.frame_y)}};
    plan.control_csv = "px,py,E,N\n";
    for (std::size_t k = 0; k < corners.size(); ++k) {
        const Point2 g = plan.to_ground(corners[k]);
        const std::string row = number17(corners[k].x) + "," + number17(corners[k].y) + "," +
                                number17(g.x) + "," + number17(g.y) + "\n";
        plan.control_csv += row;
        if (k == 0 || k == 2) plan.control_csv_two += row;
    }
    return plan;
}

}  // namespace dtm::test
