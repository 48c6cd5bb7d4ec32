#include "environment/growth_model.hpp"

#include "environment/site_sky.hpp"
#include "environment/sky_distribution.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <random>

#include "environment/bud_light.hpp"
#include "environment/leaf_light.hpp"
#include "environment/light_model.hpp"
#include "fspm/attribute_names.hpp"
#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"
#include "fspm/number_text.hpp"

namespace fspm::environment {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

using growth::Metamer;
using growth::Shoot;

// Unit vector at `angle` from h, rotated by `roll` around h from a frame fixed by the world up.
Eigen::Vector3d lateral_direction(const Eigen::Vector3d& h, double angle_rad, double roll_rad) {
  const Eigen::Vector3d ref =
      std::abs(h.z()) < 0.99 ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
  const Eigen::Vector3d u0 = ref.cross(h).normalized();
  const Eigen::Vector3d u = std::cos(roll_rad) * u0 + std::sin(roll_rad) * h.cross(u0);
  return (std::cos(angle_rad) * h + std::sin(angle_rad) * u).normalized();
}

class Grower {
 public:
  Grower(const GrowthParams& p, const Scene& scene, const Eigen::Vector3d& base)
      : p_(p), scene_(scene), base_(base), rng_(p.seed) {
    if (!scene_.ground) scene_.ground = Ground{base.z(), 1.0, true};  // obstruction only
    // A real sky (parameter table `sky`): its light per direction replaces the cos^2 sky of the
    // light models that weight sky directions (sky_distribution.hpp); its mean direction is the
    // brightest point of what takes one direction.
    if (p_.site_sky) {
      site_light_ = std::make_shared<const SkyDistribution>(sky_distribution(*p_.site_sky));
      scene_.sky.brightest = site_light_->mean_direction();
    }
    light_ = make_bud_light({p_, scene_, base_, rng_});
    wsum_ = p_.phototropism + p_.gravitropism;
    // Pirk eq. 4.7 with l_s = l_i: each internode keeps (1 - sum w)^1 of its default direction.
    ws_ = 1.0 - wsum_;
    gravity_ = p_.gravity_direction.normalized();
  }

  GrowthResult run() {
    if (scene_.inside_solid(base_ + 1e-9 * Eigen::Vector3d::UnitZ())) {
      throw ValueError("the tree base lies inside a solid obstacle");
    }
    Metamer m0;
    m0.start = base_;
    m0.heading = Eigen::Vector3d::UnitZ();
    m0.end = base_ + p_.internode_length_m * m0.heading;
    m0.terminal_bud = true;
    m0.lateral_bud = true;
    m0.lateral_dir = lateral_direction(m0.heading, p_.branching_angle_deg * kDeg, 0.0);
    m0.shoot = 0;
    ms_.push_back(m0);
    shoots_.push_back({0, 0, 0, -1, true});
    grown_ = 1;
    for (int year = 1; year <= p_.years; ++year) cycle(year);
    check_size_limits(p_.years);
    return finish();
  }

 private:
  // The scene with the sky sampled as the parameters say, without clusters.
  Scene light_scene_settings() const { return light_scene_settings(p_.light_significance); }
  Scene light_scene_settings(double significance) const {
    Scene s = scene_;
    s.sky.directions = p_.light_directions;
    s.sky.significance = significance;
    if (site_light_) apply_sky_distribution(s.sky, site_light_);
    return s;
  }

  Scene light_scene(int year) {
    Scene s = light_scene_settings();
    for (auto& sh : shoots_) {
      sh.sphere = -1;
      if (!sh.alive || year - sh.year > p_.leaf_years) continue;
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      double length = 0.0;
      const int n = sh.last - sh.first + 1;
      for (int i = sh.first; i <= sh.last; ++i) {
        c += 0.5 * (ms_[i].start + ms_[i].end);
        length += (ms_[i].end - ms_[i].start).norm();
      }
      c /= n;
      const double r = std::max(p_.cluster_radius_m, 0.5 * length);
      sh.sphere = static_cast<std::int32_t>(s.spheres.size());
      s.spheres.push_back({c, r, cluster_translucency(r, p_.gamma0), false});
    }
    return s;
  }

