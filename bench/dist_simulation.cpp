// SPDX-License-Identifier: MIT
// The distributed kernel on P in-process ranks (bench/dist_simulation.sh): for each point count
// and rank count, the wall time of partition + kernel against the serial kernel in the same run,
// the bytes every phase moves (summed over ranks), the band triangles the merging ranks received,
// widenings, and a check that the slots equal the serial kernel's. Virtual ranks share this
// machine's cores, so the times measure overhead, not cluster speed; bytes and bands are exact.
// Usage: dist_simulation [N...] (default 100000 1000000); ranks 1 2 4 8 16 64. Under mpirun the
// same job runs once on the MPI ranks instead (every rank also runs the serial kernel as the
// reference and checks its own slots against it).
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

std::vector<dist::Point> uniform(std::size_t n) {
    std::mt19937_64 rng(20261202);
    std::uniform_real_distribution<double> u(0.0, 2000.0);
    std::vector<dist::Point> pts(n);
    for (std::size_t i = 0; i < n; ++i) pts[i] = {-750000.0 + u(rng), -1050000.0 + u(rng), i};
    return pts;
}

}  // namespace

/// One run on the MPI ranks: the slowest rank's time against the serial kernel's.
int run_mpi(int argc, char** argv, const std::vector<std::size_t>& sizes) {
    dist::MpiSession session(argc, argv);
    dist::Comm& comm = session.world();
    const auto r = static_cast<std::size_t>(comm.rank());
    const auto p = static_cast<std::size_t>(comm.size());
    int failures = 0;
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
        std::vector<dist::Point> mine(
            points.begin() + static_cast<std::ptrdiff_t>(r * n / p),
            points.begin() + static_cast<std::ptrdiff_t>((r + 1) * n / p));
        comm.barrier();
        t0 = Clock::now();
        const dist::Share share = dist::partition_points(comm, std::move(mine), {}, {});
        const dist::DistributedMesh d = dist::triangulate_share(comm, share, {}, {});
        const auto micros = static_cast<std::int64_t>(seconds_since(t0) * 1e6);
        std::int64_t bad = 0;
        for (std::size_t k = 0; k < d.mesh.tris.size(); ++k) {
            bad +=
                d.mesh.tris[k] == dist::to_global(serial.tris[d.mesh.first_slot + k], 0, 0) ? 0 : 1;
        }
        const std::int64_t slowest = comm.allreduce(micros, dist::Reduce::max);
        bad = comm.allreduce(bad, dist::Reduce::sum);
        failures += bad > 0 ? 1 : 0;
        if (comm.rank() == 0) {
            std::printf(
                "| %zu | %zu MPI ranks | %.3f s | %.3f s | %.2f | slots differing: %lld |\n", n, p,
                serial_s, static_cast<double>(slowest) / 1e6,
                static_cast<double>(slowest) / 1e6 / serial_s, static_cast<long long>(bad));
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
                for (const auto& t : m.mesh.tris)
                    same = same && t == dist::to_global(serial.tris[at++], 0, 0);
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
