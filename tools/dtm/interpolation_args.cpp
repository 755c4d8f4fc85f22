// SPDX-License-Identifier: MIT
// --interpolation (grid, contour, build): linear (the TIN's planes), cubic (Clough-Tocher C1,
// creased along hard breaklines), natural (Sibson natural neighbours).
#include "interpolation_args.hpp"

#include <map>

namespace dtm::cli {

void add_interpolation_option(CLI::App& app, const std::string& flag, Interpolation& method) {
    std::map<std::string, Interpolation> names;
    for (const Interpolation m :
         {Interpolation::linear, Interpolation::cubic, Interpolation::natural}) {
        names.emplace(std::string(interpolation_name(m)), m);
    }
    app.add_option(flag, method,
                   "Surface between the TIN's points: linear (the triangles' planes, default), "
                   "cubic (Clough-Tocher C1 cubic, smooth but creased along hard breaklines, "
                   "every point kept exactly), natural (Sibson natural neighbours)")
        ->transform(CLI::CheckedTransformer(names, CLI::ignore_case));
}

}  // namespace dtm::cli
