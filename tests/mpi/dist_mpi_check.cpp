// SPDX-License-Identifier: MIT
// Run under `mpirun -np P`: each distributed step on real MPI ranks gives every rank the same
// result and the same per-phase byte counters as the same job on P in-process ranks, and the
// serial answer (the kernel's subtrees, the serial duplicate merge); random delays before every
// send change nothing. Prints one line per failure; exit 0 when all hold.
#include <algorithm>
#include <bit>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <string>

#include "algo/detail/delaunay_dc.hpp"
#include "algo/detail/input_merge.hpp"
#include "dist/constraints.hpp"
#include "dist/kernel.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/dist/duplicates.hpp"
#include "dtm/dist/in_process.hpp"
#include "dtm/dist/mpi_comm.hpp"
#include "dtm/dist/partition.hpp"
#include "dtm/io/formats/ply.hpp"
#include "io/formats/ply/ply_dist_writer.hpp"
#include "support/dist_cases.hpp"
#include "support/dist_lines.hpp"

namespace {

using namespace dtm;
using namespace dtm::dist;

using Words = std::vector<std::uint64_t>;
using Traffic = std::map<std::string, PhaseTraffic>;

/// A step run on one rank: its result as words (compared between MPI and in-process).
using Job = std::function<Words(Comm&)>;
/// Checks the concatenated results of all ranks against the serial answer ("" when equal).
using Oracle = std::function<std::string(const std::vector<Words>&)>;

std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }

/// The counters of every phase since @p before, appended to @p words.
void append_traffic(Words& words, const Comm& comm, const Traffic& before) {
    for (const auto& [phase, now] : comm.traffic()) {
        const auto then = before.find(phase);
        const PhaseTraffic zero{};
        const PhaseTraffic& b = then == before.end() ? zero : then->second;
        if (now.calls == b.calls) continue;
        words.push_back(std::hash<std::string>{}(phase));
        words.push_back(now.bytes - b.bytes);
        words.push_back(now.messages - b.messages);
        words.push_back(now.calls - b.calls);
    }
}

Words partition_job(Comm& comm, const std::vector<Point>& points, bool strided) {
    const Share share = partition_points(
        comm, test::initial_share(points, comm.rank(), comm.size(), strided), {}, {});
    Words words;
    for (std::size_t i = share.first_leaf; i < share.last_leaf; ++i) {
        const std::size_t a = share.offsets[i - share.first_leaf];
        const std::size_t b = share.offsets[i - share.first_leaf + 1];
        words.push_back(i);
        words.push_back(b - a);
        for (std::size_t k = a; k < b; ++k) words.push_back(share.points[k].id);
    }
    return words;
}

std::string partition_oracle(const std::vector<Words>& all,
                             const std::vector<Point>& points,
                             int ranks) {
    const auto serial = test::serial_kernel_order(points);
    const auto leaves = tree_leaves(points.size(), ranks, 3);
    std::size_t placed = 0;
    for (const Words& words : all) {
        for (std::size_t at = 0; at < words.size();) {
            const Leaf& leaf = leaves[words[at]];
            const std::size_t n = words[at + 1];
            Words got(words.begin() + static_cast<std::ptrdiff_t>(at + 2),
                      words.begin() + static_cast<std::ptrdiff_t>(at + 2 + n));
            Words want(serial.begin() + static_cast<std::ptrdiff_t>(leaf.lo),
                       serial.begin() + static_cast<std::ptrdiff_t>(leaf.hi));
            std::sort(got.begin(), got.end());
            std::sort(want.begin(), want.end());
            if (got != want)
                return "leaf " + std::to_string(words[at]) + " is not the serial subtree";
            placed += n;
            at += 2 + n;
        }
    }
    return placed == points.size() ? "" : "points placed: " + std::to_string(placed);
}

