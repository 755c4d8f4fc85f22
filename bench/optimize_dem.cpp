// SPDX-License-Identifier: MIT
// DEM error of `--optimize CRITERION` against a known truth (docs/performance.md,
// docs/optimize.md).
//
//   optimize_dem sample SAMPLE_DIR [CELL]          the bundled survey (samples/sjtsk) with its
//                                                  breaklines, boundary and building; truth = the
//                                                  analytic terrain of tools/dtm-sample
//   optimize_dem raster DEM.tif FRACTION SEEDS     a real DEM: a random FRACTION of its cells as
//                                                  survey points, the other cells as truth
//   optimize_dem table FILE.csv STEP FRACTION SEEDS  a grid given as a CSV matrix (R's volcano)
//
// For every criterion: the TIN (dtm::triangulate with TriangulateOptions::optimize), rasterised
// at the truth's cell centres (dtm::rasterize), compared where both have a value: RMSE, mean
// absolute error, 95th percentile and maximum of |error|, the flips and the seconds. One line
// per criterion, a markdown table, RMSE also relative to the Delaunay TIN's of the same run.
#include <gdal_priv.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "dtm/algo/criteria.hpp"
#include "dtm/algo/rasterize.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/io/inputs.hpp"
#include "sample_terrain.hpp"

