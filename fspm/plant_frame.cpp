#include "fspm/plant_frame.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace fspm {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

// A unit vector perpendicular to d.
Eigen::Vector3d perpendicular(const Eigen::Vector3d& d) {
  const Eigen::Vector3d a =
      std::abs(d.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  return d.cross(a).normalized();
}

class Framer {
 public:
  Framer(const std::vector<FrameEntity>& e, const FrameDefaults& d)
      : e_(e),
        d_(d),
        out_(e.size()),
        successor_(e.size(), kNoFrameParent),
        children_(e.size()),
        branches_(e.size(), 0),
        axis_of_(e.size(), 0) {
    for (std::size_t i = 0; i < e.size(); ++i) {
      const std::size_t p = e[i].parent;
      if (p == kNoFrameParent) continue;
      children_[p].push_back(i);
      if (!e[i].branch && successor_[p] == kNoFrameParent) successor_[p] = i;
    }
  }

  std::vector<FramedEntity> run() {
    for (std::size_t i = 0; i < e_.size(); ++i) {
      const std::size_t p = e_[i].parent;
      if (p == kNoFrameParent || successor_[p] != i) place_axis(i);
    }
    interpolate_radii();
    pipe_model_radii();
    return std::move(out_);
  }

 private:
  // The entities of the axis that starts at `head`: it and its successors.
  std::vector<std::size_t> axis(std::size_t head) const {
    std::vector<std::size_t> nodes;
    for (std::size_t k = head; k != kNoFrameParent; k = successor_[k]) nodes.push_back(k);
    return nodes;
  }

  Eigen::Vector3d heading_of(std::size_t i) const {
    const Eigen::Vector3d d = out_[i].end - out_[i].start;
    return d.norm() > 0.0 ? Eigen::Vector3d(d.normalized()) : Eigen::Vector3d::UnitZ();
  }

  // The first heading of an axis: its bearer's, turned away by the insertion angle for a branch.
  Eigen::Vector3d first_heading(std::size_t head) {
    const std::size_t p = e_[head].parent;
    if (p == kNoFrameParent) return Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d h = heading_of(p);
    if (!e_[head].branch) return h;
    const double azimuth = e_[head].azimuth_deg
                               ? *e_[head].azimuth_deg * kDegree
                               : d_.divergence_deg * kDegree * branches_[axis_of_[p]]++;
    const double insertion = e_[head].insertion_deg.value_or(d_.insertion_deg) * kDegree;
    const Eigen::Vector3d side = Eigen::AngleAxisd(azimuth, h) * perpendicular(h);
    return (Eigen::AngleAxisd(insertion, side) * h).normalized();
  }

  double length_of(std::size_t i) const { return e_[i].length_m.value_or(d_.length_m); }

  // Places every entity of one axis: measured tops kept, those between two measured points
  // spread evenly between them, those after the last one continued by the turtle.
  void place_axis(std::size_t head) {
    const std::vector<std::size_t> nodes = axis(head);
    for (std::size_t n : nodes) axis_of_[n] = head;
    const std::size_t p = e_[head].parent;
    Eigen::Vector3d heading = first_heading(head);
    Eigen::Vector3d base;
    if (p != kNoFrameParent) {
      base = out_[p].end;
    } else if (e_[head].top) {
      base = *e_[head].top - length_of(head) * Eigen::Vector3d::UnitZ();
    } else {
      base = Eigen::Vector3d::Zero();
    }
    std::size_t anchor = 0;  // nodes[anchor - 1] is the last placed measured point (0: the base)
    Eigen::Vector3d anchor_point = base;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      if (!e_[nodes[k]].top) continue;
      const Eigen::Vector3d top = *e_[nodes[k]].top;
      for (std::size_t j = anchor; j <= k; ++j) {
        const double t = double(j + 1 - anchor) / double(k + 1 - anchor);
        out_[nodes[j]].end =
            j == k ? top : Eigen::Vector3d(anchor_point + t * (top - anchor_point));
        out_[nodes[j]].inferred = j == k ? 0 : kInferredPosition;
      }
      anchor = k + 1;
      anchor_point = top;
    }
    Eigen::Vector3d start = base;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      FramedEntity& f = out_[nodes[k]];
      f.start = start;
      if (k >= anchor) {
        if (k > 0) heading = heading_of(nodes[k - 1]);
        f.end = start + length_of(nodes[k]) * heading;
        f.inferred = kInferredPosition;
      }
      start = f.end;
    }
  }

  // Radii between two measured ones of an axis, linearly by position along it.
  void interpolate_radii() {
    for (std::size_t i = 0; i < e_.size(); ++i) {
      if (e_[i].radius_m) out_[i].radius_m = *e_[i].radius_m;
      const std::size_t p = e_[i].parent;
      if (p != kNoFrameParent && successor_[p] == i) continue;
      const std::vector<std::size_t> nodes = axis(i);
      std::size_t last = nodes.size();
      for (std::size_t k = 0; k < nodes.size(); ++k) {
        if (!e_[nodes[k]].radius_m) continue;
        if (last != nodes.size()) {
          const double r0 = *e_[nodes[last]].radius_m, r1 = *e_[nodes[k]].radius_m;
          for (std::size_t j = last + 1; j < k; ++j) {
            const double t = double(j - last) / double(k - last);
            out_[nodes[j]].radius_m = r0 + t * (r1 - r0);
            out_[nodes[j]].inferred |= kInferredRadius;
            interpolated_.push_back(nodes[j]);
          }
        }
        last = k;
      }
    }
  }

  // Pipe model from the tips down for every radius neither measured nor interpolated.
  void pipe_model_radii() {
    double tip = d_.tip_radius_m;
    bool any = false;
    for (const FrameEntity& f : e_) {
      if (f.radius_m && *f.radius_m > 0.0) {
        tip = any ? std::min(tip, *f.radius_m) : *f.radius_m;
        any = true;
      }
    }
    std::vector<char> known(e_.size(), 0);
    for (std::size_t i = 0; i < e_.size(); ++i) known[i] = e_[i].radius_m.has_value();
    for (std::size_t i : interpolated_) known[i] = 1;
    for (std::size_t i = e_.size(); i-- > 0;) {
      if (known[i]) continue;
      double area = 0.0;
      for (std::size_t c : children_[i]) area += out_[c].radius_m * out_[c].radius_m;
      out_[i].radius_m = children_[i].empty() ? tip : std::sqrt(area);
      out_[i].inferred |= kInferredRadius;
    }
  }

  const std::vector<FrameEntity>& e_;
  const FrameDefaults& d_;
  std::vector<FramedEntity> out_;
  std::vector<std::size_t> successor_;
  std::vector<std::vector<std::size_t>> children_;
  std::vector<int> branches_;         // branches placed on each axis (by its head)
  std::vector<std::size_t> axis_of_;  // the head of each entity's axis
  std::vector<std::size_t> interpolated_;
};

}  // namespace

std::vector<FramedEntity> plant_frame(const std::vector<FrameEntity>& entities,
                                      const FrameDefaults& defaults) {
  return Framer(entities, defaults).run();
}

}  // namespace fspm
