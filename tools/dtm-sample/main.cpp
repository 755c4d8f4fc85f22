// SPDX-License-Identifier: MIT
// dtm-sample: writes the bundled sample survey (samples/sjtsk) from the analytic terrain of
// sample_terrain.hpp, and prints the true elevation anywhere on it.
//
//   dtm-sample write samples/sjtsk        regenerate every sample file
//   dtm-sample z -750200 -1050100 ...     true z at S-JTSK (E, N) pairs
//   dtm-sample z - < pairs.txt            the same for E N pairs read from stdin
//   dtm-sample render OUT picture.png --breaklines samples/sjtsk/breaklines.shp
//                                         the README picture from the products of `dtm build`
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "render.hpp"
#include "sample_output.hpp"
#include "sample_terrain.hpp"

namespace {

int write_sample(const std::filesystem::path& dir, double spacing) {
    using namespace dtm::sample;
    std::filesystem::create_directories(dir);
    SurveyOptions options;
    options.spacing = spacing;
    const Survey survey = make_survey(options);
    write_csv_files(survey, dir);
    write_shapefiles(survey, dir);
    write_hpgl_plan(survey, dir);
    write_natural_files(natural_survey(survey), dir);
    std::size_t vertices = 0;
    for (const Line& line : survey.breaklines) {
        vertices += line.vertices.size();
    }
    std::printf(
        "%zu spot heights (%zu beyond the boundary, %zu re-measured), %zu corrupt CSV "
        "records, %zu breaklines with %zu vertices, boundary %zu and building %zu ring "
        "vertices, %zu check points -> %s\n",
        survey.points.size(), survey.outside_points, survey.repeated_points,
        survey.bad_lines.size(), survey.breaklines.size(), vertices,
        survey.boundary.vertices.size(), survey.building.vertices.size(),
        survey.check_points.size(), dir.string().c_str());
    return 0;
}

int print_z(const std::vector<double>& coordinates) {
    if (coordinates.size() % 2 != 0) {
        std::cerr << "dtm-sample z: expected E N pairs\n";
        return 2;
    }
    for (std::size_t i = 0; i < coordinates.size(); i += 2) {
        const double e = coordinates[i];
        const double n = coordinates[i + 1];
        const double u = e - dtm::sample::origin_e;
        const double v = n - dtm::sample::origin_n;
        std::printf("%.3f %.3f %.4f%s\n", e, n, dtm::sample::true_z(e, n),
                    dtm::sample::on_surface(u, v) ? "" : " (off the surveyed surface)");
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"dtm-sample: the bundled S-JTSK sample survey and its true terrain"};
    app.require_subcommand(1);
    std::string dir;
    double spacing = 3.5;
    CLI::App* write = app.add_subcommand("write", "Write the sample files into DIR");
    write->add_option("dir", dir, "Output folder (samples/sjtsk)")->required();
    write->add_option("--spacing", spacing, "Spacing of the spot heights in metres (3.5)")
        ->check(CLI::PositiveNumber);
    std::vector<std::string> coordinates;
    CLI::App* z = app.add_subcommand("z", "Print the true elevation at E N pairs (EPSG:5514)");
    z->add_option("coordinates", coordinates, "E N [E N ...], or - to read the pairs from stdin")
        ->required();
    std::string build_dir;
    std::string png;
    dtm::sample::RenderOptions render_options;
    std::vector<std::string> render_lines;
    CLI::App* render =
        app.add_subcommand("render", "Render a picture of the products of `dtm build` in BUILD");
    render->add_option("build", build_dir, "Output folder of dtm build")->required();
    render->add_option("png", png, "Picture to write (.png)")->required();
    render->add_option("--breaklines", render_lines, "Line files drawn in blue");
    render->add_option("--z-factor", render_options.z_factor, "Hillshade exaggeration (4)");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }
    try {
        if (render->parsed()) {
            render_options.breaklines.assign(render_lines.begin(), render_lines.end());
            dtm::sample::render_picture(build_dir, png, render_options);
            return 0;
        }
        if (write->parsed()) {
            return write_sample(dir, spacing);
        }
        std::vector<double> values;
        if (coordinates.size() == 1 && coordinates[0] == "-") {
            for (double v = 0.0; std::cin >> v;) {
                values.push_back(v);
            }
        } else {
            for (const std::string& c : coordinates) {
                values.push_back(std::stod(c));
            }
        }
        return print_z(values);
    } catch (const std::exception& e) {
        std::cerr << "dtm-sample: " << e.what() << '\n';
        return 1;
    }
}
