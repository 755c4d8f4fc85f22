// SPDX-License-Identifier: MIT
// libFuzzer target for content sniffing and the reader table (src/io/sniff.cpp, reader.cpp):
// arbitrary bytes as the head of a file of each extension class (none, unknown, text, plot, xml).
// Only InputError may escape, and a chosen reader must be a row of the table.
#include <array>
#include <string_view>

#include "dtm/core/error.hpp"
#include "dtm/io/reader.hpp"
#include "dtm/io/sniff.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    (void)dtm::io::guess_content(bytes);
    constexpr std::array<std::string_view, 6> extensions{"", "dat", "csv", "plt", "xml", "las"};
    for (const std::string_view ext : extensions) {
        try {
            const dtm::io::ReaderInfo& r =
                dtm::io::find_reader(dtm::io::FileHead{"fuzz", std::string(ext), bytes});
            if (r.read == nullptr) __builtin_trap();
        } catch (const dtm::InputError&) {
        }
    }
    return 0;
}
