// SPDX-License-Identifier: MIT
// Durability helpers: fsync of files and folders, renameat2(RENAME_EXCHANGE), temporary names.
// A rename is atomic against a crash of the process; fsync of the data before the rename and of
// the folder after it also makes it survive a crash of the machine (ext4, xfs and btrfs order
// nothing else for us).
#include "durable.hpp"

#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <charconv>
#include <cstring>
#include <system_error>

#include "dtm/core/error.hpp"

namespace dtm::io::detail {
namespace fs = std::filesystem;

fs::path parent_folder(const fs::path& path) {
    return path.has_parent_path() ? path.parent_path() : fs::path(".");
}

void rename_path(const fs::path& from, const fs::path& to) {
    std::error_code ec;
    fs::rename(from, to, ec);
    if (ec)
        throw Error("cannot move " + from.string() + " to " + to.string() + ": " + ec.message());
}

std::string temp_name(const std::string& name) {
    static std::atomic<unsigned long> counter{0};
    return "." + name + ".tmp-" + std::to_string(::getpid()) + '-' +
           std::to_string(counter.fetch_add(1));
}

long temp_owner(const std::string& file, const std::string& name) {
    const std::string prefix = "." + name + ".tmp-";
    if (!file.starts_with(prefix)) return 0;
    long pid = 0;
    const char* first = file.data() + prefix.size();
    const char* last = file.data() + file.size();
    const auto [end, ec] = std::from_chars(first, last, pid);
    if (ec != std::errc{} || end == first || end == last || *end != '-') return 0;
    return pid;
}

void sync_path(const fs::path& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw Error("cannot open " + path.string() + ": " + std::strerror(errno));
    const int result = ::fsync(fd);
    const int error = errno;
    ::close(fd);
    if (result != 0 && error != EINVAL && error != EROFS) {
        throw Error("cannot write " + path.string() + " to the disk: " + std::strerror(error));
    }
}

void sync_tree(const fs::path& folder) {
    std::error_code ec;
    for (fs::recursive_directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        if (it->is_regular_file(ec) || it->is_directory(ec)) sync_path(it->path());
    }
    if (ec) throw Error("cannot read " + folder.string() + ": " + ec.message());
    sync_path(folder);
}

int exchange_paths(const fs::path& a, const fs::path& b) {
#ifdef SYS_renameat2
    constexpr unsigned exchange = 1U << 1;  // RENAME_EXCHANGE (linux/fs.h)
    if (::syscall(SYS_renameat2, AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), exchange) == 0) {
        return 0;
    }
    return errno;
#else
    (void)a;
    (void)b;
    return ENOSYS;
#endif
}

}  // namespace dtm::io::detail
