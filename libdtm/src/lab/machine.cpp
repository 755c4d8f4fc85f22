// SPDX-License-Identifier: MIT
// Machine and process figures for the lab (machine.hpp). The peak resident set is the kernel's
// VmHWM, reset before each run by writing 5 to /proc/self/clear_refs (Linux 4.0+); freed heap
// memory is handed back first (malloc_trim) so that the rise during a run is the run's own.
// glibc raises its mmap threshold to the largest block freed so far (up to 32 MiB): after a
// large run, a method's arrays would live in the heap, where freed blocks stay resident, and
// its rise would depend on what ran before it. fix_allocator() pins the thresholds at glibc's
// defaults, so every block above 128 KiB is mapped and unmapped on its own in every run. The
// dtm binary asks for transparent huge pages for blocks of 2 MiB and more (ADR 0007), which
// makes a block resident in 2 MiB steps (at 10^5 points a large part of a method's total);
// fix_allocator() turns huge pages off for the lab's process (prctl PR_SET_THP_DISABLE), so
// the rise is the 4 KiB pages the method touched.
#include "lab/machine.hpp"

#if __has_include(<malloc.h>)
#include <malloc.h>
#endif
#if __has_include(<sys/prctl.h>)
#include <sys/prctl.h>
#endif

#include <chrono>
#include <ctime>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

namespace dtm::lab::detail {
namespace {

std::size_t status_kb(const char* key) {
    std::ifstream in("/proc/self/status");
    std::string line;
    const std::string prefix = std::string(key) + ":";
    while (std::getline(in, line)) {
        if (line.rfind(prefix, 0) == 0) {
            std::istringstream fields(line.substr(prefix.size()));
            std::size_t kb = 0;
            fields >> kb;
            return kb * 1024;
        }
    }
    return 0;
}

std::string read_line(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    return line;
}

}  // namespace

MachineInfo machine_info() {
    MachineInfo m;
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpuinfo, line)) {
        if (line.rfind("model name", 0) == 0) {
            const auto colon = line.find(':');
            if (colon != std::string::npos) m.cpu = line.substr(colon + 2);
            break;
        }
    }
    m.cores = std::thread::hardware_concurrency();
    for (int index = 0; index < 8; ++index) {
        const std::string dir = "/sys/devices/system/cpu/cpu0/cache/index" + std::to_string(index);
        const std::string level = read_line(dir + "/level");
        if (level.empty()) break;
        const std::string type = read_line(dir + "/type");
        const std::string size = read_line(dir + "/size");
        const std::string name = "L" + level +
                                 (type == "Data"          ? "d"
                                  : type == "Instruction" ? "i"
                                                          : "");
        if (!m.caches.empty()) m.caches += ", ";
        m.caches += name + " " + size;
    }
    return m;
}

void fix_allocator() {
#if __has_include(<malloc.h>) && defined(M_MMAP_THRESHOLD)
    mallopt(M_MMAP_THRESHOLD, 128 * 1024);
    mallopt(M_TRIM_THRESHOLD, 128 * 1024);
#endif
#if __has_include(<sys/prctl.h>) && defined(PR_SET_THP_DISABLE)
    (void)prctl(PR_SET_THP_DISABLE, 1, 0, 0, 0);
#endif
}

std::size_t start_peak_count() {
#if __has_include(<malloc.h>)
    malloc_trim(0);
#endif
    std::ofstream clear("/proc/self/clear_refs");
    if (clear) clear << "5";
    clear.close();
    return status_kb("VmRSS");
}

std::size_t peak_resident() { return status_kb("VmHWM"); }

std::string utc_now() {
    const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm tm{};
#if defined(_WIN32)
    gmtime_s(&tm, &t);
#else
    gmtime_r(&t, &tm);
#endif
    char buffer[32];
    std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return buffer;
}

}  // namespace dtm::lab::detail
