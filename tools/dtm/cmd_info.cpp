// SPDX-License-Identifier: MIT
// dtm info INPUTS... [--json]: what each reader found in each input (format, CRS, counts, extent,
// duplicates, skipped lines, warnings). Extents are in each input's own CRS.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

#include "command.hpp"
#include "dtm/io/inputs.hpp"
#include "dtm/io/json_writer.hpp"
#include "input_args.hpp"
#include "option_names.hpp"

namespace dtm::cli {
namespace {

bool has_extent(const io::InputSummary& s) {
    return s.points + s.breakline_vertices + s.boundaries + s.holes > 0;
}

void print_json(std::ostream& out, const io::LoadedInputs& loaded) {
    using Layout = io::JsonWriter::Layout;
    io::JsonWriter json;
    json.begin_object({}, Layout::inline_);
    json.begin_array("inputs");
    for (const io::InputSummary& s : loaded.summaries) {
        json.begin_object({}, Layout::inline_);
        json.value("path", s.path.string());
        json.value("format", s.format);
        if (s.crs.empty()) {
            json.null("crs");
        } else {
            json.value("crs", s.crs);
        }
        if (!s.crs_note.empty()) json.value("crs_note", s.crs_note);
        json.value("points", s.points);
        json.value("triangles", s.triangles);
        json.value("breaklines", s.breaklines);
        json.value("breakline_vertices", s.breakline_vertices);
        json.value("boundaries", s.boundaries);
        json.value("holes", s.holes);
        if (has_extent(s)) {
            json.begin_array("bbox", Layout::inline_);
            for (const double v : s.bbox) json.value({}, v);
            json.end();
        } else {
            json.null("bbox");
        }
        if (s.z_range[0] <= s.z_range[1]) {
            json.begin_array("z_range", Layout::inline_);
            for (const double v : s.z_range) json.value({}, v);
            json.end();
        } else {
            json.null("z_range");
        }
        json.value("duplicates", s.duplicates);
        json.value("skipped_lines", s.skipped_lines);
        json.begin_array("warnings", Layout::inline_);
        for (const std::string& w : s.warnings) json.value({}, cli_text(w));
        json.end();
        json.end();
    }
    json.end();
    json.end();
    out << json.str();
}

void print_table(std::ostream& out, const io::LoadedInputs& loaded) {
    for (const io::InputSummary& s : loaded.summaries) {
        std::ostringstream bbox;
        bbox.precision(12);
        if (has_extent(s)) {
            bbox << s.bbox[0] << ", " << s.bbox[1] << " .. " << s.bbox[2] << ", " << s.bbox[3];
        } else {
            bbox << "-";
        }
        out << s.path.string() << "\n"
            << "  format             " << s.format << "\n"
            << "  crs                " << (s.crs.empty() ? "(none)" : s.crs) << "\n"
            << (s.crs_note.empty() ? "" : "  crs identification " + s.crs_note + "\n")
            << "  points             " << s.points << "\n"
            << "  triangles          " << s.triangles << "\n"
            << "  breaklines         " << s.breaklines << " (" << s.breakline_vertices
            << " vertices)\n"
            << "  boundaries         " << s.boundaries << "\n"
            << "  holes              " << s.holes << "\n"
            << "  bbox               " << bbox.str() << "\n"
            << "  z range            "
            << (s.z_range[0] <= s.z_range[1]
                    ? std::to_string(s.z_range[0]) + " .. " + std::to_string(s.z_range[1])
                    : std::string("-"))
            << "\n"
            << "  duplicates (xy)    " << s.duplicates << "\n"
            << "  skipped lines      " << s.skipped_lines << "\n";
        for (const std::string& w : s.warnings)
            out << "  warning            " << cli_text(w) << "\n";
    }
}

}  // namespace

Command info_command() {
    return {"info", "Show what each input holds (format, CRS, counts, extent, duplicates)",
            [](CLI::App& app) {
                auto args = std::make_shared<InputArgs>();
                auto json = std::make_shared<bool>(false);
                add_input_options(app, *args);
                app.add_flag("--json", *json, "One JSON object {\"inputs\": [...]}");
                return [args, json]() -> int {
                    const io::LoadedInputs loaded = io::load_inputs(to_load_options(*args));
                    if (*json) {
                        print_json(std::cout, loaded);
                    } else {
                        print_table(std::cout, loaded);
                    }
                    return 0;
                };
            }};
}

}  // namespace dtm::cli
