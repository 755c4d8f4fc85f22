// SPDX-License-Identifier: MIT
// Build step "write_tin": the TIN in dtm's lossless PLY, as a QGIS mesh (2DM) and for ParaView.
#include <array>

#include "build_steps.hpp"
#include "dtm/io/tin_file.hpp"

namespace dtm::products::detail {

void write_tin_files(BuildContext& context, const Progress& progress) {
    io::TinWriteOptions options;
    options.crs_wkt = context.crs_wkt;
    const std::array<const char*, 3> names{"tin.ply", "tin.2dm", "surface.vtp"};
    for (std::size_t i = 0; i < names.size(); ++i) {
        progress.report(static_cast<double>(i) / 3.0, "writing the TIN");
        io::write_tin(context.tin, context.out.add(names[i]), options);
    }
    progress.report(1.0, "writing the TIN");
}

}  // namespace dtm::products::detail
