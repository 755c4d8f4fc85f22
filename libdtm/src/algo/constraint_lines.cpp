// SPDX-License-Identifier: MIT
// Constrained edges to polylines with their points, every kind in enum order: the chains of
// constraint_chains() (the one chaining algorithm), closed rings repeating their first point.
#include "dtm/algo/constraint_lines.hpp"

#include "dtm/algo/constraint_chains.hpp"

namespace dtm {

std::vector<ConstraintLine> constraint_lines(const Tin& tin) {
    std::vector<ConstraintLine> out;
    for (const ConstraintKind kind : {ConstraintKind::breakline, ConstraintKind::soft_breakline,
                                      ConstraintKind::boundary, ConstraintKind::hole}) {
        for (const ConstraintChain& chain : constraint_chains(tin, kind)) {
            ConstraintLine& line = out.emplace_back();
            line.kind = kind;
            line.closed = chain.closed;
            line.points.reserve(chain.vertices.size() + 1);
            for (const VertexIndex v : chain.vertices) line.points.push_back(tin.vertices[v]);
            if (chain.closed && !chain.vertices.empty()) {
                line.points.push_back(tin.vertices[chain.vertices.front()]);
            }
        }
    }
    return out;
}

}  // namespace dtm
