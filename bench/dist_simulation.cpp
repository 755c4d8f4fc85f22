// SPDX-License-Identifier: MIT
// The distributed kernel on P in-process ranks (bench/dist_simulation.sh): for each point count
// and rank count, the wall time of partition + kernel against the serial kernel in the same run,
// the bytes every phase moves (summed over ranks), the band triangles the merging ranks received,
// widenings, and a check that the slots equal the serial kernel's. Virtual ranks share this
// machine's cores, so the times measure overhead, not cluster speed; bytes and bands are exact.
// Usage: dist_simulation [N...] (default 100000 1000000); ranks 1 2 4 8 16 64. Under mpirun the
// same job runs once on the MPI ranks instead (every rank also runs the serial kernel as the
// reference and checks its own slots against it).
#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <mutex>
#include <random>
#include <string>
#include <vector>

#include "algo/detail/delaunay_dc.hpp"
#include "dist/kernel.hpp"
#include "dtm/dist/in_process.hpp"
#include "dtm/dist/mpi_comm.hpp"
#include "dtm/dist/partition.hpp"

namespace {

using namespace dtm;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

/// Point i of a uniform set over 2 km x 2 km at S-JTSK offsets, from a hash of i: any rank can
/// make its own part.
dist::Point uniform_point(std::uint64_t i) {
    const auto mix = [](std::uint64_t z) {
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
        return z ^ (z >> 31);
    };
    const double a = static_cast<double>(mix(2 * i + 0x9E3779B97F4A7C15ULL) >> 11) * 0x1p-53;
    const double b = static_cast<double>(mix(2 * i + 1 + 0x9E3779B97F4A7C15ULL) >> 11) * 0x1p-53;
    return {-750000.0 + 2000.0 * a, -1050000.0 + 2000.0 * b, i};
}

std::vector<dist::Point> uniform(std::size_t first, std::size_t last) {
    std::vector<dist::Point> pts;
    pts.reserve(last - first);
    for (std::size_t i = first; i < last; ++i) pts.push_back(uniform_point(i));
    return pts;
}

std::vector<dist::Point> uniform(std::size_t n) { return uniform(0, n); }

/// Resident memory of this process now, bytes (/proc/self/statm).
std::int64_t current_rss() {
    long pages = 0, resident = 0;
    if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
        std::fclose(f);
    }
    return static_cast<std::int64_t>(resident) * sysconf(_SC_PAGESIZE);
}

/// Peak resident memory of this process, bytes.
std::int64_t peak_rss() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<std::int64_t>(usage.ru_maxrss) * 1024;
}

}  // namespace

/// One run on the MPI ranks: the slowest rank's time against the serial kernel's.
int run_mpi(int argc, char** argv, const std::vector<std::size_t>& sizes) {
    dist::MpiSession session(argc, argv);
    dist::Comm& comm = session.world();
    const auto r = static_cast<std::size_t>(comm.rank());
    const auto p = static_cast<std::size_t>(comm.size());
    int failures = 0;
    // DTM_SIM_MEMORY=1: no serial reference (it would hold every point on every rank); every
    // rank's peak resident memory per point of its share instead.
    const bool memory_only = std::getenv("DTM_SIM_MEMORY") != nullptr;
    // What the process holds before any point (MPI, TBB, the libraries): not per point.
    const std::int64_t start_rss = current_rss();
    for (std::size_t n : sizes) {
        double serial_s = 0.0;
        detail::GhostMesh serial;
        if (!memory_only) {
            detail::BigArray<detail::KernelPoint> kp(n);
            for (std::size_t i = 0; i < n; ++i) {
                const dist::Point q = uniform_point(i);
                kp[i] = {{q.x, q.y}, static_cast<std::uint32_t>(i)};
            }
            const auto t = Clock::now();
            detail::delaunay_divide_and_conquer(kp, serial, {}, {});
            serial_s = seconds_since(t);
        }
        std::vector<dist::Point> mine = uniform(r * n / p, (r + 1) * n / p);
        comm.barrier();
        const auto t0 = Clock::now();
        dist::Share share = dist::partition_points(comm, std::move(mine), {}, {});
        const dist::DistributedMesh d = dist::triangulate_share(comm, std::move(share), {}, {});
        const auto micros = static_cast<std::int64_t>(seconds_since(t0) * 1e6);
        std::int64_t bad = 0;
        for (std::size_t k = 0; !memory_only && k < d.mesh.tris.size(); ++k) {
            const std::uint64_t slot = d.mesh.first_slot + k;
            bad += d.mesh.at(slot) == dist::to_global(serial.tris[slot], 0, 0) ? 0 : 1;
        }
        const std::int64_t slowest = comm.allreduce(micros, dist::Reduce::max);
        bad = comm.allreduce(bad, dist::Reduce::sum);
        const std::int64_t per_point =
            peak_rss() / std::max<std::int64_t>(1, static_cast<std::int64_t>(d.input_ids.size()));
        const std::int64_t worst = comm.allreduce(per_point, dist::Reduce::max);
        const std::int64_t net_per_point =
            (peak_rss() - start_rss) /
            std::max<std::int64_t>(1, static_cast<std::int64_t>(d.input_ids.size()));
        const std::int64_t worst_net = comm.allreduce(net_per_point, dist::Reduce::max);
        const std::int64_t start_mib = comm.allreduce(start_rss >> 20, dist::Reduce::max);
        failures += bad > 0 ? 1 : 0;
        if (comm.rank() == 0) {
            if (memory_only) {
                std::printf(
                    "| %zu | %zu MPI ranks | %.3f s | peak per rank at most %lld bytes per point "
                    "of its share; %lld above the %lld MiB a rank holds before any point |\n",
                    n, p, static_cast<double>(slowest) / 1e6, static_cast<long long>(worst),
                    static_cast<long long>(worst_net), static_cast<long long>(start_mib));
            } else {
                std::printf(
                    "| %zu | %zu MPI ranks | %.3f s | %.3f s | %.2f | slots differing: %lld |\n", n,
                    p, serial_s, static_cast<double>(slowest) / 1e6,
                    static_cast<double>(slowest) / 1e6 / serial_s, static_cast<long long>(bad));
            }
        }
    }
    return failures == 0 ? 0 : 1;
}

