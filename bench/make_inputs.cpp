// SPDX-License-Identifier: MIT
// make_inputs: deterministic benchmark inputs for bench/compare_cgal.sh.
//
//   make_inputs --kind uniform|gaussian|clustered|breaklines|grid [--n N] [--seed S] --out DIR
//
// Writes DIR/points.xyz (text "x y z" per line, shortest round-trip doubles) with S-JTSK-like
// coordinates (around -750000, -1050000, about one point per square metre), and for
// --kind breaklines also DIR/breaklines.csv: a header "wkt,id" and one
// "LINESTRING Z (x y z, ...)",id per row, readable by GDAL's CSV driver (GDAL 3.6 does not
// open a CSV file with a single column, hence the id). The breaklines are many
// long west-east polylines whose jitter stays below 0.3 of their spacing, so they never
// cross or touch; together they have about N / 2 segments. --kind grid writes a 1 m lattice
// (integer coordinates, so every cell is exactly cocircular: the predicates' exact path).
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace {

constexpr double x0 = -750000.0;
constexpr double y0 = -1050000.0;

struct Args {
    std::string kind = "uniform";
    std::int64_t n = 1000000;
    std::uint64_t seed = 1;
    std::filesystem::path out;
};

[[noreturn]] void usage(const std::string& why) {
    std::cerr << "make_inputs: " << why
              << "\nusage: make_inputs --kind uniform|gaussian|clustered|breaklines|grid [--n N] "
                 "[--seed S] --out DIR\n";
    std::exit(2);
}

Args parse(int argc, char** argv) {
    Args a;
    for (int i = 1; i < argc; ++i) {
        const std::string_view key = argv[i];
        if (i + 1 >= argc) {
            usage("missing value after " + std::string(key));
        }
        const std::string value = argv[++i];
        if (key == "--kind") {
            a.kind = value;
        } else if (key == "--n") {
            a.n = std::stoll(value);
        } else if (key == "--seed") {
            a.seed = std::stoull(value);
        } else if (key == "--out") {
            a.out = value;
        } else {
            usage("unknown option " + std::string(key));
        }
    }
    if (a.out.empty()) {
        usage("--out is required");
    }
    if (a.n < 3) {
        usage("--n must be at least 3");
    }
    if (a.kind != "uniform" && a.kind != "gaussian" && a.kind != "clustered" &&
        a.kind != "breaklines" && a.kind != "grid") {
        usage("unknown kind " + a.kind);
    }
    return a;
}

/// A smooth hilly surface in metres, so z is plausible terrain.
double terrain(double x, double y) {
    return 300.0 + 20.0 * std::sin(x / 150.0) * std::cos(y / 210.0) + 0.01 * (x - x0) * 0.05;
}

/// Appends the shortest round-trip text of v.
void put(std::string& s, double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    s.append(buf, r.ptr);
}

struct Sampler {
    std::mt19937_64 rng;
    double side;  ///< square extent in metres

    double uniform() { return std::uniform_real_distribution<double>(0.0, side)(rng); }
    double normal(double mean, double sigma) {
        return std::normal_distribution<double>(mean, sigma)(rng);
    }
};

void write_points(const Args& a, Sampler& s) {
    std::vector<double> centres;
    if (a.kind == "clustered") {
        for (int i = 0; i < 100; ++i) {
            centres.push_back(s.uniform());
            centres.push_back(s.uniform());
        }
    }
    std::ofstream f(a.out / "points.xyz", std::ios::binary);
    std::string line;
    std::string chunk;
    for (std::int64_t i = 0; i < a.n; ++i) {
        double x = 0.0;
        double y = 0.0;
        if (a.kind == "gaussian") {
            x = s.normal(s.side / 2, s.side / 6);
            y = s.normal(s.side / 2, s.side / 6);
        } else if (a.kind == "grid") {  // 1 m lattice: every cell is exactly cocircular
            const auto side = static_cast<std::int64_t>(s.side);
            x = static_cast<double>(i % side);
            y = static_cast<double>(i / side);
        } else if (a.kind == "clustered" && i % 10 != 0) {  // 10 % uniform background
            const auto c = 2 * static_cast<std::size_t>(s.rng() % (centres.size() / 2));
            x = s.normal(centres[c], s.side / 80);
            y = s.normal(centres[c + 1], s.side / 80);
        } else {
            x = s.uniform();
            y = s.uniform();
        }
        x += x0;
        y += y0;
        put(chunk, x);
        chunk += ' ';
        put(chunk, y);
        chunk += ' ';
        put(chunk, terrain(x, y));
        chunk += '\n';
        if (chunk.size() > (1U << 20)) {
            f << chunk;
            chunk.clear();
        }
    }
    f << chunk;
    if (!f) {
        std::cerr << "make_inputs: cannot write " << (a.out / "points.xyz") << '\n';
        std::exit(1);
    }
}

/// About n / 2 segments in sqrt(n / 2) / 2 lines, each spanning the whole extent.
void write_breaklines(const Args& a, Sampler& s) {
    const auto segments = a.n / 2;
    const auto lines = std::max<std::int64_t>(
        1, static_cast<std::int64_t>(std::sqrt(static_cast<double>(segments)) / 2));
    const std::int64_t per_line = std::max<std::int64_t>(1, segments / lines);
    const double spacing = s.side / static_cast<double>(lines);
    const double step = s.side / static_cast<double>(per_line);
    std::uniform_real_distribution<double> jitter(-0.3, 0.3);
    std::ofstream f(a.out / "breaklines.csv", std::ios::binary);
    f << "wkt,id\n";  // GDAL 3.6's CSV driver does not open a one-column file
    std::string row;
    for (std::int64_t l = 0; l < lines; ++l) {
        const double base = (static_cast<double>(l) + 0.5) * spacing;
        row = "\"LINESTRING Z (";
        for (std::int64_t k = 0; k <= per_line; ++k) {
            const double x = x0 + static_cast<double>(k) * step + 0.25 * step * jitter(s.rng);
            const double y = y0 + base + spacing * jitter(s.rng);
            if (k > 0) {
                row += ", ";
            }
            put(row, x);
            row += ' ';
            put(row, y);
            row += ' ';
            put(row, terrain(x, y));
        }
        row += ")\",";
        row += std::to_string(l + 1);
        row += '\n';
        f << row;
    }
    if (!f) {
        std::cerr << "make_inputs: cannot write " << (a.out / "breaklines.csv") << '\n';
        std::exit(1);
    }
}

}  // namespace

int main(int argc, char** argv) {
    const Args a = parse(argc, argv);
    std::filesystem::create_directories(a.out);
    Sampler s{std::mt19937_64(a.seed), std::sqrt(static_cast<double>(a.n))};
    write_points(a, s);
    if (a.kind == "breaklines") {
        write_breaklines(a, s);
    }
    return 0;
}
