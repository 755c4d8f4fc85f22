// SPDX-License-Identifier: MIT
// libFuzzer target for the LandXML surface reader (src/io/formats/landxml/, expat): arbitrary
// bytes, read as the surface's TIN and, when the first byte is odd, as its points and lines
// (--retriangulate). Only InputError may escape; a TIN must have valid topology. Seeds:
// fuzz/seeds/landxml, tests/data/landxml, the small real exports in ../shared/data.
#include "dtm/io/formats/landxml.hpp"
#include "reader_fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    dtm::io::ReadOptions options;
    options.retriangulate = size > 0 && (data[0] & 1U) != 0;
    dtm::fuzz::read_bytes(data, size, ".xml", &dtm::io::read_landxml, options);
    return 0;
}
