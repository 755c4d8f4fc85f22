// SPDX-License-Identifier: MIT
/// @file
/// @brief What a file's first bytes look like, for the reader table (src/io/reader.cpp): a file
/// whose extension no reader takes goes to the reader its content suggests (a `.cin` or `.dat`
/// point list reads as text), and a file that looks like another format than its extension says
/// (a Compass `.plt` cave survey, a ZIP, a PDF, LAZ, binary data in a `.csv`) is an input error
/// naming what it appears to be.
#pragma once

#include <string>
#include <string_view>

namespace dtm::io {

struct ContentGuess {
    enum class Kind {
        unknown,  ///< nothing recognised (or no bytes)
        text,     ///< looks like text of a reader (point list, HP-GL): used for unknown extensions
        format,   ///< a reader's own signature (LASF, ply, DXF sections, an XML root, ...)
        foreign,  ///< a format dtm does not read (ZIP, PDF, gzip, Compass plot, ...)
        binary,   ///< binary data of no known format
    };
    Kind kind = Kind::unknown;
    std::string_view reader;  ///< the reader-table row that reads it (text, format), else empty
    std::string what;         ///< what it appears to be, e.g. "a ZIP archive"
};

/// Looks at @p head (the file's first bytes, up to 64 KiB).
[[nodiscard]] ContentGuess guess_content(std::string_view head);

}  // namespace dtm::io
