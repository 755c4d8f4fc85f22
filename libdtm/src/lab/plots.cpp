// SPDX-License-Identifier: MIT
// The lab's plots (report_detail.hpp), drawn with dtm/io/draw/chart.hpp, each as PNG and SVG:
// per distribution, time / (N log2 N) against N on log axes, one line per method (flat means
// N log N); per distribution and method, the histograms of the faces' smallest and largest
// corner angles at the histogram size.
#include <algorithm>
#include <map>
#include <string>

#include "dtm/io/draw/chart.hpp"
#include "lab/report_detail.hpp"

namespace dtm::lab::detail {
namespace {

using io::draw::Bars;
using io::draw::Chart;
using io::draw::Color;
using io::draw::Series;

Color palette(std::size_t i) {
    static const std::uint32_t colours[] = {0x1f77b4, 0xff7f0e, 0x2ca02c, 0xd62728, 0x9467bd,
                                            0x8c564b, 0xe377c2, 0x7f7f7f, 0xbcbd22, 0x17becf};
    return Color::rgb(colours[i % std::size(colours)]);
}

void both(const Chart& chart,
          const std::filesystem::path& dir,
          const std::string& stem,
          std::vector<std::string>& names) {
    io::draw::write_chart(chart, dir / (stem + ".png"));
    io::draw::write_chart(chart, dir / (stem + ".svg"));
    names.push_back("plots/" + stem + ".png");
}

std::string file_safe(std::string s) {
    for (char& c : s) {
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_') c = '_';
    }
    return s;
}

std::size_t histogram_size(const CompareOptions& o) {
    std::size_t best = 0;
    for (std::size_t n : o.sizes) {
        if (n <= o.histogram_size) best = std::max(best, n);
    }
    return best != 0 ? best : *std::min_element(o.sizes.begin(), o.sizes.end());
}

}  // namespace

std::vector<std::string> write_plots(const CompareResult& result,
                                     const std::filesystem::path& dir) {
    std::vector<std::string> names;
    for (const methods::Distribution d : result.options.distributions) {
        const std::string dist(methods::distribution_name(d));
        Chart chart;
        chart.title = "time / (N log2 N), " + dist + " points";
        chart.x = {"N (points)", true, {}, {}};
        chart.y = {"ns per N log2 N", true, {}, {}};
        std::map<std::string, Series> by_method;
        std::vector<std::string> order;
        for (const Measurement& c : result.cells) {
            if (c.distribution != dist || c.historical_only || c.status != Status::ok) continue;
            const Rates r = rates(c);
            if (!(r.per_nlogn > 0.0)) continue;
            if (by_method.count(c.method) == 0) order.push_back(c.method);
            by_method[c.method].points.push_back({double(c.n), r.per_nlogn * 1e9});
        }
        for (std::size_t i = 0; i < order.size(); ++i) {
            Series s = by_method[order[i]];
            s.name = order[i];
            s.color = palette(i);
            chart.series.push_back(std::move(s));
        }
        if (!chart.series.empty()) both(chart, dir, "scaling_" + file_safe(dist), names);

        const std::size_t hn = histogram_size(result.options);
        for (const Measurement& c : result.cells) {
            if (c.distribution != dist || c.n != hn || c.historical_only ||
                c.status != Status::ok || c.angles.faces == 0) {
                continue;
            }
            Chart h;
            h.title = c.method + ": corner angles, " + dist + " N = " + std::to_string(hn);
            h.x = {"angle (degrees)", false, 0.0, 180.0};
            h.y = {"faces", false, 0.0, {}};
            Bars lo, hi;
            lo.name = "smallest angle of each face";
            hi.name = "largest angle of each face";
            lo.color = Color::rgb(0x1f77b4, 0.7);
            hi.color = Color::rgb(0xff7f0e, 0.7);
            for (int b = 0; b <= AngleStats::bins; ++b) {
                const double edge = b * 180.0 / AngleStats::bins;
                lo.edges.push_back(edge);
                hi.edges.push_back(edge);
            }
            for (int b = 0; b < AngleStats::bins; ++b) {
                lo.counts.push_back(double(c.angles.min_histogram[std::size_t(b)]));
                hi.counts.push_back(double(c.angles.max_histogram[std::size_t(b)]));
            }
            h.bars = {lo, hi};
            both(h, dir,
                 "angles_" + file_safe(dist) + "_" + std::to_string(hn) + "_" + file_safe(c.method),
                 names);
        }
    }
    return names;
}

}  // namespace dtm::lab::detail
