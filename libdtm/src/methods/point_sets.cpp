// SPDX-License-Identifier: MIT
// Point sets of the methods lab (dtm/methods/point_sets.hpp). Only IEEE basic operations are
// used for x and y (no libm), so a set is the same bit for bit on every platform: splitmix64
// random numbers, Irwin-Hall sums of 12 uniforms for the normal distributions, rejection
// sampling for the annulus. The circle family takes integer points exactly on one circle
// (x^2 + y^2 = R^2 with R a product of primes 1 mod 4, from their Gaussian-integer factors),
// scaled by a power of two so that they stay exactly cocircular.
#include "dtm/methods/point_sets.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

namespace dtm::methods {
namespace {

class Random {
public:
    explicit Random(std::uint64_t seed)
        : state_(seed * 0x9e3779b97f4a7c15ull + 0x632be59bd9b4e019ull) {}
    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, 1).
    double uniform() { return static_cast<double>(next() >> 11) * 0x1p-53; }
    /// Approximately standard normal: the Irwin-Hall sum of 12 uniforms minus 6.
    double normal() {
        double s = 0.0;
        for (int i = 0; i < 12; ++i) s += uniform();
        return s - 6.0;
    }
    std::size_t below(std::size_t n) { return static_cast<std::size_t>(next() % n); }

private:
    std::uint64_t state_;
};

double terrain_z(double u, double v) { return 300.0 + 0.01 * u - 0.02 * v + 2e-5 * u * v; }

Point3 make_point(double u, double v, const PointSetOptions& o, bool quantize) {
    double x = o.x0 + u;
    double y = o.y0 + v;
    if (quantize && o.quantum > 0.0) {
        x = std::round(x / o.quantum) * o.quantum;
        y = std::round(y / o.quantum) * o.quantum;
    }
    return {x, y, terrain_z(x - o.x0, y - o.y0)};
}

template <class T>
void shuffle(std::vector<T>& v, Random& rng) {
    for (std::size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[rng.below(i)]);
}

/// Rounds down to a multiple of 2^-10: lattice steps whose multiples stay exact.
double dyadic(double v) { return std::floor(v * 1024.0) / 1024.0; }

std::vector<Point3> uniform(std::size_t n, Random& rng, const PointSetOptions& o) {
    std::vector<Point3> pts(n);
    for (Point3& p : pts) {
        const double u = rng.uniform() * o.size;
        p = make_point(u, rng.uniform() * o.size, o, true);
    }
    return pts;
}

/// Normal around (cu, cv) with deviation sigma, resampled until inside the square.
Point3 normal_point(double cu, double cv, double sigma, Random& rng, const PointSetOptions& o) {
    for (;;) {
        const double u = cu + sigma * rng.normal();
        const double v = cv + sigma * rng.normal();
        if (u >= 0.0 && u < o.size && v >= 0.0 && v < o.size) return make_point(u, v, o, true);
    }
}

std::vector<Point3> gauss(std::size_t n, Random& rng, const PointSetOptions& o) {
    std::vector<Point3> pts(n);
    for (Point3& p : pts) p = normal_point(o.size / 2, o.size / 2, o.size / 6, rng, o);
    return pts;
}

std::vector<Point3> cluster(std::size_t n, Random& rng, const PointSetOptions& o) {
    constexpr int clusters = 8;
    std::array<std::pair<double, double>, clusters> centre{};
    for (auto& c : centre) {
        const double u = (0.1 + 0.8 * rng.uniform()) * o.size;
        c = {u, (0.1 + 0.8 * rng.uniform()) * o.size};
    }
    std::vector<Point3> pts(n);
    for (Point3& p : pts) {
        if (rng.uniform() < 0.1) {
            const double u = rng.uniform() * o.size;
            p = make_point(u, rng.uniform() * o.size, o, true);
        } else {
            const auto& c = centre[rng.below(clusters)];
            p = normal_point(c.first, c.second, o.size / 50, rng, o);
        }
    }
    return pts;
}

std::vector<Point3> arc(std::size_t n, Random& rng, const PointSetOptions& o) {
    // Upper half of the annulus 0.47 size <= r <= 0.5 size around the square's bottom centre
    // line, by rejection from its bounding box.
    const double r1 = 0.5 * o.size;
    const double r0 = 0.47 * o.size;
    std::vector<Point3> pts(n);
    for (Point3& p : pts) {
        for (;;) {
            const double u = (2.0 * rng.uniform() - 1.0) * r1;
            const double v = rng.uniform() * r1;
            const double rr = u * u + v * v;
            if (rr >= r0 * r0 && rr <= r1 * r1) {
                p = make_point(o.size / 2 + u, 0.25 * o.size + v, o, true);
                break;
            }
        }
    }
    return pts;
}

std::vector<Point3> grid(std::size_t n, Random& rng, const PointSetOptions& o) {
    const auto cols = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
    const double step = dyadic(o.size / static_cast<double>(std::max<std::size_t>(cols, 1)));
    std::vector<Point3> pts;
    pts.reserve(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double u = static_cast<double>(k % cols) * step;
        pts.push_back(make_point(u, static_cast<double>(k / cols) * step, o, false));
    }
    shuffle(pts, rng);
    return pts;
}

std::vector<Point3> collinear(std::size_t n, Random& rng, const PointSetOptions& o) {
    // Half of the lines horizontal, half diagonal (slope 1); positions on a 2^-10 lattice.
    const std::size_t lines =
        std::max<std::size_t>(2, static_cast<std::size_t>(std::sqrt(static_cast<double>(n)) / 4));
    std::set<std::pair<double, double>> seen;
    std::vector<Point3> pts;
    pts.reserve(n);
    while (pts.size() < n) {
        const std::size_t line = pts.size() % lines;
        const double offset = dyadic((static_cast<double>(line / 2) + 0.5) * o.size /
                                     static_cast<double>((lines + 1) / 2));
        const double t = dyadic(rng.uniform() * o.size);
        double u = t;
        double v = offset;
        if (line % 2 == 1) v = t - offset + o.size / 2;  // the diagonal v = u + c
        if (v < 0.0 || v >= o.size) continue;
        if (!seen.insert({u, v}).second) continue;
        pts.push_back(make_point(u, v, o, false));
    }
    shuffle(pts, rng);
    return pts;
}

std::vector<Point3> duplicates(std::size_t n, Random& rng, const PointSetOptions& o) {
    std::vector<Point3> pts = uniform(n, rng, o);
    for (std::size_t i = 1; i < n; ++i) {
        if (rng.below(3) == 0) {
            const Point3& earlier = pts[rng.below(i)];
            pts[i] = {earlier.x, earlier.y, earlier.z + 1.0};
        }
    }
    return pts;
}

// ---- circle: Gaussian integers ----------------------------------------------------------

struct Gaussian {
    std::int64_t re = 1;
    std::int64_t im = 0;
};
Gaussian operator*(Gaussian a, Gaussian b) {
    return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re};
}

