// SPDX-License-Identifier: MIT
// The sections job: surfaces and the alignment in one CRS, section lines (algo/sections), the
// sections of every surface (algo/profile), areas, end-area and exact slab volumes, and the
// products: sections.csv, section_points.csv, sections.gpkg, sections.json and a sheet of plots.
#include "dtm/products/sections.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>

#include "dtm/core/error.hpp"
#include "dtm/io/draw/canvas.hpp"
#include "dtm/io/formats/vector_file.hpp"
#include "dtm/io/json_writer.hpp"
#include "dtm/io/output_check.hpp"
#include "dtm/products/profile.hpp"
#include "dtm/products/profile_plot.hpp"
#include "products/detail/staged_folder.hpp"

namespace dtm::products {
namespace fs = std::filesystem;
namespace {

std::string summary_csv(const SectionsReport& r) {
    std::string out =
        "station,x,y,fill_area,cut_area,width,end_area_fill,end_area_cut,exact_fill,exact_cut\n";
    char row[512];
    for (std::size_t i = 0; i < r.sections.size(); ++i) {
        const SectionRow& s = r.sections[i];
        std::snprintf(row, sizeof row, "%.3f,%.4f,%.4f,%.6f,%.6f,%.4f", s.line.station,
                      s.line.centre.x, s.line.centre.y, s.areas.fill, s.areas.cut, s.areas.width);
        out += row;
        if (i < r.exact.size()) {
            std::snprintf(row, sizeof row, ",%.6f,%.6f,%.6f,%.6f\n", r.end_area[i].fill,
                          r.end_area[i].cut, r.exact[i].fill, r.exact[i].cut);
        } else {
            std::snprintf(row, sizeof row, ",,,,\n");
        }
        out += row;
    }
    return out;
}

std::string summary_json(const SectionsReport& r, const SectionsJob& job) {
    io::JsonWriter json;
    json.begin_object();
    json.value("sections", r.sections.size());
    json.value("interval", job.options.interval);
    json.value("width", job.options.width);
    json.begin_array("surfaces");
    for (const std::string& s : r.surfaces) {
        json.value({}, s);
    }
    json.end();
    json.begin_object("end_area");
    json.value("fill", r.end_area_fill);
    json.value("cut", r.end_area_cut);
    json.end();
    json.begin_object("exact");
    json.value("fill", r.exact_fill);
    json.value("cut", r.exact_cut);
    json.end();
    json.value("explanation",
               "end-area volumes assume each section's area varies linearly between stations; "
               "the exact volumes integrate the two surfaces over each slab between sections. "
               "They differ where the ground or the design changes between stations (terrain "
               "curvature along the alignment, features between sections, where cut turns to "
               "fill), and on curves of the alignment, where the sections are not parallel");
    std::size_t worst = 0;
    double worst_diff = -1.0;
    for (std::size_t k = 0; k < r.exact.size(); ++k) {
        const double diff = std::fabs(r.end_area[k].fill - r.exact[k].fill) +
                            std::fabs(r.end_area[k].cut - r.exact[k].cut);
        if (diff > worst_diff) {
            worst_diff = diff;
            worst = k;
        }
    }
    if (!r.exact.empty()) {
        json.begin_object("largest_difference");
        json.value("from_station", r.sections[worst].line.station);
        json.value("to_station", r.sections[worst + 1].line.station);
        json.value("end_area_minus_exact", (r.end_area[worst].fill - r.exact[worst].fill) -
                                               (r.end_area[worst].cut - r.exact[worst].cut));
        json.value("absolute", worst_diff);
        json.end();
    }
    json.begin_array("notes");
    for (const std::string& n : r.notes) {
        json.value({}, n);
    }
    json.end();
    json.end();
    return json.str();
}

void write_sheet(const fs::path& folder,
                 const SectionsJob& job,
                 const SectionsReport& r,
                 const std::vector<std::vector<Profile>>& sections,
                 std::vector<std::string>& files) {
    // A4 portrait sheets of 2 x 4 sections.
    const double page_w = 210.0;
    const double page_h = 297.0;
    const double cell_w = (page_w - 20.0) / 2.0;
    const double cell_h = (page_h - 20.0) / 4.0;
    std::unique_ptr<io::draw::Canvas> pdf;
    if (job.plot_format == "pdf") {
        pdf = std::make_unique<io::draw::Canvas>(folder / "sections.pdf", page_w, page_h);
        files.emplace_back("sections.pdf");
    }
    for (std::size_t i = 0; i < r.sections.size(); ++i) {
        ProfilePlot plot;
        char title[160];
        std::snprintf(title, sizeof title, "%s   fill %.2f m2   cut %.2f m2",
                      station_label(r.sections[i].line.station).c_str(), r.sections[i].areas.fill,
                      r.sections[i].areas.cut);
        plot.title = title;
        plot.names = r.surfaces;
        plot.exaggeration = job.exaggeration;
        plot.chainage_offset = -job.options.width / 2.0;
        plot.x_label = "offset [m] (left -, right +)";
        bool any = false;
        for (const auto& s : sections) {
            plot.profiles.push_back(s[i]);
            any = any || !s[i].runs.empty();
        }
        if (!any) {
            continue;
        }
        if (pdf) {
            const std::size_t slot = i % 8;
            if (i > 0 && slot == 0) {
                pdf->new_page();
            }
            const Point2 at{10.0 + static_cast<double>(slot % 2) * cell_w,
                            10.0 + static_cast<double>(slot / 2) * cell_h};
            draw_profile(*pdf, plot, at, cell_w - 2.0, cell_h - 2.0);
        } else {
            const std::string name = "section_" + std::to_string(i + 1) + "." + job.plot_format;
            io::draw::Canvas page(folder / name, 180.0, 90.0);
            draw_profile(page, plot, {5.0, 5.0}, 170.0, 80.0);
            page.finish();
            files.push_back(name);
        }
    }
    if (pdf) {
        pdf->finish();
    }
}

}  // namespace

SectionsReport run_sections(const SectionsJob& job,
                            const fs::path& out_dir,
                            const Progress& progress) {
    if (job.surfaces.empty()) {
        throw UsageError("sections: give at least one surface");
    }
    io::check_output(out_dir, io::OutputKind::folder, "out_dir");  // before any input is read
    io::AtomicDirectory staging(out_dir);
    SectionsReport r;
    const std::vector<LoadedSurface> surfaces =
        load_surfaces(job.surfaces, r.notes, progress.sub(0.0, 0.4));
    const std::vector<Polyline> lines =
        load_lines(job.alignment, job.reader, surfaces.front().crs_wkt);
    if (lines.size() > 1) {
        r.notes.push_back(job.alignment.generic_string() + " has " + std::to_string(lines.size()) +
                          " lines: the first is the alignment");
    }
    const std::vector<SectionLine> cuts = section_lines(lines.front().points, job.options);
    std::vector<std::vector<Point3>> cut_lines;
    for (const SectionLine& l : cuts) {
        cut_lines.push_back({{l.left.x, l.left.y, 0.0}, {l.right.x, l.right.y, 0.0}});
    }
    std::vector<std::vector<Profile>> sections;
    for (const LoadedSurface& s : surfaces) {
        r.surfaces.push_back(s.name);
        sections.push_back(TinSection(s.tin).cut_all(cut_lines, job.threads));
    }
    bool any = false;
    for (std::size_t i = 0; i < cuts.size(); ++i) {
        SectionRow row{cuts[i], {}};
        if (sections.size() >= 2) {
            row.areas = section_areas(sections[0][i], sections[1][i]);
        }
        for (const auto& s : sections) {
            any = any || !s[i].runs.empty();
        }
        r.sections.push_back(row);
    }
    if (!any) {
        throw InputError(
            job.alignment, 0, 0,
            (lines.front().source.empty() ? std::string("the alignment") : lines.front().source) +
                ": no section meets a surface (the alignment lies outside them)");
    }
    if (surfaces.size() >= 2) {
        const TinOverlay overlay(surfaces[0].tin, surfaces[1].tin, {.threads = job.threads});
        r.exact = slab_volumes(difference_surface(overlay, progress.sub(0.5, 0.7)), cuts,
                               progress.sub(0.7, 0.85));
        for (std::size_t k = 0; k + 1 < r.sections.size(); ++k) {
            const double ds = r.sections[k + 1].line.station - r.sections[k].line.station;
            SlabVolume v;
            v.fill = 0.5 * (r.sections[k].areas.fill + r.sections[k + 1].areas.fill) * ds;
            v.cut = 0.5 * (r.sections[k].areas.cut + r.sections[k + 1].areas.cut) * ds;
            r.end_area.push_back(v);
            r.end_area_fill += v.fill;
            r.end_area_cut += v.cut;
            r.exact_fill += r.exact[k].fill;
            r.exact_cut += r.exact[k].cut;
        }
    }
    detail::write_text_file(staging.staging() / "sections.csv", summary_csv(r));
    std::string points = "station,surface,run,offset,x,y,z\n";
    char row[256];
    io::VectorFile gpkg(staging.staging() / "sections.gpkg", surfaces.front().crs_wkt);
    using T = io::VectorField::Type;
    const std::size_t layer =
        gpkg.add_layer("sections", io::VectorGeometry::line_3d,
                       {{"station", T::real}, {"surface", T::text}, {"run", T::integer}});
    for (std::size_t i = 0; i < cuts.size(); ++i) {
        for (std::size_t s = 0; s < sections.size(); ++s) {
            const Profile& p = sections[s][i];
            for (std::size_t run = 0; run < p.runs.size(); ++run) {
                std::vector<Point3> pts;
                for (const ProfilePoint& q : p.runs[run].points) {
                    std::snprintf(row, sizeof row, "%.3f,%s,%zu,%.6f,%.6f,%.6f,%.6f\n",
                                  cuts[i].station, r.surfaces[s].c_str(), run + 1,
                                  q.chainage - job.options.width / 2.0, q.x, q.y, q.z);
                    points += row;
                    pts.push_back({q.x, q.y, q.z});
                }
                gpkg.add_line(layer, pts,
                              {cuts[i].station, r.surfaces[s], static_cast<long long>(run + 1)});
            }
        }
    }
    gpkg.commit();
    detail::write_text_file(staging.staging() / "section_points.csv", points);
    detail::write_text_file(staging.staging() / "sections.json", summary_json(r, job));
    r.files = {"sections.csv", "section_points.csv", "sections.gpkg", "sections.json"};
    progress.report(0.9, "drawing the sections");
    if (!job.plot_format.empty()) {
        write_sheet(staging.staging(), job, r, sections, r.files);
    }
    detail::commit_files(staging, r.files);
    progress.report(1.0, "done");
    return r;
}

}  // namespace dtm::products