  void shed(std::int32_t root) {
    std::vector<std::int32_t> stack{root};
    double pipes = 0.0;  // of the shed branch, in tip pipes: its tips and its own disused pipes
    while (!stack.empty()) {
      const std::int32_t i = stack.back();
      stack.pop_back();
      Metamer& m = ms_[i];
      if (!m.alive) continue;
      const bool tip =
          !(m.main >= 0 && ms_[m.main].alive) && !(m.lateral >= 0 && ms_[m.lateral].alive);
      pipes += (tip ? 1.0 : 0.0) +
               (static_cast<std::size_t>(i) < disused_pipes_.size() ? disused_pipes_[i] : 0.0);
      m.alive = false;
      ++shed_;
      if (shoots_[m.shoot].first == i) shoots_[m.shoot].alive = false;
      if (m.main >= 0) stack.push_back(m.main);
      if (m.lateral >= 0) stack.push_back(m.lateral);
    }
    // Shinozaki et al. 1964: the shed branch's pipes stay in its parent's wood.
    if (p_.keep_shed_pipes && ms_[root].parent >= 0) {
      disused_pipes_.resize(ms_.size(), 0.0);
      disused_pipes_[static_cast<std::size_t>(ms_[root].parent)] += pipes;
    }
  }

  void cycle(int year) {
    check_size_limits(year - 1);
    expire_lateral_buds(year);
    sense_light(year);
    accumulate_light(year);
    allocate_vigour();
    check_memory_for_growth();
    const std::size_t n = ms_.size();
    // 4. Bud fate (step 4, Palubicki's continuous option): every bud with v >= min_shoot_vigour
    // grows a shoot whose length follows v.
    for (std::size_t k = 0; k < n; ++k) {
      if (!ms_[k].alive) continue;
      const double vmin = std::max(p_.min_shoot_vigour, 1e-9);
      if (ms_[k].terminal_bud && v_terminal_[k] >= vmin) grow_shoot(k, true, v_terminal_[k], year);
      if (ms_[k].lateral_bud && v_lateral_[k] >= vmin) grow_shoot(k, false, v_lateral_[k], year);
    }
  }

  // Stops a tree that explodes before its light model does (a shadow grid over hundreds of metres
  // runs out of voxels with a message about voxels, not about the parameters).
  // `year`: the cycles grown so far.
  void check_size_limits(int year) const {
    std::size_t internodes = 0;
    double height_m = 0.0;
    for (const Metamer& m : ms_) {
      if (!m.alive) continue;
      ++internodes;
      height_m = std::max(height_m, m.end.z() - base_.z());
    }
    const bool too_many = internodes > p_.max_internodes;
    if (!too_many && !(height_m > p_.max_height_m)) return;
    const auto g = [](double v) { return format_significant(v); };
    // Short enough to stay whole under kMaxErrorMessageLength with the command line's prefix.
    throw GrowthLimitError("growth stopped after year " + std::to_string(year) + " of " +
                           std::to_string(p_.years) + ": " + std::to_string(internodes) +
                           " internodes, " + g(height_m) + " m tall, above " +
                           (too_many ? "max_internodes = " + std::to_string(p_.max_internodes)
                                     : "max_height_m = " + g(p_.max_height_m) + " m") +
                           "; the parameters make the tree explode (alpha " + g(p_.alpha) +
                           ", apical_control " + g(p_.apical_control) +
                           "): change them or raise the limit (--max-internodes, max_height_m)");
  }

  // The metamers this cycle's shoots will add (the count grow_shoot gives each), checked against
  // the memory limit with the tree already grown, before any is allocated: per metamer its own
  // record, the per-node light arrays and its node in the output tree.
  void check_memory_for_growth() const {
    const double vmin = std::max(p_.min_shoot_vigour, 1e-9);
    const auto metamers = [&](double v) {
      return v >= vmin ? std::clamp(static_cast<double>(std::lround(v)), 1.0,
                                    static_cast<double>(p_.max_shoot_metamers))
                       : 0.0;
    };
    double added = 0.0;
    for (std::size_t k = 0; k < ms_.size(); ++k) {
      if (!ms_[k].alive) continue;
      if (ms_[k].terminal_bud) added += metamers(v_terminal_[k]);
      if (ms_[k].lateral_bud) added += metamers(v_lateral_[k]);
    }
    const double per_metamer =
        sizeof(Metamer) + 8.0 * sizeof(double) + TreeGraph::bytes_per_node(4);
    check_memory((static_cast<double>(ms_.size()) + added) * per_metamer,
                 "growing a tree of " + std::to_string(ms_.size()) + " metamers by " +
                     std::to_string(static_cast<std::uint64_t>(added)) + " more");
  }

