// SPDX-License-Identifier: MIT
// The profile job: surfaces and lines in one CRS, sections cut in parallel (algo/profile), and
// the products: CSV, GeoPackage, DXF and plots.
#include "dtm/products/profile.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include <cctype>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <type_traits>

#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"
#include "dtm/io/draw/canvas.hpp"
#include "dtm/io/formats/crs.hpp"
#include "dtm/io/formats/dxf.hpp"
#include "dtm/io/formats/vector_file.hpp"
#include "dtm/io/output_check.hpp"
#include "dtm/products/profile_plot.hpp"
#include "products/detail/staged_folder.hpp"

namespace dtm::products {
namespace fs = std::filesystem;

namespace {

/// @p name as an R12 layer name: characters other than letters, digits, '_', '-', '$' become '_'.
std::string dxf_layer_name(std::string name) {
    for (char& c : name) {
        const auto u = static_cast<unsigned char>(c);
        if (!(std::isalnum(u) || c == '_' || c == '-' || c == '$')) c = '_';
    }
    return name;
}

void write_csv(const fs::path& path,
               const std::vector<Polyline>& lines,
               const std::vector<std::string>& names,
               const std::vector<std::vector<Profile>>& sections,
               ProfileReport& report) {
    std::ofstream out(path, std::ios::binary);
    out << "line,surface,run,chainage,x,y,z\n";
    std::string row;
    char number[64];
    const auto add = [&](auto value, char after) {  // %zu or %.6f (std::to_chars: the same text)
        std::to_chars_result r{};
        if constexpr (std::is_floating_point_v<decltype(value)>) {
            r = std::to_chars(number, number + sizeof number, value, std::chars_format::fixed, 6);
        } else {
            r = std::to_chars(number, number + sizeof number, value);
        }
        row.append(number, r.ptr);
        row.push_back(after);
    };
    for (std::size_t l = 0; l < lines.size(); ++l) {
        for (std::size_t s = 0; s < names.size(); ++s) {
            const Profile& p = sections[s][l];
            row.clear();
            for (std::size_t r = 0; r < p.runs.size(); ++r) {
                for (const ProfilePoint& q : p.runs[r].points) {
                    add(l + 1, ',');
                    row += names[s];
                    row.push_back(',');
                    add(r + 1, ',');
                    add(q.chainage, ',');
                    add(q.x, ',');
                    add(q.y, ',');
                    add(q.z, '\n');
                    ++report.breakpoints;
                }
            }
            out << row;
            report.gaps += p.runs.empty() ? 0 : p.runs.size() - 1;
        }
    }
    if (!out) {
        throw Error("cannot write " + path.string());
    }
}

std::vector<Point3> run_points(const ProfileRun& run) {
    std::vector<Point3> pts;
    pts.reserve(run.points.size());
    for (const ProfilePoint& q : run.points) {
        pts.push_back({q.x, q.y, q.z});
    }
    return pts;
}

/// Calls f(surface, line, run, points) for every run of every section, in file order.
template <class F>
void for_each_run(const std::vector<std::vector<Profile>>& sections, F&& f) {
    for (std::size_t s = 0; s < sections.size(); ++s) {
        for (std::size_t l = 0; l < sections[s].size(); ++l) {
            const Profile& p = sections[s][l];
            for (std::size_t r = 0; r < p.runs.size(); ++r) {
                f(s, l, r, run_points(p.runs[r]));
            }
        }
    }
}

void write_gpkg(const fs::path& folder,
                const std::string& crs,
                const std::vector<std::string>& names,
                const std::vector<std::vector<Profile>>& sections) {
    io::VectorFile gpkg(folder / "profile.gpkg", crs);
    using T = io::VectorField::Type;
    const std::size_t layer = gpkg.add_layer("profiles", io::VectorGeometry::line_3d,
                                             {{"line", T::integer},
                                              {"surface", T::text},
                                              {"run", T::integer},
                                              {"chainage_from", T::real},
                                              {"chainage_to", T::real}});
    for_each_run(
        sections, [&](std::size_t s, std::size_t l, std::size_t r, const std::vector<Point3>& pts) {
            const ProfileRun& run = sections[s][l].runs[r];
            gpkg.add_line(layer, pts,
                          {static_cast<long long>(l + 1), names[s], static_cast<long long>(r + 1),
                           run.points.front().chainage, run.points.back().chainage});
        });
    gpkg.commit();
}

void write_dxf(const fs::path& folder,
               const std::vector<std::string>& names,
               const std::vector<std::vector<Profile>>& sections) {
    std::vector<io::DxfLayer> layers;
    for (std::size_t s = 0; s < names.size(); ++s) {
        layers.push_back({dxf_layer_name("PROFILE_" + names[s]), static_cast<int>(1 + s % 6)});
    }
    io::DxfWriter dxf(folder / "profile.dxf", layers);
    for_each_run(sections,
                 [&](std::size_t s, std::size_t, std::size_t, const std::vector<Point3>& pts) {
                     dxf.polyline(layers[s].name, pts, false);
                 });
    dxf.finish();
}

std::vector<std::string> write_plots(const fs::path& folder,
                                     const ProfileJob& job,
                                     const std::vector<Polyline>& lines,
                                     const std::vector<std::string>& names,
                                     const std::vector<std::vector<Profile>>& sections) {
    std::vector<std::string> files;
    const double width = 270.0;  // A4 landscape
    const double height = 190.0;
    std::unique_ptr<io::draw::Canvas> pdf;
    if (job.plot_format == "pdf") {
        pdf = std::make_unique<io::draw::Canvas>(folder / "profile.pdf", width, height);
        files.emplace_back("profile.pdf");
    }
    for (std::size_t l = 0; l < lines.size(); ++l) {
        ProfilePlot plot;
        plot.title = "Profile " + std::to_string(l + 1) +
                     (lines[l].source.empty() ? std::string() : " (" + lines[l].source + ")");
        plot.names = names;
        plot.exaggeration = job.exaggeration;
        plot.station_interval = job.station_interval;
        for (std::size_t s = 0; s < names.size(); ++s) {
            plot.profiles.push_back(sections[s][l]);
        }
        if (pdf) {
            if (l > 0) {
                pdf->new_page();
            }
            draw_profile(*pdf, plot, {10.0, 10.0}, width - 20.0, height - 20.0);
        } else {
            const std::string name = "profile_" + std::to_string(l + 1) + "." + job.plot_format;
            io::draw::Canvas page(folder / name, width, height);
            draw_profile(page, plot, {10.0, 10.0}, width - 20.0, height - 20.0);
            page.finish();
            files.push_back(name);
        }
    }
    if (pdf) {
        pdf->finish();
    }
    return files;
}

}  // namespace

ProfileReport run_profile(const ProfileJob& job,
                          const fs::path& out_dir,
                          const Progress& progress) {
    if (job.surfaces.empty()) {
        throw UsageError("profile: give at least one surface");
    }
    if (!job.plot_format.empty() && job.plot_format != "pdf" && job.plot_format != "svg" &&
        job.plot_format != "png") {
        throw OptionError("plot_format", "profile: `plot_format` must be pdf, svg, png or none");
    }
    io::check_output(out_dir, io::OutputKind::folder, "out_dir");  // before any input is read
    io::AtomicDirectory staging(out_dir);
    ProfileReport report;
    const auto start = std::chrono::steady_clock::now();
    const auto since = [](std::chrono::steady_clock::time_point t) {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    };
    const std::vector<LoadedSurface> surfaces =
        load_surfaces(job.surfaces, report.notes, progress.sub(0.0, 0.5));
    const std::string crs = surfaces.front().crs_wkt;
    const std::vector<Polyline> lines = load_lines(job.lines, job.line_reader, crs);
    std::vector<std::vector<Point3>> points;
    for (const Polyline& l : lines) {
        points.push_back(l.points);
        if (l.closed && !l.points.empty()) {
            points.back().push_back(l.points.front());
        }
    }
    report.read_seconds = since(start);
    const auto cut_start = std::chrono::steady_clock::now();
    // Each surface's index (a sequential pass) is built beside the others'.
    std::vector<std::unique_ptr<TinSection>> indexes(surfaces.size());
    tbb::parallel_for(std::size_t{0}, surfaces.size(), [&](std::size_t s) {
        indexes[s] = std::make_unique<TinSection>(surfaces[s].tin);
    });
    std::vector<std::vector<Profile>> sections;
    for (std::size_t s = 0; s < surfaces.size(); ++s) {
        report.surfaces.push_back(surfaces[s].name);
        sections.push_back(indexes[s]->cut_all(points, job.threads, progress.sub(0.5, 0.7)));
    }
    for (std::size_t l = 0; l < lines.size(); ++l) {
        bool any = false;
        for (const auto& s : sections) {
            any = any || !s[l].runs.empty();
        }
        if (!any) {
            throw InputError(
                job.lines, 0, 0,
                (lines[l].source.empty() ? "line " + std::to_string(l + 1) : lines[l].source) +
                    ": the line lies outside every surface");
        }
    }
    report.lines = lines.size();
    tbb::task_group writers;  // the three files at once
    writers.run([&] {
        write_csv(staging.staging() / "profile.csv", lines, report.surfaces, sections, report);
    });
    writers.run([&] { write_dxf(staging.staging(), report.surfaces, sections); });
    writers.run_and_wait([&] { write_gpkg(staging.staging(), crs, report.surfaces, sections); });
    report.files.insert(report.files.end(), {"profile.csv", "profile.gpkg", "profile.dxf"});
    progress.report(0.8, "drawing the profiles");
    if (!job.plot_format.empty()) {
        const std::vector<std::string> plots =
            write_plots(staging.staging(), job, lines, report.surfaces, sections);
        report.files.insert(report.files.end(), plots.begin(), plots.end());
    }
    detail::commit_files(staging, report.files);
    report.sections_seconds = since(cut_start);
    progress.report(1.0, "done");
    return report;
}

}  // namespace dtm::products
