// SPDX-License-Identifier: MIT
// libFuzzer target for the LAS reader (src/io/formats/las/): arbitrary bytes read from memory
// (read_las_bytes), with the class filter and thinning chosen from the last byte. Only
// InputError may escape; the points must be finite and every record accounted for. Seeds:
// fuzz/seeds/las.
#include "dtm/io/formats/las.hpp"
#include "reader_fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    dtm::io::ReadOptions options;
    const unsigned last = size > 0 ? data[size - 1] : 0U;
    if ((last & 1U) != 0) options.classes = {2, 9};
    if ((last & 2U) != 0) options.thin = 0.5 + (last >> 2);
    try {
        const std::string_view bytes(reinterpret_cast<const char*>(data), size);
        dtm::fuzz::check_result(
            dtm::io::read_las_bytes(bytes, {"fuzz.las", dtm::io::InputRole::points}, options));
    } catch (const dtm::InputError&) {
    }
    return 0;
}
