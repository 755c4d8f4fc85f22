// SPDX-License-Identifier: MIT
// The methods lab's runs (dtm/lab/compare.hpp): for every distribution and size (ascending),
// every point set, every method, every repeat: time the registry function, keep its counters,
// the rise of the resident set and the triangles' corner angles. The test design follows the
// pseudo-triangulation thesis (001 ch. 4: uniform, gauss, cluster, arc; several sets, several
// runs, time / N, / N log N, / N^(4/3)); the historical column is 000 §3.10.9, Fig. 36.
#include "dtm/lab/compare.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <numbers>
#include <string>

#include "dtm/core/error.hpp"
#include "dtm/methods/registry.hpp"
#include "lab/machine.hpp"

namespace dtm::lab {
namespace {

using methods::MethodInfo;
using methods::Output;

double corner_angle(const Point3& prev, const Point3& at, const Point3& next) {
    const double ux = prev.x - at.x, uy = prev.y - at.y, vx = next.x - at.x, vy = next.y - at.y;
    // Interior angle of a counter-clockwise polygon at `at`, in [0, 360).
    double a = std::atan2(ux * vy - uy * vx, ux * vx + uy * vy) * 180.0 / std::numbers::pi;
    if (a < 0.0) a += 360.0;
    return 360.0 - a;
}

struct AngleAccumulator {
    AngleStats s;
    double min_sum = 0.0, max_sum = 0.0;
    void add_face(double lo, double hi) {
        const auto bin = [](double a) {
            return std::clamp(static_cast<int>(a / (180.0 / AngleStats::bins)), 0,
                              AngleStats::bins - 1);
        };
        if (s.faces == 0) {
            s.min_min = lo;
            s.max_max = hi;
        }
        ++s.faces;
        min_sum += lo;
        max_sum += hi;
        s.min_min = std::min(s.min_min, lo);
        s.max_max = std::max(s.max_max, hi);
        ++s.min_histogram[static_cast<std::size_t>(bin(lo))];
        ++s.max_histogram[static_cast<std::size_t>(bin(hi))];
    }
    AngleStats finish() {
        if (s.faces > 0) {
            s.min_mean = min_sum / double(s.faces);
            s.max_mean = max_sum / double(s.faces);
        }
        return s;
    }
};

void merge_angles(AngleStats& into, const AngleStats& add) {
    if (add.faces == 0) return;
    if (into.faces == 0) {
        into = add;
        return;
    }
    const double total = double(into.faces + add.faces);
    into.min_mean = (into.min_mean * double(into.faces) + add.min_mean * double(add.faces)) / total;
    into.max_mean = (into.max_mean * double(into.faces) + add.max_mean * double(add.faces)) / total;
    into.min_min = std::min(into.min_min, add.min_min);
    into.max_max = std::max(into.max_max, add.max_max);
    for (int i = 0; i < AngleStats::bins; ++i) {
        into.min_histogram[std::size_t(i)] += add.min_histogram[std::size_t(i)];
        into.max_histogram[std::size_t(i)] += add.max_histogram[std::size_t(i)];
    }
    into.faces += add.faces;
}

std::vector<const MethodInfo*> chosen_methods(const CompareOptions& options) {
    std::vector<const MethodInfo*> out;
    if (options.methods.empty()) {
        for (const MethodInfo& m : methods::registry()) {
            if (m.output != Output::all_triangulations) out.push_back(&m);
        }
        return out;
    }
    for (const std::string& name : options.methods) {
        const MethodInfo* m = methods::find_method(name);
        if (m == nullptr) {
            throw UsageError("methods compare: unknown method '" + name +
                             "' (dtm methods list shows them)");
        }
        out.push_back(m);
    }
    return out;
}

double work(std::size_t n) { return double(n) * std::log2(double(std::max<std::size_t>(n, 2))); }

/// The lab's state while it runs.
class Runner {
public:
    Runner(const CompareOptions& options, const Progress& progress)
        : options_(options), progress_(progress), methods_(chosen_methods(options)) {
        if (options_.distributions.empty()) {
            const auto lab = methods::lab_distributions();
            options_.distributions.assign(lab.begin(), lab.end());
        }
        std::sort(options_.sizes.begin(), options_.sizes.end());
        options_.sizes.erase(std::unique(options_.sizes.begin(), options_.sizes.end()),
                             options_.sizes.end());
        if (options_.sizes.empty()) throw UsageError("methods compare: no size given");
        if (options_.sets == 0 || options_.repeat == 0) {
            throw UsageError("methods compare: sets and repeat must be at least 1");
        }
        for (std::size_t n : options_.sizes) total_ += work(n) * double(methods_.size());
        total_ *= double(options_.distributions.size() * options_.sets * options_.repeat);
    }

