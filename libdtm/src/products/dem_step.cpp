// SPDX-License-Identifier: MIT
// Build step "dem": the TIN's surface (BuildOptions::interpolation) sampled at cell centres
// into a GeoTIFF DEM, and GDAL's hillshade of it.
#include "build_steps.hpp"
#include "dtm/algo/rasterize.hpp"
#include "dtm/io/grid_writer.hpp"
#include "dtm/products/rules.hpp"

namespace dtm::products::detail {

void write_dem(BuildContext& context, const Progress& progress) {
    const bool given = context.options.cell > 0.0;
    const double cell = given ? context.options.cell : default_cell(context.surface);
    context.report.cell_rule = given ? context.worded("given (`cell`)") : default_cell_rule;
    const GridSpec spec = snapped_grid_spec(tin_bounds(context.tin), cell);
    io::GridWriteOptions options;
    options.crs_wkt = context.crs_wkt;
    const std::filesystem::path dem = context.out.add("dem.tif");
    io::GridWriter writer(dem, spec, options);
    RasterizeOptions raster;
    raster.threads = context.options.triangulate.threads;
    rasterize(context.tin, context.interpolant, spec, raster, writer, progress.sub(0.0, 0.8));
    writer.commit();
    progress.report(0.8, "hillshade");
    io::write_dem_derivative(dem, context.out.add("hillshade.tif"), io::DemDerivative::hillshade);
    progress.report(1.0, "hillshade");
    context.report.dem = spec;
}

}  // namespace dtm::products::detail
