// SPDX-License-Identifier: MIT
/// @file
/// @brief Decoder of the HP-GL/2 PE (polyline encoded) instruction.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

namespace dtm::io::hpgl {

class Diagnostics;

/// One decoded PE element: a pen selection or a coordinate pair.
struct PeItem {
    enum class Kind { pen, move, draw };
    Kind kind = Kind::draw;
    bool absolute = false;  ///< '=' flag: x, y are absolute (otherwise relative)
    double x = 0.0;         ///< in current units, fractional bits applied
    double y = 0.0;
    int pen = 0;  ///< Kind::pen only
};

/// Decodes PE data starting at @p pos (just after "PE") and returns the position after it: after
/// the ';', or at the escape or the next instruction that ends it. Invalid bytes are reported to
/// @p diagnostics with their offset (strict mode throws there).
std::size_t decode_pe(std::string_view bytes,
                      std::size_t pos,
                      std::vector<PeItem>& out,
                      Diagnostics& diagnostics);

}  // namespace dtm::io::hpgl
