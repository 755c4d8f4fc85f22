// SPDX-License-Identifier: MIT
/// @file
/// @brief Writing the sample survey as the files a surveyor would hand over: a CSV point list,
/// shapefiles with an EPSG:5514 .prj, and an HP-GL height plan at 1:500.
#pragma once

#include <filesystem>

#include "sample_site.hpp"

namespace dtm::sample {

/// Ground position of plotter unit (0, 0) on the HP-GL plan, and the plan scale.
inline constexpr double plan_origin_e = origin_e - 10.0;
inline constexpr double plan_origin_n = origin_n - 10.0;
inline constexpr double plan_scale = 500.0;
/// 40 plotter units per millimetre: one unit is 0.025 mm on paper, 12.5 mm on the ground.
inline constexpr double ground_metres_per_plotter_unit = plan_scale / 40.0 / 1000.0;

/// points.csv (id,x,y,z; two corrupt records included) and checkpoints.csv (id,x,y,z true).
void write_csv_files(const Survey& survey, const std::filesystem::path& dir);
/// breaklines.shp (LineStringZ, field `kind`), boundary.shp and building.shp (PolygonZ).
void write_shapefiles(const Survey& survey, const std::filesystem::path& dir);
/// The natural ground before the road (natural_survey): natural_points.csv (id,x,y,z),
/// natural_breaklines.shp, natural_boundary.shp and natural_building.shp.
void write_natural_files(const Survey& natural, const std::filesystem::path& dir);
/// plan_500.hpgl: spot heights as `SM*` symbols with `LB` height labels (pen 1), breaklines pen
/// 2, boundary pen 3, building pen 4.
void write_hpgl_plan(const Survey& survey, const std::filesystem::path& dir);

}  // namespace dtm::sample
