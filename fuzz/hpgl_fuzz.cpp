// SPDX-License-Identifier: MIT
// libFuzzer target for the HPGL reader: tokenizer (PCL/PJL/RS-232 unwrapping, labels, PE),
// plotter state machine, crosses, spot-height matching and line heights. Corrupt input may only
// end in dtm::InputError (strict) or warnings (lenient); anything else is a bug.
// Build: clang++ -fsanitize=fuzzer,address,undefined (DTM_FUZZ=ON); seeds:
// /work/shared/data/hpgl-*.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "dtm/core/error.hpp"
#include "dtm/io/formats/hpgl_options.hpp"
#include "io/formats/hpgl/hpgl_plan.hpp"
#include "io/formats/hpgl/hpgl_plot.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    dtm::io::HpglOptions options;
    options.pens = {{1, dtm::io::PenRole::points},
                    {2, dtm::io::PenRole::breakline},
                    {3, dtm::io::PenRole::boundary},
                    {4, dtm::io::PenRole::hole},
                    {5, dtm::io::PenRole::soft_breakline}};
    options.height_pens = {6};
    for (const bool strict : {true, false}) {
        dtm::io::hpgl::PlotOptions plot_options;
        plot_options.strict = strict;
        try {
            dtm::io::hpgl::Plot plot = dtm::io::hpgl::plot_hpgl(bytes, "fuzz.plt", plot_options);
            (void)dtm::io::hpgl::build_terrain_plan(plot, options);
        } catch (const dtm::InputError&) {
            if (!strict) __builtin_trap();  // lenient mode must not throw on bad bytes
        }
    }
    return 0;
}
