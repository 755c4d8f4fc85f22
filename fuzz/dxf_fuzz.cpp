// SPDX-License-Identifier: MIT
// libFuzzer target for the DXF 3DFACE reader (src/io/formats/dxf/dxf_reader.cpp): arbitrary
// bytes, read as a TIN and, when the first byte is odd, as points (--retriangulate). Drawings
// without 3DFACEs go on to OGR, whose DXF driver is GDAL's to fuzz: it is skipped here (GDAL_SKIP),
// so that fallback is an InputError and only dtm's parser runs (GDAL 3.6's DXF driver loops on
// some broken drawings, which made this target time out in GDAL's code). Only InputError may
// escape; a TIN must have valid topology. Seeds: fuzz/seeds/dxf.
#include <cpl_conv.h>

#include "dtm/io/formats/dxf.hpp"
#include "reader_fuzz_support.hpp"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    CPLSetConfigOption("GDAL_SKIP", "DXF");
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    dtm::io::ReadOptions options;
    options.retriangulate = size > 0 && (data[0] & 1U) != 0;
    dtm::fuzz::read_bytes(data, size, ".dxf", &dtm::io::read_dxf, options);
    return 0;
}
