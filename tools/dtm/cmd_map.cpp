// SPDX-License-Identifier: MIT
// dtm map INPUTS... -o map.pdf --scale 500 [--paper A4|A3|A2|A1|A0|WxHmm]
//         [--orientation auto|portrait|landscape] [--extent XMIN,YMIN,XMAX,YMAX] [--sheets]
//         [--title T] [--interval I] [--index-every K] [--hillshade] [--spot-heights N|all|none]
//         [--report map.json]
// The surveyor's contour map at scale: products::map() behind its options (parse -> options ->
// library -> report). Every label position that found no room is counted on stdout and listed
// in the --report JSON.
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "command.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"
#include "dtm/io/map/map.hpp"
#include "dtm/io/output_check.hpp"
#include "dtm/products/map.hpp"
#include "input_args.hpp"
#include "terminal_progress.hpp"
#include "tin_args.hpp"

namespace dtm::cli {
namespace {

struct MapArgs {
    InputArgs input;
    TriangulateOptions tin;
    std::string output;
    std::string paper;
    std::string orientation = "auto";
    std::vector<double> extent;
    std::string spots = "auto";
    std::string report;
    io::map::MapOptions map;
    bool quiet = false;
};

void parse_spots(const std::string& text, io::map::MapOptions& map) {
    if (text == "auto") return;
    if (text == "all") {
        map.spots = io::map::SpotMode::all;
        return;
    }
    if (text == "none" || text == "0") {
        map.spots = io::map::SpotMode::none;
        return;
    }
    std::size_t used = 0;
    long long n = -1;
    try {
        n = std::stoll(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || n <= 0) {
        throw UsageError("map: --spot-heights takes a count, 'all', 'none' or 'auto', not '" +
                         text + "'");
    }
    map.spots = io::map::SpotMode::count;
    map.spot_count = static_cast<std::size_t>(n);
}

void print_summary(const io::map::MapReport& r) {
    const io::map::PageFrame& p = r.layout.pages.front();
    std::printf("map: %zu sheet%s of %.1f x %.1f mm at 1:%g%s -> %s%s\n", r.layout.pages.size(),
                r.layout.pages.size() == 1 ? "" : "s", p.width_mm, p.height_mm, p.scale,
                r.index_page ? " and a sheet index" : "", r.output.string().c_str(),
                r.georeferenced ? " (georeferenced)" : "");
    std::printf("map: %zu contour lines every %g, %zu index; %zu contour labels placed\n",
                r.contour_lines, r.interval, r.index_lines, r.labels.size());
    std::printf("map: %zu spot heights (%zu summits, %zu pits, %zu saddles)\n", r.spots_drawn,
                r.summits, r.pits, r.saddles);
    std::map<std::string, std::size_t> reasons;
    for (const io::map::FailureRecord& f : r.label_failures) ++reasons[to_string(f.reason)];
    if (!r.label_failures.empty()) {
        std::string list;
        for (const auto& [why, n] : reasons) {
            list += (list.empty() ? "" : ", ") + std::to_string(n) + " " + why;
        }
        std::printf("map: %zu contour label positions found no room (%s)\n",
                    r.label_failures.size(), list.c_str());
    }
    if (r.lines_too_short > 0) {
        std::printf("map: %zu index contour pieces are too short for a label\n", r.lines_too_short);
    }
    if (r.spot_labels_failed > 0) {
        std::printf("map: %zu selected spot heights left out: no room for their height\n",
                    r.spot_labels_failed);
    }
    std::printf("map: %.2f s\n", r.seconds);
}

int run_map(MapArgs args) {
    if (!args.paper.empty()) args.map.paper = io::draw::paper_named(args.paper);
    args.map.orientation = io::draw::orientation_named(args.orientation);
    if (!args.extent.empty()) {
        if (args.extent.size() != 4) {
            throw UsageError("map: --extent takes four numbers XMIN,YMIN,XMAX,YMAX");
        }
        args.map.extent = Box2{args.extent[0], args.extent[1], args.extent[2], args.extent[3]};
    }
    parse_spots(args.spots, args.map);
    io::check_output(args.output, io::OutputKind::drawing, "output");
    if (!args.report.empty()) io::check_output(args.report, io::OutputKind::any_file, "report");
    const Progress progress = terminal_progress("map", args.quiet);
    const io::map::MapReport report =
        products::map(to_load_options(args.input), args.output, {args.tin, args.map}, progress);
    if (!args.report.empty()) {
        io::AtomicOutput out(args.report);
        {
            std::ofstream f(out.temp_path(), std::ios::binary);
            f << io::map::map_report_json(report);
            if (!f) throw Error("map: cannot write the report " + args.report);
        }
        out.commit();
    }
    if (!args.quiet) print_summary(report);
    if (!report.georeferenced && report.output.extension() == ".pdf") {
        std::fprintf(stderr,
                     "dtm map: warning: the inputs carry no CRS (give --crs): the map is not "
                     "georeferenced and its grid labels are plain coordinates\n");
    }
    return 0;
}

}  // namespace

Command map_command() {
    return {
        "map", "The surveyor's contour map at scale: a printable, georeferenced PDF (or SVG, PNG)",
        [](CLI::App& app) {
            auto args = std::make_shared<MapArgs>();
            add_input_options(app, args->input);
            add_tin_options(app, args->tin);
            app.add_option("-o,--output", args->output, "Map file: .pdf, .svg or .png")->required();
            app.add_option("--scale", args->map.scale, "Map scale 1:N (e.g. 500)")
                ->required()
                ->check(CLI::PositiveNumber);
            app.add_option("--paper", args->paper,
                           "Paper A4, A3, A2, A1, A0 or WxHmm; the extent then follows from it "
                           "(default: the page follows from the extent and the scale)");
            app.add_option("--orientation", args->orientation,
                           "auto, portrait or landscape (with --paper)");
            app.add_option("--extent", args->extent,
                           "Map extent XMIN,YMIN,XMAX,YMAX in CRS units (default: the surface "
                           "with a margin)")
                ->delimiter(',');
            app.add_flag("--sheets", args->map.sheets,
                         "Split a site larger than one paper into sheets (A3 unless --paper), "
                         "with a sheet index");
            app.add_option("--title", args->map.title, "Title (default: Contour map)");
            app.add_option("--interval", args->map.interval,
                           "Contour interval (default: z range / 20, rounded down)")
                ->check(CLI::PositiveNumber);
            app.add_option("--base", args->map.base, "Levels are base + k * interval (default 0)");
            app.add_option("--index-every", args->map.index_every,
                           "Every K-th level is an index contour, labelled (default 5)");
            app.add_flag("--hillshade", args->map.hillshade, "Hillshade underlay");
            app.add_option("--spot-heights", args->spots,
                           "auto (summits, pits, saddles and a spacing rule), a count N, all or "
                           "none");
            app.add_option("--spot-spacing", args->map.spot_spacing_mm,
                           "Least distance between spot heights in page mm (default 30)")
                ->check(CLI::PositiveNumber);
            app.add_option("--spot-decimals", args->map.spot_decimals,
                           "Decimals of spot heights (default: 2 up to 1:1000, 1 up to 1:5000)");
            app.add_option("--label-spacing", args->map.label_spacing_mm,
                           "Distance between contour labels along a line, page mm (default 120)")
                ->check(CLI::PositiveNumber);
            app.add_option("--vertical-datum", args->map.vertical_datum,
                           "Height system for the title block (e.g. Bpv)");
            app.add_option("--date", args->map.date, "Date in the title block (default: today)");
            app.add_option("--dpi", args->map.png_dpi, "PNG resolution (default 200)")
                ->check(CLI::PositiveNumber);
            app.add_option("--report", args->report,
                           "JSON report: every placed label with its page box, every failure");
            app.add_flag("-q,--quiet", args->quiet, "No progress and no summary");
            return [args]() { return run_map(*args); };
        }};
}

}  // namespace dtm::cli
