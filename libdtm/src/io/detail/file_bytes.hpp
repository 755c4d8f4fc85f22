// SPDX-License-Identifier: MIT
// The bytes of a whole input file for the readers that parse bytes themselves (PLY, LAS): mapped
// read-only where possible (the page cache's own pages: no copy and no fresh memory to fault in
// and zero), read into memory otherwise (a pipe, or a system without mmap).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace dtm::io::detail {

enum class Access {
    whole,       ///< the file is read all over (prefaulted: MAP_POPULATE)
    sequential,  ///< read once from start to end (MADV_SEQUENTIAL; nothing prefaulted)
};

class FileBytes {
public:
    /// @throws InputError naming @p path if it cannot be opened or read.
    explicit FileBytes(const std::filesystem::path& path, Access access = Access::whole);
    ~FileBytes();
    FileBytes(const FileBytes&) = delete;
    FileBytes& operator=(const FileBytes&) = delete;

    /// Drops the pages wholly inside bytes [from, to) from this process's memory (a mapped file
    /// only; they are read again if touched). For readers that are done with a part.
    void release(std::size_t from, std::size_t to) const noexcept;
    [[nodiscard]] std::string_view view() const noexcept {
        return map_ != nullptr ? std::string_view(static_cast<const char*>(map_), size_) : copy_;
    }

private:
    void read(const std::filesystem::path& path);

    void* map_ = nullptr;
    std::size_t size_ = 0;
    std::string copy_;
};

}  // namespace dtm::io::detail
