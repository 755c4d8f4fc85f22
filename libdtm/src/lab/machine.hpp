// SPDX-License-Identifier: MIT
/// @file
/// @brief What the lab needs to know about the machine and the process: CPU model and caches,
/// the resident set and its peak (Linux /proc and /sys; elsewhere the figures stay zero).
#pragma once

#include <cstddef>
#include <string>

#include "dtm/lab/compare.hpp"

namespace dtm::lab::detail {

[[nodiscard]] MachineInfo machine_info();

/// Returns freed heap memory to the system and restarts the peak count from the current
/// resident set (Linux: /proc/self/clear_refs). @return the resident set in bytes, 0 unknown.
std::size_t start_peak_count();

/// The peak resident set in bytes since start_peak_count (0 unknown).
[[nodiscard]] std::size_t peak_resident();

/// Current UTC time as ISO 8601 ("2024-05-01T12:00:00Z").
[[nodiscard]] std::string utc_now();

}  // namespace dtm::lab::detail
