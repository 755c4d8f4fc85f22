// SPDX-License-Identifier: MIT
/// @file
/// @brief HP-GL and HP-GL/2 plotter plans (optionally PCL/PJL-wrapped) as terrain input: spot
/// heights from numeric labels next to point markers, breaklines, boundaries and holes by pen,
/// georeferenced by scale + origin (+ rotation) or by control points. See docs/formats.md "HPGL".
#pragma once

#include "dtm/core/progress.hpp"
#include "dtm/io/reader.hpp"

namespace dtm::io {

/// Reads one HPGL plot file with options.hpgl.
/// @throws InputError ("<file>: byte N: ...") on corrupt data unless options.skip_bad_lines,
///         in which case the problem becomes a warning and reading goes on; OptionError on
///         contradictory georeferencing options; Cancelled.
[[nodiscard]] ReadResult read_hpgl(const InputFile& file,
                                   const ReadOptions& options,
                                   const Progress& progress = {});

}  // namespace dtm::io