  void expire_lateral_buds(int year) {
    for (auto& m : ms_) {
      if (m.alive && m.lateral_bud && year - m.birth_year > p_.lateral_bud_lifetime_years) {
        m.lateral_bud = false;
      }
    }
  }

  // 1. Light Q and optimal growth direction V of every live bud (Palubicki step 1).
  void sense_light(int year) {
    const std::size_t n = ms_.size();
    q_terminal_.assign(n, 0.0);
    q_lateral_.assign(n, 0.0);
    dir_terminal_.assign(n, Eigen::Vector3d::UnitZ());
    dir_lateral_.assign(n, Eigen::Vector3d::UnitZ());
    Scene clusters;
    if (light_->needs_cluster_scene()) clusters = light_scene(year);
    BudLightOutput out{q_terminal_, q_lateral_, dir_terminal_, dir_lateral_};
    light_->sense({ms_, shoots_, light_->needs_cluster_scene() ? &clusters : nullptr}, out);
    const double f = p_.sky_light_fraction, k = p_.light_half_saturation;
    auto response = [f, k](double q) {
      q *= f;
      return std::isinf(k) ? q : q * (1.0 + k) / (q + k);
    };
    // The light a node's bud sensed, for the output's "light" attribute: nodes without a bud
    // sensed nothing, which is "no value" (nan), not darkness.
    bud_light_.assign(n, std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i = 0; i < n; ++i) {
      q_terminal_[i] = response(q_terminal_[i]);
      q_lateral_[i] = response(q_lateral_[i]);
      if (has_bud(ms_[i])) bud_light_[i] = ms_[i].terminal_bud ? q_terminal_[i] : q_lateral_[i];
    }
  }

  // 2. Basipetal accumulation, shedding lateral branches below the pruning factor (step 5).
  void accumulate_light(int year) {
    const std::size_t n = ms_.size();
    q_.assign(n, 0.0);
    count_.assign(n, 0);
    for (std::size_t k = n; k-- > 0;) {
      Metamer& m = ms_[k];
      if (!m.alive) continue;
      double q = (m.terminal_bud ? q_terminal_[k] : 0.0) + (m.lateral_bud ? q_lateral_[k] : 0.0);
      std::int64_t c = 1;
      if (m.main >= 0 && ms_[m.main].alive) {
        q += q_[m.main];
        c += count_[m.main];
      }
      if (m.lateral >= 0 && ms_[m.lateral].alive) {
        const std::int32_t l = m.lateral;
        if (year - ms_[l].birth_year >= 1 && q_[l] < p_.pruning_factor * count_[l]) {
          shed(l);
        } else {
          q += q_[l];
          c += count_[l];
        }
      }
      q_[k] = q;
      count_[k] = c;
    }
  }

  // 3. Acropetal extended Borchert-Honda allocation with apical control lambda (step 3).
  void allocate_vigour() {
    const std::size_t n = ms_.size();
    const double lambda = p_.apical_control;
    v_.assign(n, 0.0);
    v_terminal_.assign(n, 0.0);
    v_lateral_.assign(n, 0.0);
    v_[0] = p_.alpha * q_[0];
    for (std::size_t k = 0; k < n; ++k) {
      const Metamer& m = ms_[k];
      if (!m.alive || v_[k] <= 0.0) continue;
      const bool main_alive = m.main >= 0 && ms_[m.main].alive;
      const bool lat_alive = m.lateral >= 0 && ms_[m.lateral].alive;
      const double qm = main_alive ? q_[m.main] : (m.terminal_bud ? q_terminal_[k] : 0.0);
      const double ql = lat_alive ? q_[m.lateral] : (m.lateral_bud ? q_lateral_[k] : 0.0);
      const double den = lambda * qm + (1.0 - lambda) * ql;
      if (den <= 0.0) continue;
      const double vm = v_[k] * lambda * qm / den;
      const double vl = v_[k] * (1.0 - lambda) * ql / den;
      (main_alive ? v_[m.main] : v_terminal_[k]) = vm;
      (lat_alive ? v_[m.lateral] : v_lateral_[k]) = vl;
    }
  }

