// SPDX-License-Identifier: MIT
// One registry method on loaded survey inputs (lab/run.hpp).
#include "dtm/lab/run.hpp"

#include <algorithm>
#include <chrono>

#include "dtm/algo/line_heights.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/faces_file.hpp"
#include "dtm/io/json_writer.hpp"
#include "dtm/io/tin_file.hpp"

namespace dtm::lab {

MethodPoints method_points(TerrainInput& terrain) {
    (void)resolve_line_heights(terrain);
    MethodPoints out;
    out.points = std::move(terrain.points);
    for (const Polyline& line : terrain.breaklines) {
        for (std::size_t i = 0; i < line.points.size(); ++i) {
            out.points.push_back(line.points[i]);
            if (i > 0) {
                const auto b = static_cast<VertexIndex>(out.points.size() - 1);
                out.segments.emplace_back(b - 1, b);
            }
        }
    }
    return out;
}

io::OutputKind method_output_kind(const methods::MethodInfo& method) {
    if (method.output == methods::Output::all_triangulations) return io::OutputKind::folder;
    if (method.output == methods::Output::polygon_faces) return io::OutputKind::any_file;
    return io::OutputKind::tin;
}

void write_method_output(const methods::MethodInfo& method,
                         const methods::MethodResult& result,
                         const std::filesystem::path& path,
                         const std::string& crs_wkt) {
    if (method.output == methods::Output::all_triangulations) {
        io::write_tin_series(result.all, path, crs_wkt);
    } else if (method.output == methods::Output::polygon_faces) {
        io::write_polygon_faces(result.tin.vertices, result.faces, path, {crs_wkt, false});
    } else {
        io::TinWriteOptions options;
        options.crs_wkt = crs_wkt;
        io::write_tin(result.tin, path, options);
    }
}

std::string method_stats_json(const methods::MethodInfo& method,
                              std::size_t points,
                              const methods::MethodResult& result,
                              double seconds) {
    const methods::MethodCounters& c = result.counters;
    std::string counters = "{\"orient_calls\": " + std::to_string(c.orient_calls) +
                           ", \"incircle_calls\": " + std::to_string(c.incircle_calls) +
                           ", \"flips\": " + std::to_string(c.flips) +
                           ", \"walk_steps\": " + std::to_string(c.walk_steps) +
                           ", \"peak_bytes\": " + std::to_string(c.peak_bytes);
    for (const auto& [key, value] : c.extra) {
        counters += ", " + io::json_string(key) + ": " + std::to_string(value);
    }
    counters += "}";
    return "{\"method\": " + io::json_string(method.name) +
           ", \"points\": " + std::to_string(points) +
           ", \"vertices\": " + std::to_string(result.tin.vertices.size()) +
           ", \"triangles\": " + std::to_string(result.tin.triangles.size()) +
           ", \"seconds\": " + io::json_number(seconds) + ", \"counters\": " + counters +
           (result.stats_json.empty() ? "" : ", ") + result.stats_json + "}";
}

MethodRun run_method(const std::string& name,
                     const io::LoadOptions& load,
                     const methods::MethodOptions& options,
                     const std::filesystem::path& output,
                     const Progress& progress) {
    MethodRun run;
    run.method = methods::find_method(name);
    if (run.method == nullptr) {
        throw UsageError("methods run: unknown method '" + name +
                         "' (dtm methods list shows them)");
    }
    const auto refuse_lines = [&] {
        throw UsageError("methods run: method '" + name + "' takes no breaklines");
    };
    io::check_output(output, method_output_kind(*run.method), "output");
    const bool lines = std::any_of(load.files.begin(), load.files.end(), [](const auto& f) {
        return f.role == io::InputRole::breaklines;
    });
    if (lines && !run.method->takes_constraints) refuse_lines();
    io::LoadedInputs loaded = io::load_inputs(load, progress.sub(0.0, 0.1));
    const MethodPoints input = method_points(loaded.terrain);
    if (!input.segments.empty() && !run.method->takes_constraints) refuse_lines();
    run.points = input.points.size();
    const auto start = std::chrono::steady_clock::now();
    run.result = run.method->run(methods::MethodInput{input.points, input.segments}, options,
                                 progress.sub(0.1, 0.95));
    run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    write_method_output(*run.method, run.result, output, loaded.crs_wkt);
    progress.report(1.0, "done");
    return run;
}

std::string registry_json() {
    const auto methods = methods::registry();
    std::string out = "[";
    for (std::size_t i = 0; i < methods.size(); ++i) {
        const methods::MethodInfo& m = methods[i];
        out += (i ? ",\n " : "\n ");
        out += "{\"name\": " + io::json_string(m.name) +
               ", \"family\": " + io::json_string(methods::family_name(m.family)) +
               ", \"source\": " + io::json_string(m.source) +
               ", \"complexity\": " + io::json_string(m.complexity) +
               ", \"summary\": " + io::json_string(m.summary) +
               ", \"takes_constraints\": " + (m.takes_constraints ? "true" : "false") +
               ", \"quadratic\": " + (m.quadratic ? "true" : "false") +
               ", \"params\": " + io::json_string(m.params) + "}";
    }
    return out + "\n]";
}

}  // namespace dtm::lab