int main(int argc, char** argv) {
    std::vector<std::size_t> sizes;
    for (int i = 1; i < argc; ++i) sizes.push_back(std::strtoull(argv[i], nullptr, 10));
    if (sizes.empty()) sizes = {100000, 1000000};
    if (dist::launched_ranks() > 0 && dist::mpi_built()) return run_mpi(argc, argv, sizes);
    std::printf(
        "| points | ranks | serial kernel | partition + kernel | ratio | partition MB | shuffle MB "
        "| "
        "band MB | results MB | band triangles | band / sqrt(n) | widenings | same slots |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (std::size_t n : sizes) {
        const auto points = uniform(n);
        detail::BigArray<detail::KernelPoint> kp(n);
        for (std::size_t i = 0; i < n; ++i) {
            kp[i] = {{points[i].x, points[i].y}, static_cast<std::uint32_t>(i)};
        }
        detail::GhostMesh serial;
        auto t0 = Clock::now();
        detail::delaunay_divide_and_conquer(kp, serial, {}, {});
        const double serial_s = seconds_since(t0);
        for (int ranks : {1, 2, 4, 8, 16, 64}) {
            std::mutex mutex;
            std::map<std::string, std::uint64_t> bytes;
            std::uint64_t band = 0;
            std::uint32_t widenings = 0;
            std::vector<dist::DistributedMesh> meshes(static_cast<std::size_t>(ranks));
            t0 = Clock::now();
            dist::run_in_process(ranks, [&](dist::Comm& comm) {
                const auto r = static_cast<std::size_t>(comm.rank());
                const auto p = static_cast<std::size_t>(ranks);
                std::vector<dist::Point> mine(
                    points.begin() + static_cast<std::ptrdiff_t>(r * n / p),
                    points.begin() + static_cast<std::ptrdiff_t>((r + 1) * n / p));
                const dist::Share share = dist::partition_points(comm, std::move(mine), {}, {});
                meshes[r] = dist::triangulate_share(comm, share, {}, {});
                const std::lock_guard lock(mutex);
                for (const auto& [phase, t] : comm.traffic()) bytes[phase] += t.bytes;
                band += meshes[r].stats.band_triangles;
                widenings = std::max(widenings, meshes[r].stats.widenings);
            });
            const double dist_s = seconds_since(t0);
            bool same = true;
            std::size_t at = 0;
            for (const auto& m : meshes) {
                for (const auto& t : m.mesh.global_triangles()) {
                    same = same && t == dist::to_global(serial.tris[at++], 0, 0);
                }
            }
            same = same && at == serial.tris.size();
            const auto mb = [&](const char* phase) {
                return static_cast<double>(bytes[phase]) / 1e6;
            };
            std::printf(
                "| %zu | %d | %.3f s | %.3f s | %.2f | %.1f | %.1f | %.1f | %.1f | %llu | %.2f | "
                "%u | %s |\n",
                n, ranks, serial_s, dist_s, dist_s / serial_s, mb("partition"), mb("shuffle"),
                mb("kernel bands"), mb("kernel results"), static_cast<unsigned long long>(band),
                static_cast<double>(band) / std::sqrt(static_cast<double>(n)), widenings,
                same ? "yes" : "NO");
            std::fflush(stdout);
            if (!same) return 1;
        }
    }
    return 0;
}
