#include "scans/scanned_tree.hpp"

#include <fmt/format.h>

#include "scans/isolated_points.hpp"

namespace fspm::scans {

std::string bridged_gaps_warning(const EncodeResult& r) {
  constexpr std::size_t kListed = 5;
  std::string where;
  for (std::size_t k = 0; k < r.gaps.size() && k < kListed; ++k) {
    const Eigen::Vector3d mid = 0.5 * (r.gaps[k].from + r.gaps[k].to);
    where += fmt::format("{}({:.2f}, {:.2f}, {:.2f}) over {:.2f} m", k > 0 ? "; " : "", mid.x(),
                         mid.y(), mid.z(), r.gaps[k].length_m);
  }
  if (r.gaps.size() > kListed) where += fmt::format("; and {} more", r.gaps.size() - kListed);
  return fmt::format(
      "{} occlusion gap{} (longer than {:.3f} m) bridged along the branch's direction or by the "
      "shortest edge, at {}; check the skeleton there",
      r.gaps.size(), r.gaps.size() == 1 ? "" : "s", r.gap_m, where);
}

ScannedTree encode_and_measure(const PointSet& points, const EncodeOptions& options) {
  // Stray returns metres off the tree would be joined to it and widen its crown.
  const IsolatedPoints cleaned = remove_isolated_points(points);
  ScannedTree out;
  out.isolated_points = cleaned.removed;
  out.encoding = encode_point_set(cleaned.kept, options);
  TreeMeasurements& m = out.measurements;
  m = measure_tree(cleaned.kept, out.encoding.full_skeleton);
  if (!options.root_diameter_m && !m.dbh_m && m.tree_found) {
    // d_root of eq. 3.1 comes from a circle through the lowest trunk points, which a trunk
    // without a breast-height diameter does not confirm (an airborne scan: a handful of points).
    m.warnings.push_back(
        fmt::format("the radii of eq. 3.1 scale with a root diameter of {:.3f} m fitted to the "
                    "lowest points, unconfirmed at breast height; give --root-diameter",
                    out.encoding.model.root_diameter_m));
  }
  if (cleaned.removed > 0) {
    m.warnings.push_back(fmt::format(
        "{} isolated points left out (mean distance to their 8 nearest neighbours above {:.2f} m: "
        "stray returns)",
        cleaned.removed, cleaned.threshold_m));
  }
  if (!out.encoding.gaps.empty()) m.warnings.push_back(bridged_gaps_warning(out.encoding));
  return out;
}

}  // namespace fspm::scans