    CompareResult run() {
        CompareResult result;
        result.machine = detail::machine_info();
        result.date = detail::utc_now();
        warm_up();
        for (const methods::Distribution dist : options_.distributions) {
            for (const std::size_t n : options_.sizes) {
                for (const MethodInfo* m : methods_) {
                    result.cells.push_back(cell(*m, dist, n, false));
                }
            }
        }
        historical(result);
        result.options = options_;
        progress_.report(1.0, "done");
        return result;
    }

private:
    CompareOptions options_;
    const Progress& progress_;
    std::vector<const MethodInfo*> methods_;
    double total_ = 0.0, done_ = 0.0;
    /// Per (method, distribution): the last measured size and mean time, for the cap.
    std::map<std::pair<std::string, std::string>, std::pair<std::size_t, double>> last_;

    Measurement cell(const MethodInfo& m, methods::Distribution dist, std::size_t n, bool history) {
        Measurement c;
        c.method = std::string(m.name);
        c.family = std::string(methods::family_name(m.family));
        c.quadratic = m.quadratic;
        c.distribution = std::string(methods::distribution_name(dist));
        c.n = n;
        c.historical_only = history;
        const double cell_work = work(n) * double(options_.sets * options_.repeat);
        const auto key = std::make_pair(c.method, c.distribution);
        if (m.quadratic && !history && last_.count(key) != 0) {
            const auto [n0, t0] = last_.at(key);
            const double ratio = double(n) / double(n0);
            const double estimate = t0 * ratio * ratio;
            if (estimate > options_.cap_seconds) {
                c.status = Status::capped;
                char text[160];
                std::snprintf(text, sizeof text,
                              "quadratic: estimated %.3g s from %.3g s at N = %zu (cap %.3g s)",
                              estimate, t0, n0, options_.cap_seconds);
                c.note = text;
                done_ += cell_work;
                return c;
            }
        }
        for (unsigned set = 0; set < options_.sets && c.status == Status::ok; ++set) {
            const std::vector<Point3> points =
                methods::generate_points(dist, n, options_.seed + set);
            AngleStats angles;
            for (unsigned run = 0; run < options_.repeat; ++run) {
                progress_.report(done_ / std::max(total_, 1.0),
                                 c.method + " " + c.distribution + " " + std::to_string(n));
                const Progress part = progress_.sub(done_ / std::max(total_, 1.0),
                                                    (done_ + work(n)) / std::max(total_, 1.0));
                if (!timed_run(m, points, c, run == 0 ? &angles : nullptr, part)) break;
                done_ += work(n);
            }
            merge_angles(c.angles, angles);
        }
        if (c.status == Status::ok && !c.seconds.empty()) {
            double sum = 0.0;
            c.min_seconds = c.seconds.front();
            for (double s : c.seconds) {
                sum += s;
                c.min_seconds = std::min(c.min_seconds, s);
            }
            c.mean_seconds = sum / double(c.seconds.size());
            if (!history) last_[key] = {n, c.mean_seconds};
        }
        return c;
    }

    /// One timed run; false when the method refused or failed (recorded in @p c).
    bool timed_run(const MethodInfo& m,
                   const std::vector<Point3>& points,
                   Measurement& c,
                   AngleStats* angles,
                   const Progress& part) {
        methods::MethodOptions mo;
        mo.threads = options_.threads;
        mo.seed = options_.seed;
        const std::size_t base = detail::start_peak_count();
        try {
            const auto start = std::chrono::steady_clock::now();
            methods::MethodResult r = m.run(methods::MethodInput{points, {}}, mo, part);
            const double seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            const std::size_t peak = detail::peak_resident();
            c.seconds.push_back(seconds);
            c.peak_rss_bytes = std::max(c.peak_rss_bytes, peak > base ? peak - base : 0);
            c.counters = std::move(r.counters);
            c.vertices = r.tin.vertices.size();
            c.triangles = r.tin.triangles.size();
            c.faces = r.faces.size();
            if (angles != nullptr && m.output != Output::all_triangulations)
                *angles = angle_stats(r);
            return true;
        } catch (const Cancelled&) {
            throw;
        } catch (const InputError& e) {
            c.status = Status::refused;
            c.note = e.what();
        } catch (const std::exception& e) {
            c.status = Status::failed;
            c.note = e.what();
        }
        return false;
    }

