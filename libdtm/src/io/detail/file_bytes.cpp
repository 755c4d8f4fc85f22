// SPDX-License-Identifier: MIT
#include "io/detail/file_bytes.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

#if defined(__unix__)
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#endif

#include "dtm/core/error.hpp"

namespace dtm::io::detail {

FileBytes::FileBytes(const std::filesystem::path& path, Access access) {
#if defined(__unix__)
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw InputError(path, 0, 0, "cannot open: " + std::string(std::strerror(errno)));
    struct stat st {};
    if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
        const auto size = static_cast<std::size_t>(st.st_size);
        const int flags = MAP_PRIVATE | (access == Access::whole ? MAP_POPULATE : 0);
        void* map = ::mmap(nullptr, size, PROT_READ, flags, fd, 0);
        if (map != MAP_FAILED) {
            if (access == Access::sequential) ::madvise(map, size, MADV_SEQUENTIAL);
            map_ = map;
            size_ = size;
            ::close(fd);
            return;
        }
    }
    ::close(fd);
#endif
    read(path);
}

FileBytes::~FileBytes() {
#if defined(__unix__)
    if (map_ != nullptr) ::munmap(map_, size_);
#endif
}

void FileBytes::read(const std::filesystem::path& path) {
    std::FILE* file = std::fopen(path.c_str(), "rb");
    if (file == nullptr) {
        throw InputError(path, 0, 0, "cannot open: " + std::string(std::strerror(errno)));
    }
    char buffer[1 << 16];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, file)) > 0) copy_.append(buffer, n);
    const bool failed = std::ferror(file) != 0;
    std::fclose(file);
    if (failed) throw InputError(path, 0, 0, "read error");
}

void FileBytes::release(std::size_t from, std::size_t to) const noexcept {
    if (map_ == nullptr) return;
    const auto page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
    const std::size_t first = (from + page - 1) / page * page;
    const std::size_t last = std::min(to, size_) / page * page;
    if (first < last) ::madvise(static_cast<char*>(map_) + first, last - first, MADV_DONTNEED);
}

}  // namespace dtm::io::detail
