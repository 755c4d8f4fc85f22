// SPDX-License-Identifier: MIT
// libFuzzer target for the JVF DTM reader (src/io/formats/jvf/, expat): arbitrary bytes. Only
// InputError may escape; points must be finite and their ids parallel. Seeds: fuzz/seeds/jvf.
#include "dtm/io/formats/jvf.hpp"
#include "reader_fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    dtm::fuzz::read_bytes(data, size, ".xml", &dtm::io::read_jvf);
    return 0;
}
