// SPDX-License-Identifier: MIT
// Sample 3: survey points from a text file -> constrained Delaunay TIN -> 1 m contours in a
// GeoPackage, with a custom ContourSink counting the lines on the way. Public API only.
//
//   sample_03_contours_from_csv samples/quick/points.xyz contours.gpkg [interval]
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "dtm/algo/contour.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/io/contour_writer.hpp"
#include "dtm/io/inputs.hpp"

namespace {

/// Passes every line on to the file writer and counts them per kind.
class CountingSink final : public dtm::ContourSink {
public:
    explicit CountingSink(dtm::ContourSink& next) : next_(next) {}
    void add(const dtm::ContourLevel& level,
             std::span<const dtm::Point3> line,
             bool closed) override {
        (closed ? rings : open_lines) += 1;
        next_.add(level, line, closed);
    }
    int rings = 0;
    int open_lines = 0;

private:
    dtm::ContourSink& next_;
};

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s POINTS OUT.gpkg [INTERVAL]\n", argv[0]);
        return 2;
    }
    try {
        const dtm::io::LoadedInputs inputs = dtm::io::load_inputs({.files = {{argv[1]}}});
        const dtm::Tin tin = dtm::triangulate(inputs.terrain).tin;
        dtm::io::ContourWriter writer(argv[2], {.crs_wkt = inputs.crs_wkt});
        CountingSink counter(writer);
        dtm::contour(tin, {.interval = argc > 3 ? std::atof(argv[3]) : 1.0}, counter);
        writer.commit();
        std::printf("%zu triangles, %d closed rings, %d open lines -> %s\n", tin.triangles.size(),
                    counter.rings, counter.open_lines, argv[2]);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
}
