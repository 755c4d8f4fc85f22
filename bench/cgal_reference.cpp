// SPDX-License-Identifier: MIT
// cgal_reference: CGAL's triangulation of the same input as `dtm tin`, for bench/compare_cgal.sh.
//
//   cgal_reference --kind NAME points.xyz [breaklines.csv]
//
// Without breaklines: CGAL::Delaunay_triangulation_2<Epick> filled with the range insert
// (which sorts the points spatially). With breaklines (header "wkt", one quoted
// "LINESTRING Z (x y z, ...)" per row): CGAL::Constrained_Delaunay_triangulation_2<Epick,
// Default, Exact_predicates_tag>, points by range insert, then all breakline segments through
// insert_constraints (which also sorts spatially). Only the triangulation is timed
// (std::chrono::steady_clock); reading is not. Prints one JSON line:
//   {"engine":"cgal","kind":...,"vertices":...,"faces":...,"seconds":...}
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_2;
using Dt = CGAL::Delaunay_triangulation_2<K>;
using Cdt =
    CGAL::Constrained_Delaunay_triangulation_2<K, CGAL::Default, CGAL::Exact_predicates_tag>;

[[noreturn]] void fail(const std::string& what) {
    std::cerr << "cgal_reference: " << what << '\n';
    std::exit(1);
}

std::string slurp(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) {
        fail("cannot open " + path);
    }
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

/// Parses a double at text[pos...], skipping spaces and tabs first; advances pos.
bool next_number(std::string_view text, std::size_t& pos, double& v) {
    while (pos < text.size() && (text[pos] == ' ' || text[pos] == '\t')) {
        ++pos;
    }
    const char* first = text.data() + pos;
    const auto r = std::from_chars(first, text.data() + text.size(), v);
    if (r.ec != std::errc()) {
        return false;
    }
    pos += static_cast<std::size_t>(r.ptr - first);
    return true;
}

std::vector<Point> read_xyz(const std::string& path) {
    const std::string text = slurp(path);
    std::vector<Point> points;
    std::size_t line_start = 0;
    std::size_t line_no = 0;
    while (line_start < text.size()) {
        std::size_t end = text.find('\n', line_start);
        if (end == std::string::npos) {
            end = text.size();
        }
        ++line_no;
        const std::string_view line(text.data() + line_start, end - line_start);
        std::size_t pos = 0;
        double x = 0.0;
        double y = 0.0;
        if (line.find_first_not_of(" \t\r") != std::string_view::npos) {
            if (!next_number(line, pos, x) || !next_number(line, pos, y)) {
                fail(path + ":" + std::to_string(line_no) + ": expected \"x y z\"");
            }
            points.emplace_back(x, y);
        }
        line_start = end + 1;
    }
    return points;
}

/// Breakline vertices and the index pairs of their segments.
struct Breaklines {
    std::vector<Point> points;
    std::vector<std::pair<std::size_t, std::size_t>> segments;
};

void parse_linestring(std::string_view row, const std::string& where, Breaklines& b) {
    const std::size_t open = row.find('(');
    const std::size_t close = row.rfind(')');
    if (open == std::string_view::npos || close == std::string_view::npos || close < open) {
        fail(where + ": expected \"LINESTRING Z (x y z, ...)\"");
    }
    const std::string_view body = row.substr(open + 1, close - open - 1);
    std::size_t pos = 0;
    bool first = true;
    while (pos < body.size()) {
        double x = 0.0;
        double y = 0.0;
        double z = 0.0;
        if (!next_number(body, pos, x) || !next_number(body, pos, y)) {
            fail(where + ": bad coordinate");
        }
        (void)next_number(body, pos, z);  // Z is optional and unused
        if (!first) {
            b.segments.emplace_back(b.points.size() - 1, b.points.size());
        }
        b.points.emplace_back(x, y);
        first = false;
        while (pos < body.size() && (body[pos] == ' ' || body[pos] == ',')) {
            ++pos;
        }
    }
}

Breaklines read_wkt_csv(const std::string& path) {
    const std::string text = slurp(path);
    Breaklines b;
    std::size_t line_start = text.find('\n');  // skip the header row
    std::size_t line_no = 1;
    while (line_start != std::string::npos && line_start + 1 < text.size()) {
        ++line_start;
        std::size_t end = text.find('\n', line_start);
        const std::size_t stop = end == std::string::npos ? text.size() : end;
        ++line_no;
        const std::string_view row(text.data() + line_start, stop - line_start);
        if (row.find_first_not_of(" \t\r") != std::string_view::npos) {
            parse_linestring(row, path + ":" + std::to_string(line_no), b);
        }
        line_start = end;
    }
    return b;
}

double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

void print(const std::string& kind, std::size_t vertices, std::size_t faces, double seconds) {
    std::cout << "{\"engine\":\"cgal\",\"kind\":\"" << kind << "\",\"vertices\":" << vertices
              << ",\"faces\":" << faces << ",\"seconds\":" << seconds << "}" << std::endl;
}

}  // namespace

int main(int argc, char** argv) {
    std::string kind = "unknown";
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) {
        const std::string_view a = argv[i];
        if (a == "--kind" && i + 1 < argc) {
            kind = argv[++i];
        } else {
            files.emplace_back(a);
        }
    }
    if (files.empty() || files.size() > 2) {
        std::cerr << "usage: cgal_reference [--kind NAME] points.xyz [breaklines.csv]\n";
        return 2;
    }
    const std::vector<Point> points = read_xyz(files[0]);
    if (files.size() == 1) {
        const auto start = std::chrono::steady_clock::now();
        Dt dt;
        dt.insert(points.begin(), points.end());
        const double s = seconds_since(start);
        print(kind, dt.number_of_vertices(), dt.number_of_faces(), s);
        return 0;
    }
    const Breaklines b = read_wkt_csv(files[1]);
    const auto start = std::chrono::steady_clock::now();
    Cdt cdt;
    cdt.insert(points.begin(), points.end());
    cdt.insert_constraints(b.points.begin(), b.points.end(), b.segments.begin(), b.segments.end());
    const double s = seconds_since(start);
    print(kind, cdt.number_of_vertices(), cdt.number_of_faces(), s);
    return 0;
}
