// SPDX-License-Identifier: MIT
// libFuzzer target for the SMS 2DM mesh reader (src/io/formats/mesh_2dm.cpp): arbitrary bytes.
// Only InputError may escape; a TIN it returns must have valid indices and topology
// (tin_fuzz_support.hpp). Seeds: tests/data/tin/*.2dm.
#include <cstddef>
#include <cstdint>

#include "dtm/core/error.hpp"
#include "dtm/io/formats/mesh_2dm.hpp"
#include "tin_fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto path = dtm::fuzz::bytes_to_file(data, size, ".2dm");
    try {
        dtm::fuzz::check_tin(dtm::io::read_2dm(path));
    } catch (const dtm::InputError&) {
    }
    return 0;
}