Words duplicates_job(Comm& comm, const std::vector<InputPoint>& all, DuplicateRule rule) {
    const auto r = static_cast<std::size_t>(comm.rank());
    const auto p = static_cast<std::size_t>(comm.size());
    const std::span<const InputPoint> mine(all.data() + r * all.size() / p,
                                           (r + 1) * all.size() / p - r * all.size() / p);
    const MergedShare share = merge_exact_duplicates(comm, mine, rule);
    Words words{share.vertex_of_input.size()};
    words.insert(words.end(), share.vertex_of_input.begin(), share.vertex_of_input.end());
    for (const Vertex& v : share.vertices) {
        words.insert(words.end(),
                     {v.id, bits(v.p.x), bits(v.p.y), bits(v.p.z), v.z_known ? 1U : 0U});
    }
    for (const DuplicateMerge& m : share.merges) {
        words.insert(words.end(), {m.kept_input, m.merged_input, bits(m.kept.z)});
    }
    return words;
}

Words kernel_job(Comm& comm, const std::vector<Point>& points, bool strided) {
    const Share share = partition_points(
        comm, test::initial_share(points, comm.rank(), comm.size(), strided), {}, {});
    const DistributedMesh d = triangulate_share(comm, share, {}, {});
    Words words{d.mesh.tris.size()};
    for (const GlobalTriangle& t : d.mesh.global_triangles()) {
        words.insert(words.end(), t.v.begin(), t.v.end());
        words.insert(words.end(), t.n.begin(), t.n.end());
    }
    words.insert(words.end(), d.input_ids.begin(), d.input_ids.end());
    return words;
}

/// The ranks' slots and vertex ids, concatenated, equal the serial kernel's.
std::string kernel_oracle(const std::vector<Words>& all, const std::vector<Point>& points) {
    const test::SerialKernel serial = test::serial_kernel(points);
    Words slots;
    Words ids;
    for (const Words& words : all) {
        const std::size_t n = words[0];
        slots.insert(slots.end(), words.begin() + 1,
                     words.begin() + 1 + static_cast<std::ptrdiff_t>(6 * n));
        ids.insert(ids.end(), words.begin() + 1 + static_cast<std::ptrdiff_t>(6 * n), words.end());
    }
    Words want_slots;
    for (const GlobalTriangle& g : serial.tris) {
        want_slots.insert(want_slots.end(), g.v.begin(), g.v.end());
        want_slots.insert(want_slots.end(), g.n.begin(), g.n.end());
    }
    if (slots != want_slots) return "triangle slots differ from the serial kernel";
    const Words& want_ids = serial.ids;
    return ids == want_ids ? "" : "vertex order differs from the serial kernel";
}

/// Breaklines inserted across ranks: every slot and its constraint bits.
Words constraints_job(Comm& comm, const test::LineCase& c) {
    const Share share = partition_points(
        comm, test::initial_share(c.points, comm.rank(), comm.size(), true), {}, {});
    DistributedMesh d = triangulate_share(comm, share, {}, {});
    insert_constraints(comm, d, c.segments, {});
    Words words;
    const auto tris = d.mesh.global_triangles();
    for (std::size_t s = 0; s < tris.size(); ++s) {
        words.insert(words.end(), tris[s].v.begin(), tris[s].v.end());
        words.insert(words.end(), tris[s].n.begin(), tris[s].n.end());
        for (const std::uint8_t b : d.mesh.bits[s]) words.push_back(b);
    }
    return words;
}

std::string constraints_oracle(const std::vector<Words>& all, const test::LineCase& c) {
    const test::ConstrainedMesh serial = test::serial_constrained(c);
    Words want;
    for (std::size_t s = 0; s < serial.tris.size(); ++s) {
        want.insert(want.end(), serial.tris[s].v.begin(), serial.tris[s].v.end());
        want.insert(want.end(), serial.tris[s].n.begin(), serial.tris[s].n.end());
        for (const std::uint8_t b : serial.bits[s]) want.push_back(b);
    }
    Words got;
    for (const Words& w : all) got.insert(got.end(), w.begin(), w.end());
    return got == want ? "" : "slots or constraint bits differ from the serial insertion";
}

