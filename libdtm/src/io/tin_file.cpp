// SPDX-License-Identifier: MIT
// write_tin(): the table of TIN output formats, chosen by file extension, and the one place that
// makes every TIN output atomic (temporary sibling, then rename; see atomic_file.cpp). A format
// is one row: its extension, a description for messages, and a function that writes exactly the
// path it is given.
#include "dtm/io/tin_file.hpp"

#include <algorithm>
#include <array>
#include <string>

#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"
#include "dtm/io/extension.hpp"
#include "dtm/io/formats/dxf.hpp"
#include "dtm/io/formats/landxml.hpp"
#include "dtm/io/formats/mesh_2dm.hpp"
#include "dtm/io/formats/ogr_tin.hpp"
#include "dtm/io/formats/ply.hpp"
#include "dtm/io/formats/tin_tiles.hpp"
#include "dtm/io/formats/vtk_surface.hpp"

namespace dtm::io {
namespace {

using TinWriteFn = void (*)(const Tin&, const std::filesystem::path&, const TinWriteOptions&);

struct TinWriterInfo {
    std::string_view extension;  ///< lower case, no dot
    std::string_view description;
    TinWriteFn write;
};

// The whole list, in one place. Add a row per format (its writer lives in src/io/formats/).
constexpr std::array tin_writer_table{
    TinWriterInfo{"ply", "PLY TIN with constrained edges (dtm's own, lossless)", &write_tin_ply},
    TinWriterInfo{"2dm", "SMS 2DM mesh (a QGIS mesh layer through MDAL)", &write_2dm},
    TinWriterInfo{"vtp", "VTK XML PolyData: triangles, breaklines, elevation", &write_vtp},
    TinWriterInfo{"gpkg", "GeoPackage: one PolygonZ feature per triangle", &write_ogr_tin},
    TinWriterInfo{"xml", "LandXML 1.2 surface: points, faces, breaklines, boundaries",
                  &write_landxml},
    TinWriterInfo{"dxf", "DXF R12 for CAD: 3DFACE triangles, breaklines as 3-D polylines",
                  &write_tin_dxf},
    TinWriterInfo{"shp", "ESRI Shapefile: one PolygonZ feature per triangle", &write_ogr_tin},
};

}  // namespace

std::vector<std::string_view> tin_extensions() {
    std::vector<std::string_view> extensions;
    for (const TinWriterInfo& info : tin_writer_table) extensions.push_back(info.extension);
    extensions.emplace_back("json");  // a tiled TIN: several files, atomic on its own
    return extensions;
}

void write_tin(const Tin& tin, const std::filesystem::path& path, const TinWriteOptions& options) {
    const std::string extension = lower_extension(path);
    if (extension == "json") {
        write_tin_tiles(tin, path, options);
        return;
    }
    const auto* info =
        std::find_if(tin_writer_table.begin(), tin_writer_table.end(),
                     [&](const TinWriterInfo& row) { return row.extension == extension; });
    if (info == tin_writer_table.end()) {
        std::string known;
        for (const std::string_view e : tin_extensions()) {
            known += (known.empty() ? "." : ", .") + std::string(e);
        }
        throw UsageError("cannot write TIN " + path.string() + ": unknown extension '" +
                         path.extension().string() + "' (known: " + known + ")");
    }
    AtomicOutput output(path);
    info->write(tin, output.temp_path(), options);
    output.commit();
}

}  // namespace dtm::io
