// SPDX-License-Identifier: MIT
/// @file
/// @brief JVF DTM reader: the Czech digital technical map's exchange format (version 1.4.x,
/// `*.jvf.xml`, root element JVFDTM; docs/formats.md "JVF DTM"). Detail and height points become
/// survey points with their ids, terrain edges (TerenniHrana) hard breaklines. Source:
/// src/io/formats/jvf/jvf_reader.cpp (expat, ADR 0006).
#pragma once

#include "dtm/core/progress.hpp"
#include "dtm/io/reader.hpp"

namespace dtm::io {

/// The reader table's entry. @throws InputError naming the file and line.
[[nodiscard]] ReadResult read_jvf(const InputFile& file,
                                  const ReadOptions& options,
                                  const Progress& progress = {});

/// True for a file whose root element is JVFDTM.
[[nodiscard]] bool is_jvf(const FileHead& head);

}  // namespace dtm::io