std::string duplicates_oracle(const std::vector<Words>& all,
                              const TerrainInput& input,
                              DuplicateRule rule) {
    TriangulateOptions options;
    options.duplicates = rule;
    const detail::MergedInput serial = detail::merge_input(input, options);
    std::size_t at_input = 0;
    for (const Words& words : all) {
        for (std::size_t i = 0; i < words[0]; ++i, ++at_input) {
            if (words[1 + i] != serial.vertex_of_input(at_input)) {
                return "input " + std::to_string(at_input) + " has another vertex than serially";
            }
        }
    }
    return at_input == serial.points_in ? "" : "inputs: " + std::to_string(at_input);
}

/// A rank's job result with its counters since @p before: [result size, result, counters].
Words with_traffic(const Words& result, const Comm& comm, const Traffic& before) {
    Words words{result.size()};
    words.insert(words.end(), result.begin(), result.end());
    append_traffic(words, comm, before);
    return words;
}

/// Runs @p job on the MPI ranks and (on rank 0) on as many in-process ranks; "" when equal.
std::string compare(Comm& world, const Job& job, const Oracle& oracle) {
    const Traffic before = world.traffic();
    const Words mine = with_traffic(job(world), world, before);
    const auto gathered = world.allgatherv(to_bytes(std::span<const std::uint64_t>(mine)));
    if (world.rank() != 0) return {};
    std::vector<Words> mpi;
    for (const Bytes& b : gathered) mpi.push_back(from_bytes<std::uint64_t>(b));
    std::vector<Words> in_process(mpi.size());
    run_in_process(world.size(), [&](Comm& comm) {
        in_process[static_cast<std::size_t>(comm.rank())] = with_traffic(job(comm), comm, {});
    });
    std::vector<Words> results;
    for (std::size_t r = 0; r < mpi.size(); ++r) {
        if (mpi[r] != in_process[r]) {
            return "rank " + std::to_string(r) +
                   ": result or byte counters differ from the in-process run";
        }
        results.emplace_back(mpi[r].begin() + 1,
                             mpi[r].begin() + 1 + static_cast<std::ptrdiff_t>(mpi[r][0]));
    }
    return oracle(results);
}

std::string file_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The PLY of the distributed pipeline (duplicates, partition, kernel, MPI-IO write) against the
/// serial triangulate() + write_tin_ply() on rank 0; "" when the bytes are equal.
std::string ply_check(Comm& world, const TerrainInput& input) {
    Bytes dir_bytes;
    if (world.rank() == 0) {
        char pattern[] = "/tmp/dtm_mpi_check_XXXXXX";
        const std::string dir = mkdtemp(pattern) ? pattern : "";
        const auto* p = reinterpret_cast<const std::byte*>(dir.data());
        dir_bytes.assign(p, p + dir.size());
    }
    world.bcast(dir_bytes, 0);
    const std::filesystem::path dir(
        std::string(reinterpret_cast<const char*>(dir_bytes.data()), dir_bytes.size()));
    const auto all = test::combined_input(input);
    const auto r = static_cast<std::size_t>(world.rank());
    const auto p = static_cast<std::size_t>(world.size());
    const std::span<const InputPoint> mine(all.data() + r * all.size() / p,
                                           (r + 1) * all.size() / p - r * all.size() / p);
    const MergedShare merged = merge_exact_duplicates(world, mine, DuplicateRule::mean);
    std::vector<Point> points;
    for (const Vertex& v : merged.vertices) points.push_back({v.p.x, v.p.y, v.id});
    const Share share = partition_points(world, std::move(points), {}, {});
    const DistributedMesh kernel = triangulate_share(world, share, {}, {});
    io::TinWriteOptions options;
    options.crs_wkt = "PROJCRS[\"S-JTSK / Krovak East North\",ID[\"EPSG\",5514]]";
    io::write_distributed_ply(world, merged, kernel, dir / "dist.ply", options);
    std::string error;
    if (world.rank() == 0) {
        TriangulateOptions topts;
        topts.duplicates = DuplicateRule::mean;
        io::write_tin_ply(triangulate(input, topts).tin, dir / "serial.ply", options);
        if (file_bytes(dir / "dist.ply") != file_bytes(dir / "serial.ply")) {
            error = "the PLY differs from the serial one";
        }
        std::filesystem::remove_all(dir);
    }
    return error;
}

}  // namespace