    /// One untimed run of every method on a few points, so that the first timed cell does not
    /// pay for thread pools, lazy initialisation and first page faults.
    void warm_up() {
        const std::vector<Point3> points =
            methods::generate_points(methods::Distribution::uniform, 256, 7);
        for (const MethodInfo* m : methods_) {
            methods::MethodOptions mo;
            mo.threads = options_.threads;
            try {
                (void)m->run(methods::MethodInput{points, {}}, mo, progress_.sub(0, 0));
            } catch (const Cancelled&) {
                throw;
            } catch (const std::exception&) {
                // refusals show in the timed cells
            }
        }
    }

    void historical(CompareResult& result) {
        if (!options_.historical) return;
        const MethodInfo* grid = nullptr;
        for (const MethodInfo* m : methods_) {
            if (m->name == "uniform-grid") grid = m;
        }
        const auto& dists = options_.distributions;
        if (grid == nullptr ||
            std::find(dists.begin(), dists.end(), methods::Distribution::uniform) == dists.end()) {
            return;
        }
        for (const HistoricalTiming& row : thesis_fig36()) {
            if (std::find(options_.sizes.begin(), options_.sizes.end(), row.n) !=
                options_.sizes.end()) {
                continue;  // measured with the main runs
            }
            result.cells.push_back(cell(*grid, methods::Distribution::uniform, row.n, true));
        }
    }
};

}  // namespace

const std::vector<HistoricalTiming>& thesis_fig36() {
    // Exact copy of the thesis' table (seconds; multiples of the DOS tick 1/18.2 s except
    // 0.504396, its erratum 13).
    static const std::vector<HistoricalTiming> table{
        {100, 0.054945, 0.054945}, {200, 0.054945, 0.21978},   {300, 0.054945, 0.32967},
        {400, 0.054945, 0.43956},  {500, 0.10989, 0.504396},   {1000, 0.164835, 1.318681},
        {1500, 0.21978, 2.032967}, {2000, 0.384615, 2.857143}, {2500, 0.43956, 3.736264},
        {3000, 0.494505, 4.56044}, {3500, 0.549451, 5.274725}, {4000, 0.604396, 6.208791},
    };
    return table;
}

AngleStats angle_stats(const methods::MethodResult& result) {
    AngleAccumulator acc;
    const std::vector<Point3>& v = result.tin.vertices;
    if (!result.faces.empty()) {
        for (const auto& face : result.faces) {
            double lo = 360.0, hi = 0.0;
            const std::size_t k = face.size();
            for (std::size_t i = 0; i < k; ++i) {
                const double a =
                    corner_angle(v[face[(i + k - 1) % k]], v[face[i]], v[face[(i + 1) % k]]);
                if (a >= 180.0) continue;  // not a corner
                lo = std::min(lo, a);
                hi = std::max(hi, a);
            }
            if (hi > 0.0) acc.add_face(lo, hi);
        }
        return acc.finish();
    }
    for (const Triangle& t : result.tin.triangles) {
        double lo = 180.0, hi = 0.0;
        for (int i = 0; i < 3; ++i) {
            const double a = corner_angle(v[t.v[(i + 2) % 3]], v[t.v[i]], v[t.v[(i + 1) % 3]]);
            lo = std::min(lo, a);
            hi = std::max(hi, a);
        }
        acc.add_face(lo, hi);
    }
    return acc.finish();
}

CompareResult run_compare(const CompareOptions& options, const Progress& progress) {
    return Runner(options, progress).run();
}

std::string_view status_name(Status status) {
    switch (status) {
        case Status::ok:
            return "ok";
        case Status::capped:
            return "capped";
        case Status::refused:
            return "refused";
        case Status::failed:
            return "failed";
    }
    return "?";
}

}  // namespace dtm::lab
