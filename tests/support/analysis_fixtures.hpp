// SPDX-License-Identifier: MIT
/// @file
/// @brief Helpers of the analysis CLI tests (volume, profile, sections, check): paths of the
/// bundled sample, the sample's TINs built by `dtm tin`, and numbers read from their JSON reports.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "support/test_support.hpp"

namespace dtm::test {

/// A file of samples/sjtsk.
inline std::filesystem::path sample_file(const char* name) {
    return std::filesystem::path(DTM_TEST_DATA_DIR) / ".." / ".." / "samples" / "sjtsk" / name;
}

/// The number after "key": inside the object "section": { ... } of a JSON report (NaN, and a
/// test failure, when absent).
inline double json_number(const std::string& json,
                          const std::string& section,
                          const std::string& key) {
    const std::size_t s = json.find("\"" + section + "\": {");
    const std::size_t k = s == std::string::npos ? s : json.find("\"" + key + "\": ", s);
    if (k == std::string::npos) {
        ADD_FAILURE() << "no " << section << "." << key << " in " << json;
        return NAN;
    }
    return std::strtod(json.c_str() + k + key.size() + 4, nullptr);
}

/// `dtm tin` of the sample as built (natural = false) or of its natural ground, to @p out.
inline RunResult build_sample_tin(const std::filesystem::path& out, bool natural) {
    const std::string p = natural ? "natural_" : "";
    std::vector<std::string> args{"tin",
                                  sample_file((p + "points.csv").c_str()).string(),
                                  "--breaklines",
                                  sample_file((p + "breaklines.shp").c_str()).string(),
                                  "--boundary",
                                  sample_file((p + "boundary.shp").c_str()).string(),
                                  "--holes",
                                  sample_file((p + "building.shp").c_str()).string(),
                                  "--crs",
                                  "EPSG:5514",
                                  "-o",
                                  out.string(),
                                  "-q"};
    if (!natural) {
        args.push_back("--skip-bad-lines");
    }
    return run_dtm(args);
}

}  // namespace dtm::test