int main(int argc, char** argv) {
    MpiSession session(argc, argv);
    Comm& world = session.world();
    const int ranks = world.size();
    int failures = 0;
    const auto run_check = [&](const std::string& what, const std::function<std::string()>& check) {
        std::string error;
        try {
            error = check();
        } catch (const std::exception& e) {
            error = e.what();
        }
        Bytes verdict(error.size());
        if (!error.empty()) std::memcpy(verdict.data(), error.data(), error.size());
        world.bcast(verdict, 0);
        if (verdict.empty()) return;
        ++failures;
        if (world.rank() == 0) {
            std::fprintf(stderr, "FAIL %s on %d ranks: %.*s\n", what.c_str(), ranks,
                         static_cast<int>(verdict.size()),
                         reinterpret_cast<const char*>(verdict.data()));
        }
    };
    const auto run = [&](const std::string& what, const Job& job, const Oracle& oracle) {
        run_check(what, [&] { return compare(world, job, oracle); });
    };
    const TerrainInput dup_input = test::duplicate_rich_input(4000, 11);
    const std::vector<InputPoint> dup_points = test::combined_input(dup_input);
    for (bool jitter : {false, true}) {
        if (jitter) world.set_jitter(500, 3);
        const std::string suffix = jitter ? " (jitter)" : "";
        for (const auto& c : test::dist_cases(20000)) {
            for (bool strided : {false, true}) {
                run(
                    "partition " + c.name + (strided ? " strided" : "") + suffix,
                    [&](Comm& comm) { return partition_job(comm, c.points, strided); },
                    [&](const std::vector<Words>& all) {
                        return partition_oracle(all, c.points, ranks);
                    });
            }
        }
        for (const auto& c : test::dist_cases(20000)) {
            run(
                "kernel " + c.name + suffix,
                [&](Comm& comm) { return kernel_job(comm, c.points, true); },
                [&](const std::vector<Words>& all) { return kernel_oracle(all, c.points); });
        }
        for (const auto& c : test::dist_cases(20000)) {
            if (c.points.size() < 1000 || c.name == "collinear") continue;
            const test::LineCase lines = test::with_lines(c);
            run(
                "constraints " + c.name + suffix,
                [&](Comm& comm) { return constraints_job(comm, lines); },
                [&](const std::vector<Words>& all) { return constraints_oracle(all, lines); });
        }
        for (DuplicateRule rule : {DuplicateRule::first, DuplicateRule::mean, DuplicateRule::max}) {
            run(
                "duplicates rule " + std::to_string(static_cast<int>(rule)) + suffix,
                [&](Comm& comm) { return duplicates_job(comm, dup_points, rule); },
                [&](const std::vector<Words>& all) {
                    return duplicates_oracle(all, dup_input, rule);
                });
        }
    }
    for (const auto& c : test::dist_cases(20000)) {
        if (c.points.size() < 3 || c.name == "collinear") continue;
        TerrainInput input;
        for (const auto& q : c.points) input.points.push_back({q.x, q.y, q.x * 0.01 - q.y * 0.02});
        run_check("ply " + c.name, [&] { return ply_check(world, input); });
    }
    TerrainInput duplicates = test::duplicate_rich_input(4000, 11);
    duplicates.soft_breaklines.clear();
    run_check("ply duplicates", [&] { return ply_check(world, duplicates); });
    if (world.rank() == 0 && failures == 0) {
        std::printf("distributed steps on %d MPI ranks: equal to in-process and serial\n", ranks);
    }
    return failures == 0 ? 0 : 1;
}
