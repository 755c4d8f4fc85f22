// SPDX-License-Identifier: MIT
// libFuzzer target for dtm's PLY TIN reader (src/io/formats/ply/ply_reader.cpp): arbitrary bytes,
// ASCII and binary bodies alike. Only InputError may escape; a TIN it returns must have valid
// indices and topology (tin_fuzz_support.hpp). Seeds: tests/data/tin/*.ply.
#include <cstddef>
#include <cstdint>

#include "dtm/core/error.hpp"
#include "dtm/io/formats/ply.hpp"
#include "tin_fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto path = dtm::fuzz::bytes_to_file(data, size, ".ply");
    try {
        const dtm::io::LoadedTin loaded = dtm::io::read_tin_ply(path);
        dtm::fuzz::check_tin(loaded.tin);
    } catch (const dtm::InputError&) {
    }
    return 0;
}
