// SPDX-License-Identifier: MIT
#include "distributed.hpp"

#include <tbb/global_control.h>
#include <tbb/info.h>

#include <algorithm>
#include <memory>
#include <string>

#include "dtm/core/error.hpp"
#include "dtm/dist/mpi_comm.hpp"
#include "dtm/io/extension.hpp"
#include "dtm/io/reader.hpp"

namespace dtm::cli {
namespace {
dist::Comm* job = nullptr;
}  // namespace

dist::Comm* distributed_comm() noexcept { return job; }
void set_distributed_comm(dist::Comm* comm) noexcept { job = comm; }
bool prints() noexcept { return job == nullptr || job->rank() == 0; }

unsigned threads_per_rank(unsigned cores, unsigned local_ranks) noexcept {
    if (local_ranks == 0) return std::max(cores, 1u);
    return std::max(cores / local_ranks, 1u);
}

void share_cores_among_local_ranks() {
    static std::unique_ptr<tbb::global_control> control;
    const auto cores = static_cast<unsigned>(std::max(tbb::info::default_concurrency(), 1));
    const auto local = static_cast<unsigned>(std::max(dist::launched_local_ranks(), 0));
    control = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                    threads_per_rank(cores, local));
}

void check_distributed_input(const char* command,
                             const InputArgs& in,
                             const TriangulateOptions& triangulate) {
    const auto refuse = [command](const std::string& what) {
        throw UsageError(std::string(command) + ": a distributed run (mpirun) does not take " +
                         what + " yet");
    };
    if (in.inputs.size() != 1) refuse("more than one input file");
    if (!in.flat_areas.empty()) refuse("flat areas");
    const std::string_view reader = io::find_reader(in.inputs[0]).name;
    if (reader != "csv" && reader != "ogr" && reader != "csv-wkt") {
        refuse("a ." + io::lower_extension(in.inputs[0]) +
               " input (text point lists such as .csv, .txt, .xyz, and OGR point sources such "
               "as .shp, .gpkg, .fgb, .geojson)");
    }
    if (in.dem.clip_radius > 0.0 || in.dem.max_error > 0.0) refuse("DEM thinning");
    if (triangulate.snap_distance > 0.0 || triangulate.optimize != Criterion::delaunay) {
        refuse("`snap` or `optimize`");
    }
}

products::DistributedSource distributed_source(const InputArgs& in,
                                               const TriangulateOptions& triangulate) {
    products::DistributedSource source;
    source.input = {in.inputs[0], io::InputRole::points};
    source.read = in.read;
    source.default_crs = in.crs.default_crs;
    source.target_crs = in.crs.target_crs;
    source.duplicates = triangulate.duplicates;
    for (const std::string& f : in.breaklines)
        source.lines.push_back({f, io::InputRole::breaklines});
    for (const std::string& f : in.soft_breaklines)
        source.lines.push_back({f, io::InputRole::soft_breaklines});
    for (const std::string& f : in.boundaries) source.lines.push_back({f, io::InputRole::boundary});
    for (const std::string& f : in.holes) source.lines.push_back({f, io::InputRole::holes});
    source.z_tolerance = triangulate.z_tolerance;
    source.max_edge = triangulate.max_edge;
    return source;
}

}  // namespace dtm::cli
