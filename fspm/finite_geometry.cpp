#include "fspm/finite_geometry.hpp"

#include <cmath>

#include "fspm/error.hpp"

namespace fspm {

const char* non_finite_geometry(const TreeGraph& tree, NodeId n) {
  if (!tree.start(n).allFinite()) return "start";
  if (!tree.end(n).allFinite()) return "end";
  if (!tree.direction(n).allFinite()) return "direction";
  if (!std::isfinite(tree.length(n))) return "length";
  if (!std::isfinite(tree.radius(n))) return "radius";
  if (!std::isfinite(tree.birth_time(n))) return "birth time";
  return nullptr;
}

void require_finite_geometry(const TreeGraph& tree, const std::string& path) {
  for (NodeId n = 0; n < tree.size(); ++n) {
    if (const char* field = non_finite_geometry(tree, n)) {
      throw ValueError("cannot write node " + std::to_string(n) + ": its " + field +
                           " is nan or infinite (tree files hold finite geometry only)",
                       path);
    }
  }
}

}  // namespace fspm