namespace {

using namespace dtm;

struct Truth {
    GridSpec spec;
    std::vector<double> z;  ///< per cell, NaN where unknown
};

struct Errors {
    double rmse = 0, mae = 0, p95 = 0, max = 0;
    std::size_t cells = 0;
};

Errors compare(const Tin& tin, const Truth& truth) {
    RasterizeOptions ro;
    ro.nodata = -9999.0F;
    const Grid g = rasterize(tin, truth.spec, ro);
    std::vector<double> e;
    for (std::size_t i = 0; i < g.values.size(); ++i) {
        if (g.values[i] == ro.nodata || std::isnan(truth.z[i])) continue;
        e.push_back(std::abs(static_cast<double>(g.values[i]) - truth.z[i]));
    }
    Errors out;
    out.cells = e.size();
    if (e.empty()) return out;
    double s2 = 0, s1 = 0;
    for (const double v : e) {
        s2 += v * v;
        s1 += v;
    }
    out.rmse = std::sqrt(s2 / double(e.size()));
    out.mae = s1 / double(e.size());
    std::sort(e.begin(), e.end());
    out.p95 = e[std::min(e.size() - 1, static_cast<std::size_t>(0.95 * double(e.size())))];
    out.max = e.back();
    return out;
}

struct Row {
    Criterion c;
    Errors e;
    std::uint64_t flips = 0;
    double seconds = 0;
};

std::vector<Row> run_all(const TerrainInput& input, const Truth& truth) {
    std::vector<Row> rows;
    for (const Criterion c : all_criteria()) {
        TriangulateOptions o;
        o.optimize = c;
        const auto t0 = std::chrono::steady_clock::now();
        const TriangulateResult r = triangulate(input, o);
        const double s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        rows.push_back({c, compare(r.tin, truth), r.stats.optimize.flips, s});
    }
    return rows;
}

void print(const std::string& title, const std::vector<std::vector<Row>>& runs) {
    std::printf("\n%s (%zu run%s; errors in metres, mean over the runs)\n\n", title.c_str(),
                runs.size(), runs.size() == 1 ? "" : "s");
    std::printf("| criterion | RMSE | vs delaunay | MAE | P95 | max | flips | seconds |\n");
    std::printf("|---|---|---|---|---|---|---|---|\n");
    const std::size_t n = runs[0].size();
    for (std::size_t k = 0; k < n; ++k) {
        Row m{runs[0][k].c, {}, 0, 0};
        double ratio = 0;
        for (const auto& run : runs) {
            m.e.rmse += run[k].e.rmse;
            m.e.mae += run[k].e.mae;
            m.e.p95 += run[k].e.p95;
            m.e.max += run[k].e.max;
            m.flips += run[k].flips;
            m.seconds += run[k].seconds;
            ratio += run[k].e.rmse / run[0].e.rmse;
        }
        const double r = double(runs.size());
        std::printf("| %s | %.4f | %.3f | %.4f | %.4f | %.3f | %.0f | %.3f |\n",
                    std::string(criterion_name(m.c)).c_str(), m.e.rmse / r, ratio / r, m.e.mae / r,
                    m.e.p95 / r, m.e.max / r, double(m.flips) / r, m.seconds / r);
    }
    std::printf("\n(%zu cells compared in the first run)\n", runs[0][0].e.cells);
}

int run_sample(const std::string& dir, double cell) {
    io::LoadOptions lo;
    lo.files = {{dir + "/points.csv", io::InputRole::points},
                {dir + "/breaklines.shp", io::InputRole::breaklines},
                {dir + "/boundary.shp", io::InputRole::boundary},
                {dir + "/building.shp", io::InputRole::holes}};
    lo.read.skip_bad_lines = true;
    lo.crs.default_crs = "EPSG:5514";
    const io::LoadedInputs in = io::load_inputs(lo);
    Box2 box;
    for (const Point3& p : in.terrain.points) box.add(p);
    Truth t;
    t.spec.xmin = std::floor(box.xmin);
    t.spec.ymax = std::ceil(box.ymax);
    t.spec.cell = cell;
    t.spec.cols = static_cast<std::size_t>((box.xmax - t.spec.xmin) / cell) + 1;
    t.spec.rows = static_cast<std::size_t>((t.spec.ymax - box.ymin) / cell) + 1;
    t.z.resize(t.spec.cell_count());
    for (std::size_t r = 0; r < t.spec.rows; ++r) {
        for (std::size_t c = 0; c < t.spec.cols; ++c) {
            const double e = t.spec.center_x(c);
            const double n = t.spec.center_y(r);
            t.z[r * t.spec.cols + c] =
                dtm::sample::on_surface(e - dtm::sample::origin_e, n - dtm::sample::origin_n)
                    ? dtm::sample::true_z(e, n)
                    : NAN;
        }
    }
    print("Bundled sample (samples/sjtsk: " + std::to_string(in.terrain.points.size()) +
              " points, breaklines, boundary, building; truth = the analytic terrain, " +
              std::to_string(cell) + " m cells)",
          {run_all(in.terrain, t)});
    return 0;
}

/// Splits a grid of known heights: a random fraction of the cells become survey points (their
/// centres), the rest is the truth.
int grid_experiment(const std::string& title,
                    const GridSpec& spec,
                    const std::vector<double>& z,
                    double fraction,
                    int seeds) {
    std::vector<std::vector<Row>> runs;
    std::size_t used = 0;
    for (int seed = 1; seed <= seeds; ++seed) {
        std::mt19937_64 rng(static_cast<std::uint64_t>(seed));
        std::uniform_real_distribution<double> u(0.0, 1.0);
        TerrainInput input;
        Truth t{spec, std::vector<double>(z.size(), NAN)};
        for (std::size_t r = 0; r < spec.rows; ++r) {
            for (std::size_t c = 0; c < spec.cols; ++c) {
                const double v = z[r * spec.cols + c];
                if (std::isnan(v)) continue;
                if (u(rng) < fraction) {
                    input.points.push_back({spec.center_x(c), spec.center_y(r), v});
                } else {
                    t.z[r * spec.cols + c] = v;
                }
            }
        }
        used = input.points.size();
        runs.push_back(run_all(input, t));
    }
    print(title + " (" + std::to_string(used) + " points = " + std::to_string(fraction * 100) +
              " % of the cells)",
          runs);
    return 0;
}

int raster(const std::string& path, double fraction, int seeds) {
    GDALAllRegister();
    GDALDataset* ds = static_cast<GDALDataset*>(GDALOpen(path.c_str(), GA_ReadOnly));
    if (ds == nullptr) {
        std::fprintf(stderr, "cannot open %s\n", path.c_str());
        return 1;
    }
    double gt[6];
    ds->GetGeoTransform(gt);
    GDALRasterBand* band = ds->GetRasterBand(1);
    GridSpec spec{gt[0], gt[3], gt[1], static_cast<std::size_t>(ds->GetRasterXSize()),
                  static_cast<std::size_t>(ds->GetRasterYSize())};
    std::vector<float> values(spec.cell_count());
    if (band->RasterIO(GF_Read, 0, 0, int(spec.cols), int(spec.rows), values.data(), int(spec.cols),
                       int(spec.rows), GDT_Float32, 0, 0) != CE_None) {
        std::fprintf(stderr, "cannot read %s\n", path.c_str());
        return 1;
    }
    int has_nodata = 0;
    const double nodata = band->GetNoDataValue(&has_nodata);
    std::vector<double> z(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) {
        z[i] = has_nodata && values[i] == float(nodata) ? NAN : values[i];
    }
    GDALClose(ds);
    return grid_experiment("DEM " + path, spec, z, fraction, seeds);
}

int table(const std::string& path, double step, double fraction, int seeds) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);  // header
    std::vector<std::vector<double>> rows;
    while (std::getline(in, line)) {
        std::stringstream s(line);
        std::string item;
        std::getline(s, item, ',');  // row name
        std::vector<double> row;
        while (std::getline(s, item, ',')) row.push_back(std::stod(item));
        rows.push_back(row);
    }
    GridSpec spec{0.0, double(rows.size()) * step, step, rows.at(0).size(), rows.size()};
    std::vector<double> z;
    for (const auto& row : rows) z.insert(z.end(), row.begin(), row.end());
    return grid_experiment("Grid " + path, spec, z, fraction, seeds);
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> a(argv + 1, argv + argc);
    try {
        if (a.size() >= 2 && a[0] == "sample")
            return run_sample(a[1], a.size() > 2 ? std::stod(a[2]) : 0.5);
        if (a.size() == 4 && a[0] == "raster")
            return raster(a[1], std::stod(a[2]), std::stoi(a[3]));
        if (a.size() == 5 && a[0] == "table") {
            return table(a[1], std::stod(a[2]), std::stod(a[3]), std::stoi(a[4]));
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "optimize_dem: %s\n", e.what());
        return 1;
    }
    std::fprintf(stderr,
                 "usage: optimize_dem sample DIR [CELL] | raster DEM.tif FRACTION SEEDS | table "
                 "FILE.csv STEP FRACTION SEEDS\n");
    return 2;
}
