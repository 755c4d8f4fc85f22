// SPDX-License-Identifier: MIT
/// @file
/// @brief [dc] The production kernel (dtm::triangulate: Guibas-Stolfi divide and conquer in
/// parallel tiles, constraints by cavity retriangulation) as the methods' reference.
#pragma once

#include "dtm/methods/method.hpp"

namespace dtm::methods {

[[nodiscard]] MethodResult run_dc(const MethodInput& input,
                                  const MethodOptions& options,
                                  const Progress& progress);

}  // namespace dtm::methods
