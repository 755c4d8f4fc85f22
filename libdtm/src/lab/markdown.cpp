// SPDX-License-Identifier: MIT
// report.md of the methods lab (report_detail.hpp): what ran where, the scaling summary per
// method (the table docs/performance.md quotes), one table per distribution, the thesis' grid
// timings next to today's, the plots.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "dtm/methods/registry.hpp"
#include "lab/report_detail.hpp"

namespace dtm::lab::detail {
namespace {

std::string fmt(double v, const char* format = "%.3g") {
    if (!std::isfinite(v)) return "–";
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, v);
    return buffer;
}

std::string count(std::uint64_t v) {
    if (v == 0) return "0";
    if (v < 100000) return std::to_string(v);
    return fmt(double(v), "%.3g");
}

std::string power_of_ten(std::size_t n) {
    const double e = std::log10(double(n));
    if (n >= 1000 && std::abs(e - std::round(e)) < 1e-12)
        return "10^" + std::to_string(int(std::round(e)));
    return std::to_string(n);
}

std::vector<std::string> method_order(const CompareResult& r) {
    std::vector<std::string> out;
    for (const Measurement& c : r.cells) {
        if (std::find(out.begin(), out.end(), c.method) == out.end()) out.push_back(c.method);
    }
    return out;
}

const Measurement* find(const CompareResult& r,
                        const std::string& m,
                        const std::string& d,
                        std::size_t n) {
    for (const Measurement& c : r.cells) {
        if (c.method == m && c.distribution == d && c.n == n && !c.historical_only) return &c;
    }
    return nullptr;
}

void header(std::ostringstream& out, const CompareResult& r) {
    const CompareOptions& o = r.options;
    out << "# Triangulation methods compared (`dtm methods compare`)\n\n";
    out << "- Date (UTC): " << r.date << "\n";
    out << "- Machine: " << (r.machine.cpu.empty() ? "unknown CPU" : r.machine.cpu) << ", "
        << r.machine.cores << " logical cores"
        << (r.machine.caches.empty() ? "" : "; caches " + r.machine.caches) << "\n";
    out << "- Sizes:";
    for (std::size_t n : o.sizes) out << " " << n;
    out << "; distributions:";
    for (const auto d : o.distributions) out << " " << methods::distribution_name(d);
    out << "\n- Each cell: " << o.sets << " point set(s) x " << o.repeat << " run(s), seed "
        << o.seed << ", " << o.threads
        << " thread(s) for the parallel methods; quadratic methods capped at an"
        << " estimated " << fmt(o.cap_seconds) << " s\n\n";
    out << "Times are wall-clock seconds of the method call alone (the points are generated "
           "before),"
           " the mean of a cell's runs. time/(N log N) uses log2 N; the CSV also has log10 N (the"
           " unit of the pseudo-triangulation thesis' tables) and N^(4/3). Memory is the largest"
           " rise of the process's resident set during a run, per point: the method's own"
           " structures and its result (the Tin, and the diagram of a Voronoi method). Angles are"
           " the faces' smallest and largest corner angles in degrees, averaged over the "
           "faces.\n\n";
}

/// The scaling summary: the table of issue 11's speed and memory figures.
void summary(std::ostringstream& out, const CompareResult& r, const std::string& dist) {
    const auto& sizes = r.options.sizes;
    out << "## Scaling summary (" << dist << ")\n\n";
    out << "time/(N log2 N) in ns at each N; *spread* is its largest over its smallest value (the"
           " O(N log N) claim holds within a factor 2 when it is at most 2); for uniform-grid also"
           " the spread of time/N; *x dc* compares the time at the largest N the method reached"
           " with dc's there; B/pt is the largest resident rise per point.\n\n";
    out << "| method | claimed |";
    for (std::size_t n : sizes) out << " N = " << power_of_ten(n) << " |";
    out << " spread | time/N spread | largest N | time [s] | x dc | B/pt |\n|---|---|";
    for (std::size_t i = 0; i < sizes.size(); ++i) out << "---:|";
    out << "---:|---:|---:|---:|---:|---:|\n";
    for (const std::string& m : method_order(r)) {
        const methods::MethodInfo* info = methods::find_method(m);
        out << "| " << m << " | " << (info ? std::string(info->complexity) : "") << " |";
        double lo = INFINITY, hi = 0, lo_n = INFINITY, hi_n = 0, bpp = 0;
        const Measurement* last = nullptr;
        for (std::size_t n : sizes) {
            const Measurement* c = find(r, m, dist, n);
            if (c == nullptr || c->status != Status::ok) {
                out << " " << (c ? std::string(status_name(c->status)) : "–") << " |";
                continue;
            }
            const Rates rt = rates(*c);
            out << " " << fmt(rt.per_nlogn * 1e9) << " |";
            lo = std::min(lo, rt.per_nlogn);
            hi = std::max(hi, rt.per_nlogn);
            lo_n = std::min(lo_n, rt.per_n);
            hi_n = std::max(hi_n, rt.per_n);
            bpp = std::max(bpp, rt.bytes_per_point);
            last = c;
        }
        out << " " << (hi > 0 ? fmt(hi / lo, "%.2f") : "–") << " | "
            << (m == "uniform-grid" && hi_n > 0 ? fmt(hi_n / lo_n, "%.2f") : "") << " | ";
        if (last != nullptr) {
            const Measurement* dc = find(r, "dc", dist, last->n);
            out << power_of_ten(last->n) << " | " << fmt(last->mean_seconds) << " | "
                << (dc && dc->status == Status::ok
                        ? fmt(last->mean_seconds / dc->mean_seconds, "%.2f")
                        : "–")
                << " | " << fmt(bpp, "%.0f") << " |\n";
        } else {
            out << "– | – | – | – |\n";
        }
    }
    out << "\n";
}

void table(std::ostringstream& out, const CompareResult& r, const std::string& dist) {
    out << "## " << dist
        << "\n\n| method | N | status | time [s] | time/N [us] | time/(N log2 N) [ns] |"
           " time/N^(4/3) [ns] | orient | incircle | flips | walk | B/pt | triangles | min angle |"
           " max angle "
           "|\n|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    std::vector<std::string> notes;
    for (const std::string& m : method_order(r)) {
        for (std::size_t n : r.options.sizes) {
            const Measurement* c = find(r, m, dist, n);
            if (c == nullptr) continue;
            out << "| " << m << " | " << n << " | " << status_name(c->status);
            if (c->status != Status::ok) {
                notes.push_back(m + " at N = " + std::to_string(n) + ": " + c->note);
                out << " [" << notes.size() << "] | | | | | | | | | | | | |\n";
                continue;
            }
            const Rates rt = rates(*c);
            const bool faces = c->angles.faces > 0;
            out << " | " << fmt(c->mean_seconds, "%.4g") << " | " << fmt(rt.per_n * 1e6) << " | "
                << fmt(rt.per_nlogn * 1e9) << " | " << fmt(rt.per_n43 * 1e9) << " | "
                << count(c->counters.orient_calls) << " | " << count(c->counters.incircle_calls)
                << " | " << count(c->counters.flips) << " | " << count(c->counters.walk_steps)
                << " | " << fmt(rt.bytes_per_point, "%.0f") << " | "
                << (c->faces ? c->faces : c->triangles) << " | "
                << (faces ? fmt(c->angles.min_mean, "%.1f") : "–") << " | "
                << (faces ? fmt(c->angles.max_mean, "%.1f") : "–") << " |\n";
        }
    }
    out << "\n";
    for (std::size_t i = 0; i < notes.size(); ++i)
        out << "[" << i + 1 << "] " << notes[i] << "\n\n";
}

void historical(std::ostringstream& out, const CompareResult& r) {
    bool any = false;
    for (const Measurement& c : r.cells)
        any = any || (c.method == "uniform-grid" && c.distribution == "uniform");
    if (!any) return;
    out << "## The thesis' grid timings next to today's uniform-grid\n\n"
           "000 §3.10.9, Fig. 36: random points, the thesis' DTUG.EXE (Borland C++ 3.1) on a "
           "486/DX2"
           " 66 MHz under MS-DOS 6.22, timed in DOS ticks of 1/18.2 s (0.504396 is off that grid:"
           " the thesis' erratum). Today: uniform-grid on uniform points, this machine.\n\n"
           "| N | grid [s] (1996) | triangulation [s] (1996) | total [s] (1996) | uniform-grid [s] "
           "| speed-up |\n"
           "|---:|---:|---:|---:|---:|---:|\n";
    for (const HistoricalTiming& h : thesis_fig36()) {
        const Measurement* today = nullptr;
        for (const Measurement& c : r.cells) {
            if (c.method == "uniform-grid" && c.distribution == "uniform" && c.n == h.n) today = &c;
        }
        const double total = h.grid_seconds + h.triangulation_seconds;
        const bool ok = today && today->status == Status::ok;
        out << "| " << h.n << " | " << h.grid_seconds << " | " << h.triangulation_seconds << " | "
            << fmt(total, "%.6g") << " | " << (ok ? fmt(today->mean_seconds, "%.3g") : "–") << " | "
            << (ok && today->mean_seconds > 0 ? fmt(total / today->mean_seconds, "%.0f") : "–")
            << " |\n";
    }
    out << "\n";
}

}  // namespace

std::string markdown(const CompareResult& result, const std::vector<std::string>& plots) {
    std::ostringstream out;
    header(out, result);
    std::vector<std::string> dists;
    for (const auto d : result.options.distributions)
        dists.emplace_back(methods::distribution_name(d));
    const std::string main =
        std::find(dists.begin(), dists.end(), "uniform") != dists.end() ? "uniform" : dists.front();
    summary(out, result, main);
    for (const std::string& d : dists) table(out, result, d);
    historical(out, result);
    if (!plots.empty()) {
        out << "## Plots\n\nEach as PNG and SVG in plots/.\n\n";
        for (const std::string& p : plots) out << "![" << p << "](" << p << ")\n\n";
    }
    return out.str();
}

}  // namespace dtm::lab::detail
