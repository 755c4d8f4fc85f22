// SPDX-License-Identifier: MIT
// Machine and process figures for the lab (machine.hpp). The peak resident set is the kernel's
// VmHWM, reset before each run by writing 5 to /proc/self/clear_refs (Linux 4.0+); freed heap
// memory is handed back first (malloc_trim) so that the rise during a run is the run's own.
#include "lab/machine.hpp"

#if __has_include(<malloc.h>)
#include <malloc.h>
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
