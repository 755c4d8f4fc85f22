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
#include "input_args.hpp"
#include "json_text.hpp"

namespace dtm::cli {
namespace {

bool has_extent(const io::InputSummary& s)
{
    return s.points + s.breakline_vertices + s.boundaries + s.holes > 0;
}

void print_json(std::ostream& out, const io::LoadedInputs& loaded)
{
    out << "{\"inputs\": [";
    for (std::size_t i = 0; i < loaded.summaries.size(); ++i) {
        const io::InputSummary& s = loaded.summaries[i];
        const bool extent = has_extent(s);
        const bool heights = s.z_range[0] <= s.z_range[1];
        out << (i ? ",\n  " : "\n  ") << "{\"path\": " << json_string(s.path.string())
            << ", \"format\": " << json_string(s.format) << ", \"crs\": "
            << (s.crs.empty() ? "null" : json_string(s.crs)) << ", \"points\": " << s.points
            << ", \"breaklines\": " << s.breaklines
            << ", \"breakline_vertices\": " << s.breakline_vertices
            << ", \"boundaries\": " << s.boundaries << ", \"holes\": " << s.holes
            << ", \"bbox\": ";
        if (extent) {
            out << "[" << json_number(s.bbox[0]) << ", " << json_number(s.bbox[1]) << ", "
                << json_number(s.bbox[2]) << ", " << json_number(s.bbox[3]) << "]";
        } else {
            out << "null";
        }
        out << ", \"z_range\": ";
        if (heights) {
            out << "[" << json_number(s.z_range[0]) << ", " << json_number(s.z_range[1]) << "]";
        } else {
            out << "null";
        }
        out << ", \"duplicates\": " << s.duplicates << ", \"skipped_lines\": " << s.skipped_lines
            << ", \"warnings\": [";
        for (std::size_t w = 0; w < s.warnings.size(); ++w) {
            out << (w ? ", " : "") << json_string(s.warnings[w]);
        }
        out << "]}";
    }
    out << "\n]}\n";
}

void print_table(std::ostream& out, const io::LoadedInputs& loaded)
{
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
            << "  points             " << s.points << "\n"
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
        for (const std::string& w : s.warnings) out << "  warning            " << w << "\n";
    }
}

}  // namespace

Command info_command()
{
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