  void grow_shoot(std::size_t from, bool terminal, double v, int year) {
    // Palubicki's continuous option: the shoot is v internode lengths long, in round(v) metamers.
    const int count = std::clamp(static_cast<int>(std::lround(v)), 1, p_.max_shoot_metamers);
    const double length = v * p_.internode_length_m / count;
    Eigen::Vector3d d = terminal ? ms_[from].heading : ms_[from].lateral_dir;
    const Eigen::Vector3d& light_dir = terminal ? dir_terminal_[from] : dir_lateral_[from];
    // Tropism direction t (Pirk eq. 4.6): weighted mean of the light and gravity directions.
    Eigen::Vector3d t = Eigen::Vector3d::Zero();
    if (wsum_ > 0) t = (p_.phototropism * light_dir + p_.gravitropism * gravity_) / wsum_;
    // Pirk eq. 4.7: the default direction keeps (1 - sum w)^(l_s / l_i) of its weight.
    const double ws = std::pow(ws_, length / p_.internode_length_m);
    const std::uint16_t order = ms_[from].order + (terminal ? 0 : 1);
    double roll = ms_[from].roll + (terminal ? p_.phyllotaxy_deg : 90.0) * kDeg;
    std::int32_t prev = static_cast<std::int32_t>(from);
    Eigen::Vector3d pos = ms_[from].end;
    const std::int32_t shoot = static_cast<std::int32_t>(shoots_.size());
    int made = 0;
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < count; ++i) {
      Eigen::Vector3d h = ws * d + (1.0 - ws) * t;  // Pirk eq. 4.6
      if (p_.perturbation_deg > 0) {
        const double z = 2.0 * u(rng_) - 1.0, phi = 2.0 * std::numbers::pi * u(rng_);
        const double s = std::sqrt(1.0 - z * z);
        h = h.normalized() + std::sin(p_.perturbation_deg * kDeg) *
                                 Eigen::Vector3d(s * std::cos(phi), s * std::sin(phi), z);
      }
      if (h.norm() < 1e-12) h = d;
      h.normalize();
      Eigen::Vector3d end = pos + length * h;
      if (scene_.segment_blocked(pos, end)) {
        // A shoot that meets a solid turns to its optimal growth direction V (away from the
        // obstacle's shade) and stops only when that is blocked too.
        h = light_dir;
        end = pos + length * h;
        if (scene_.segment_blocked(pos, end)) break;
      }
      Metamer m;
      m.start = pos;
      m.end = end;
      m.heading = h;
      m.parent = prev;
      m.shoot = shoot;
      m.birth_year = year;
      m.order = order;
      m.roll = roll;
      m.lateral_bud = true;
      m.lateral_dir = lateral_direction(h, p_.branching_angle_deg * kDeg, roll);
      roll += p_.phyllotaxy_deg * kDeg;
      const std::int32_t id = static_cast<std::int32_t>(ms_.size());
      if (i == 0) {
        (terminal ? ms_[from].main : ms_[from].lateral) = id;
      } else {
        ms_[prev].main = id;
      }
      ms_.push_back(m);
      prev = id;
      pos = end;
      d = h;
      ++made;
    }
    // The bud is spent either way: it grew, or it would have grown into an obstacle.
    (terminal ? ms_[from].terminal_bud : ms_[from].lateral_bud) = false;
    if (made == 0) return;
    ms_[prev].terminal_bud = true;
    shoots_.push_back({prev - made + 1, prev, year, -1, true});
    grown_ += made;
  }

