// SPDX-License-Identifier: MIT
// Shared by the TIN-file fuzzers (ply_fuzz, mesh_2dm_fuzz): the readers take a path, so the bytes
// go to one file per process first; and the invariants every TIN a reader returns must keep.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "dtm/algo/validate.hpp"
#include "dtm/core/tin.hpp"

namespace dtm::fuzz {

/// Writes @p data to "<tmp>/dtm-fuzz-<pid><extension>" and returns the path.
inline std::filesystem::path bytes_to_file(const std::uint8_t* data,
                                           std::size_t size,
                                           const char* extension) {
    static const std::filesystem::path path =
        std::filesystem::temp_directory_path() /
        ("dtm-fuzz-" + std::to_string(::getpid()) + extension);
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (f == nullptr) __builtin_trap();
    if (size > 0 && std::fwrite(data, 1, size, f) != size) __builtin_trap();
    std::fclose(f);
    return path;
}

/// Traps unless the TIN is one a reader may return.
inline void check_tin(const Tin& tin) {
    const std::size_t n = tin.vertices.size();
    for (const Triangle& t : tin.triangles) {
        for (const VertexIndex v : t.v) {
            if (v >= n) __builtin_trap();
        }
    }
    for (const ConstrainedEdge& e : tin.constraints) {
        if (e.a >= n || e.b >= n) __builtin_trap();
    }
    // What every algorithm downstream relies on (counter-clockwise triangles of distinct
    // vertices, symmetric neighbours, constrained edges on triangles): a reader must refuse a
    // file that breaks it rather than return it.
    if (!verify_topology(tin).ok()) __builtin_trap();
}

}  // namespace dtm::fuzz
