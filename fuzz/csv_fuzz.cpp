// SPDX-License-Identifier: MIT
// libFuzzer target for the delimited-text reader: arbitrary bytes through layout detection and
// row parsing, for every role and with --skip-bad-lines on and off. Only InputError and
// UsageError may escape the reader; anything else (crash, sanitizer report, other exception)
// is a bug.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "dtm/core/error.hpp"
#include "dtm/io/formats/csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    constexpr dtm::io::InputRole roles[] = {dtm::io::InputRole::points,
                                            dtm::io::InputRole::breaklines,
                                            dtm::io::InputRole::boundary, dtm::io::InputRole::holes};
    for (const dtm::io::InputRole role : roles) {
        for (const bool skip : {false, true}) {
            dtm::io::LoadOptions options;
            options.skip_bad_lines = skip;
            try {
                const dtm::io::ReadResult r =
                    dtm::io::parse_csv_text(text, dtm::io::InputFile{"fuzz.csv", role}, options);
                if (!r.labels.ids.empty() && r.labels.ids.size() != r.terrain.points.size()) {
                    __builtin_trap();  // labels must stay parallel to points
                }
            } catch (const dtm::InputError&) {
            } catch (const dtm::UsageError&) {
            }
        }
    }
    (void)dtm::io::csv_has_geometry_column(text);
    return 0;
}
