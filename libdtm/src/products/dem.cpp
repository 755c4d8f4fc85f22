// SPDX-License-Identifier: MIT
// `dtm grid` on one machine: the grid, the rasterisation into the writer with a count of the
// cells that got a value, and the gdaldem derivatives of the committed DEM.
#include "dtm/products/dem.hpp"

#include <utility>

#include "algo/detail/raster_vertex_order.hpp"
#include "dtm/algo/rasterize.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/extension.hpp"
#include "dtm/io/grid_writer.hpp"
#include "dtm/io/output_check.hpp"

namespace dtm::products {
namespace {

/// Counts the cells that received a value while passing the rows on.
class CountingSink final : public GridSink {
public:
    CountingSink(GridSink& next, float nodata) : next_(next), nodata_(nodata) {}
    void write_rows(std::size_t first_row,
                    std::size_t row_count,
                    std::span<const float> values) override {
        for (const float v : values) {
            filled += v != nodata_ ? 1 : 0;
        }
        next_.write_rows(first_row, row_count, values);
    }
    std::uint64_t filled = 0;

private:
    GridSink& next_;
    float nodata_;
};

}  // namespace

void check_dem_size(const GridSpec& spec) {
    constexpr double max_cells = 68'719'476'736.0;  // 2^36
    if (static_cast<double>(spec.cols) * static_cast<double>(spec.rows) > max_cells) {
        throw OptionError("cell", std::to_string(spec.cols) + " x " + std::to_string(spec.rows) +
                                      " cells is too many (at most 2^36); use a larger `cell` "
                                      "or a smaller `extent`");
    }
}

GridSpec dem_grid_spec(const Box2& tin_box, double cell, const std::optional<Box2>& extent) {
    const GridSpec spec =
        extent ? extent_grid_spec(*extent, cell) : snapped_grid_spec(tin_box, cell);
    check_dem_size(spec);
    return spec;
}

std::vector<DemDerivativeFile> dem_derivatives(const std::filesystem::path& hillshade,
                                               const std::filesystem::path& slope,
                                               const std::filesystem::path& aspect) {
    std::vector<DemDerivativeFile> out;
    for (const DemDerivativeFile& d : {DemDerivativeFile{hillshade, io::DemDerivative::hillshade},
                                       DemDerivativeFile{slope, io::DemDerivative::slope},
                                       DemDerivativeFile{aspect, io::DemDerivative::aspect}}) {
        if (!d.file.empty()) out.push_back(d);
    }
    return out;
}

void check_dem_outputs(const std::filesystem::path& output, const DemOptions& options) {
    io::check_output(output, io::OutputKind::raster, "output");
    const std::string extension = io::lower_extension(output);
    if (options.cog && extension != "tif" && extension != "tiff") {
        throw OptionError("cog", "`cog` needs a .tif target, not " + output.string());
    }
    for (const auto& [file, kind] :
         dem_derivatives(options.hillshade, options.slope, options.aspect)) {
        io::check_output(file, io::OutputKind::raster, io::dem_derivative_name(kind));
    }
}

DemResult write_dem(const Tin& tin,
                    const std::string& crs_wkt,
                    const DemOptions& options,
                    const std::filesystem::path& output,
                    const Progress& progress) {
    if (tin.triangles.empty()) {
        throw InputError("the inputs give no triangle to rasterise");
    }
    DemResult result;
    result.spec =
        dem_grid_spec(options.extent ? Box2{} : tin_bounds(tin), options.cell, options.extent);
    io::GridWriter writer(output, result.spec,
                          {.crs_wkt = crs_wkt, .nodata = options.nodata, .cog = options.cog});
    CountingSink counter(writer, options.nodata);
    rasterize(tin, result.spec,
              {.nodata = options.nodata,
               .threads = options.threads,
               .interpolation = options.interpolation,
               .gradients = {.threads = options.threads,
                             .crease_at_breaklines = options.crease_at_breaklines}},
              counter, progress.sub(0.0, 0.9));
    writer.commit();
    result.filled = counter.filled;
    for (const auto& [file, kind] :
         dem_derivatives(options.hillshade, options.slope, options.aspect)) {
        io::write_dem_derivative(output, file, kind);
    }
    progress.report(1.0, "done");
    return result;
}

DemResult write_dem(Tin&& tin,
                    const std::string& crs_wkt,
                    const DemOptions& options,
                    const std::filesystem::path& output,
                    const Progress& progress) {
    if (options.interpolation == Interpolation::linear && !detail::has_coherent_vertices(tin)) {
        detail::make_vertices_coherent(tin);  // rasterize then reads it without a copy
    }
    const Tin& owned = tin;
    return write_dem(owned, crs_wkt, options, output, progress);
}

}  // namespace dtm::products