  GrowthResult finish() {
    GrowthResult out;
    const std::size_t n = ms_.size();
    // Pipe model radii from the tips (Palubicki step 6).
    std::vector<double> radius(n, 0.0);
    const double e = p_.pipe_exponent;
    for (std::size_t k = n; k-- > 0;) {
      const Metamer& m = ms_[k];
      if (!m.alive) continue;
      double sum = 0.0;
      if (m.main >= 0 && ms_[m.main].alive) sum += std::pow(radius[m.main], e);
      if (m.lateral >= 0 && ms_[m.lateral].alive) sum += std::pow(radius[m.lateral], e);
      const double disused = k < disused_pipes_.size() ? disused_pipes_[k] : 0.0;
      if (disused > 0.0) {
        // The living pipes (a tip's own) and the disused ones of shed branches.
        const double tip_pipe = std::pow(p_.tip_radius_m, e);
        radius[k] = std::pow((sum > 0 ? sum : tip_pipe) + disused * tip_pipe, 1.0 / e);
        continue;
      }
      radius[k] = sum > 0 ? std::pow(sum, 1.0 / e) : p_.tip_radius_m;
    }
    std::vector<NodeId> new_id(n, kNoNode);
    out.tree.reserve(n);
    out.tree.add_attribute(kLightAttribute, std::numeric_limits<double>::quiet_NaN());
    std::vector<std::int32_t> stack{0};
    double top = base_.z();
    // Light of the last cycle, at nodes that had a bud then.
    while (!stack.empty()) {
      const std::int32_t k = stack.back();
      stack.pop_back();
      const Metamer& m = ms_[k];
      NodeData d;
      d.start = m.start;
      d.end = m.end;
      d.radius = radius[k];
      d.birth_time = m.birth_year;
      d.order = m.order;
      d.kind = OrganKind::kInternode;
      const NodeId id = out.tree.add_node(m.parent < 0 ? kNoNode : new_id[m.parent], d);
      new_id[k] = id;
      if (static_cast<std::size_t>(k) < bud_light_.size()) {
        out.tree.attribute(kLightAttribute)[id] = bud_light_[k];
      }
      top = std::max(top, m.end.z());
      if (m.lateral >= 0 && ms_[m.lateral].alive) stack.push_back(m.lateral);
      if (m.main >= 0 && ms_[m.main].alive) stack.push_back(m.main);
    }
    out.internodes = out.tree.size();
    // Leaf clusters of the young shoots, as after one more cycle.
    const Scene s = light_scene(p_.years + 1);
    out.tree.add_attribute("translucency", 1.0);
    for (const auto& sh : shoots_) {
      if (sh.sphere < 0 || !sh.alive) continue;
      const Sphere& c = s.spheres[sh.sphere];
      out.cluster_spheres.push_back(c);
      NodeData d;
      d.start = c.center;
      d.end = c.center;
      d.direction = Eigen::Vector3d::UnitZ();
      d.length = 0.0;
      d.radius = c.radius_m;
      d.birth_time = sh.year;
      d.order = ms_[sh.last].order;
      d.kind = OrganKind::kLeaf;
      const NodeId id = out.tree.add_node(new_id[sh.last], d);
      out.tree.attribute("translucency")[id] = c.translucency;
    }
    // The mean light of each cluster's leaves through the final clusters as turbid media (the
    // shoots of the last cycle had no bud light). The cutoff is at most the sky's default: each
    // cluster below it is ignored alone, and in a crown hundreds of them add up.
    Scene leaf_scene = light_scene_settings(std::min(p_.light_significance, Sky{}.significance));
    record_leaf_light(out.tree, leaf_scene);
    out.clusters = out.cluster_spheres.size();
    out.shed = shed_;
    out.grown = grown_;
    out.height_m = top - base_.z();
    return out;
  }

  GrowthParams p_;
  Scene scene_;
  std::shared_ptr<const SkyDistribution> site_light_;  // the real sky's light, if any
  Eigen::Vector3d base_;
  std::mt19937_64 rng_;
  double wsum_ = 0.0, ws_ = 1.0;
  Eigen::Vector3d gravity_;
  std::vector<Metamer> ms_;
  std::vector<Shoot> shoots_;
  // Per node, this cycle: light Q and direction V of its terminal and lateral bud.
  std::vector<double> q_terminal_, q_lateral_;
  std::vector<double> bud_light_;  // light sensed by each node's bud in the last cycle, nan: no bud
  std::vector<Eigen::Vector3d> dir_terminal_, dir_lateral_;
  std::vector<double> q_, v_, v_terminal_, v_lateral_;
  std::unique_ptr<BudLight> light_;  // made after scene_, rng_ and the sky it reads
  std::vector<std::int64_t> count_;
  std::size_t shed_ = 0, grown_ = 0;
  std::vector<double> disused_pipes_;  // per metamer, of shed laterals (keep_shed_pipes)
};

}  // namespace

GrowthResult grow_tree(const GrowthParams& params, const Scene& scene,
                       const Eigen::Vector3d& base) {
  params.validate();
  return Grower(params, scene, base).run();
}

}  // namespace fspm::environment
