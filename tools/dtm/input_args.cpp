// SPDX-License-Identifier: MIT
// The input options every terrain-reading subcommand takes (positional INPUTS, --breaklines,
// --soft-breaklines, --boundary, --holes, CRS and reader options).
#include "input_args.hpp"

#include "hpgl_args.hpp"

namespace dtm::cli {

void add_input_options(CLI::App& app, InputArgs& args) {
    app.add_option(
           "inputs", args.inputs,
           "Survey points: text (x y z, id;Y;X;Z, lat/lon...), OGR vector files (shp, gpkg, "
           "geojson, dxf...: points, lines become breaklines), or a TIN (dtm .ply, LandXML .xml)")
        ->check(CLI::ExistingPath);
    const auto files = [&app](const char* name, std::vector<std::string>& into, const char* what) {
        app.add_option(name, into, what)->check(CLI::ExistingPath)->allow_extra_args(false);
    };
    files("--breaklines", args.breaklines,
          "Hard 3-D breaklines (OGR lines/polygons, or shapeid,x,y,z text); repeatable");
    files("--soft-breaklines", args.soft_breaklines,
          "Soft 2-D breaklines: edges whose heights come from the surface; repeatable");
    files("--boundary", args.boundaries,
          "Outer boundary: polygons (inner rings are holes) or closed lines; repeatable");
    files("--holes", args.holes,
          "Holes: polygons or closed lines, or points as hole seeds; repeatable");
    files("--flat-areas", args.flat_areas,
          "Real flats (lakes, ponds): closed lines or polygons at one height whose inside stays "
          "flat when contour flats are removed; hard breaklines otherwise; repeatable");
    add_reader_options(app, args.read, args.crs);
}

void add_reader_options(CLI::App& app, io::ReadOptions& o, io::CrsOptions& crs) {
    app.add_option("--crs", crs.default_crs,
                   "CRS of inputs that carry none (EPSG:5514, WKT, PROJ)");
    app.add_option("--target-crs", crs.target_crs,
                   "Transform every input into this CRS (default: the first input's CRS; "
                   "geographic inputs go to their UTM zone)");
    app.add_option("--columns", o.columns,
                   "Text column names in order, e.g. id,y,x,z,code (- skips a column)");
    app.add_option("--layer", o.layer, "OGR layer to read (default: every layer)");
    app.add_option("--where", o.where, "OGR attribute filter, e.g. \"type = 'edge'\"");
    app.add_option("--z-field", o.z_field,
                   "OGR attribute holding the height (points, or one height per line)");
    app.add_flag("--skip-bad-lines", o.skip_bad_lines,
                 "Skip and count malformed text lines instead of failing");
    app.add_flag("--retriangulate", o.retriangulate,
                 "Surface inputs (LandXML, DXF 3DFACE): triangulate their points and lines "
                 "instead of keeping their faces");
    app.add_option("--surface", o.surface,
                   "LandXML: the surface of this name (default: the first)");
    app.add_option("--classes", o.classes,
                   "LAS point clouds: keep only these classification codes, e.g. 2,9 (ground, "
                   "water)")
        ->delimiter(',')
        ->check(CLI::Range(0, 255));
    app.add_option("--thin", o.thin,
                   "LAS point clouds: keep the lowest point of every D x D cell (cells from "
                   "x = y = 0; default 0: every point)")
        ->check(CLI::NonNegativeNumber);
    add_hpgl_options(app, o.hpgl);
}

void add_surface_options(CLI::App& app, const std::string& name, InputArgs& args) {
    const auto files = [&app](const std::string& flag, std::vector<std::string>& into,
                              const std::string& what) {
        app.add_option(flag, into, what)->check(CLI::ExistingPath)->allow_extra_args(false);
    };
    files("--" + name, args.inputs,
          "The " + name + " surface: a dtm .ply TIN, or points (and lines) to triangulate");
    files("--" + name + "-breaklines", args.breaklines,
          "Hard breaklines of the " + name + " surface");
    files("--" + name + "-soft-breaklines", args.soft_breaklines,
          "Soft breaklines of the " + name + " surface");
    files("--" + name + "-boundary", args.boundaries, "Outer boundary of the " + name + " surface");
    files("--" + name + "-holes", args.holes, "Holes of the " + name + " surface");
}

io::LoadOptions to_load_options(const InputArgs& args) {
    io::LoadOptions options;
    options.read = args.read;
    options.crs = args.crs;
    const auto add = [&options](const std::vector<std::string>& paths, io::InputRole role) {
        for (const std::string& p : paths) options.files.push_back({p, role});
    };
    add(args.inputs, io::InputRole::points);
    add(args.breaklines, io::InputRole::breaklines);
    add(args.soft_breaklines, io::InputRole::soft_breaklines);
    add(args.boundaries, io::InputRole::boundary);
    add(args.holes, io::InputRole::holes);
    add(args.flat_areas, io::InputRole::breaklines);
    return options;
}

}  // namespace dtm::cli
