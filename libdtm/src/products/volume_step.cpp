// SPDX-License-Identifier: MIT
// Build step "volume" (with a base surface): the built TIN against the base, exactly, with every
// volume product in volume/ (products::write_volume_products) for the project's cut/fill map.
#include <filesystem>
#include <string>
#include <system_error>

#include "build_steps.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/formats/crs.hpp"
#include "dtm/products/volume.hpp"

namespace dtm::products::detail {

bool wants_volume(const BuildOptions& options) { return !options.base.files.empty(); }

void write_volume(BuildContext& context, const Progress& progress) {
    VolumeJob job;
    job.base = {"base", context.options.base, context.options.triangulate};
    job.threads = context.options.triangulate.threads;
    const LoadedSurface base = load_surface(job.base, context.crs_wkt, progress.sub(0.0, 0.3));
    VolumeReport volume;
    volume.crs_wkt = context.crs_wkt.empty() ? base.crs_wkt : context.crs_wkt;
    volume.top = "the built TIN";
    volume.base = base.description();
    if (!base.transformed_from.empty()) {
        volume.notes.push_back("the base was reprojected from " + base.transformed_from +
                               " into the TIN's " + io::crs_label(context.crs_wkt));
    }
    const std::filesystem::path folder = context.out.staging() / "volume";
    std::error_code ec;
    std::filesystem::create_directory(folder, ec);
    if (ec) throw Error("cannot create " + folder.string() + ": " + ec.message());
    write_volume_products(context.tin, &base.tin, job, folder, volume, progress.sub(0.3, 1.0));
    for (const std::string& file : volume.files) (void)context.out.add("volume/" + file);
    context.report.has_volume = true;
    context.report.volume = volume.volume;
    context.report.volume_base = volume.base;
}

}  // namespace dtm::products::detail