/// R = 5^3 * 13 * 17 * 29 * 37 * 41 = 1 215 306 625 < 2^31. Each prime p = a^2 + b^2 with
/// exponent e contributes 2e + 1 choices, so x^2 + y^2 = R^2 has 4 * 7 * 3^5 = 6804 solutions.
struct PrimeFactor {
    std::int64_t a;
    std::int64_t b;
    int exponent;
};
constexpr std::array<PrimeFactor, 6> circle_primes{
    {{1, 2, 3}, {2, 3, 1}, {1, 4, 1}, {2, 5, 1}, {1, 6, 1}, {4, 5, 1}}};

std::vector<std::pair<std::int64_t, std::int64_t>> circle_lattice_points() {
    std::vector<Gaussian> zs{Gaussian{}};
    for (const PrimeFactor& f : circle_primes) {
        const Gaussian w{f.a, f.b};
        const Gaussian wbar{f.a, -f.b};
        std::vector<Gaussian> next;
        for (const Gaussian z : zs) {
            for (int k = 0; k <= 2 * f.exponent; ++k) {
                Gaussian t = z;
                for (int i = 0; i < k; ++i) t = t * w;
                for (int i = k; i < 2 * f.exponent; ++i) t = t * wbar;
                next.push_back(t);
            }
        }
        zs = std::move(next);
    }
    std::vector<std::pair<std::int64_t, std::int64_t>> out;
    for (const Gaussian z : zs) {
        out.emplace_back(z.re, z.im);
        out.emplace_back(-z.im, z.re);
        out.emplace_back(-z.re, -z.im);
        out.emplace_back(z.im, -z.re);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

std::vector<Point3> circle(std::size_t n, Random& rng, const PointSetOptions& o) {
    auto lattice = circle_lattice_points();
    if (n > lattice.size()) {
        throw std::invalid_argument("circle: at most " + std::to_string(lattice.size()) +
                                    " points, asked for " + std::to_string(n));
    }
    shuffle(lattice, rng);
    // A power of two scales the radius R ~ 1.2e9 to at most a quarter of the square's side.
    int e = 0;
    (void)std::frexp(0.25 * o.size / 1215306625.0, &e);
    const double scale = std::ldexp(1.0, e - 1);
    const double cu = std::floor(o.size / 2);
    std::vector<Point3> pts;
    pts.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double u = cu + static_cast<double>(lattice[i].first) * scale;
        pts.push_back(make_point(u, cu + static_cast<double>(lattice[i].second) * scale, o, false));
    }
    return pts;
}

constexpr std::array kAll{Distribution::uniform,   Distribution::gauss,     Distribution::cluster,
                          Distribution::arc,       Distribution::grid,      Distribution::circle,
                          Distribution::collinear, Distribution::duplicates};

}  // namespace

std::vector<Point3> generate_points(Distribution distribution,
                                    std::size_t n,
                                    std::uint64_t seed,
                                    const PointSetOptions& options) {
    Random rng(seed);
    switch (distribution) {
        case Distribution::uniform:
            return uniform(n, rng, options);
        case Distribution::gauss:
            return gauss(n, rng, options);
        case Distribution::cluster:
            return cluster(n, rng, options);
        case Distribution::arc:
            return arc(n, rng, options);
        case Distribution::grid:
            return grid(n, rng, options);
        case Distribution::circle:
            return circle(n, rng, options);
        case Distribution::collinear:
            return collinear(n, rng, options);
        case Distribution::duplicates:
            return duplicates(n, rng, options);
    }
    return {};
}

std::size_t max_circle_points() { return 6804; }

std::string_view distribution_name(Distribution distribution) {
    switch (distribution) {
        case Distribution::uniform:
            return "uniform";
        case Distribution::gauss:
            return "gauss";
        case Distribution::cluster:
            return "cluster";
        case Distribution::arc:
            return "arc";
        case Distribution::grid:
            return "grid";
        case Distribution::circle:
            return "circle";
        case Distribution::collinear:
            return "collinear";
        case Distribution::duplicates:
            return "duplicates";
    }
    return "?";
}

std::optional<Distribution> parse_distribution(std::string_view name) {
    for (const Distribution d : kAll) {
        if (distribution_name(d) == name) return d;
    }
    return std::nullopt;
}

std::span<const Distribution> all_distributions() { return kAll; }

std::span<const Distribution> lab_distributions() { return std::span(kAll).first(4); }

}  // namespace dtm::methods
