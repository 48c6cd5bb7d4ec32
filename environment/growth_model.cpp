#include "environment/growth_model.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

#include "environment/light_model.hpp"
#include "fspm/error.hpp"

namespace fspm::environment {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct Metamer {
  Eigen::Vector3d start, end, heading, lateral_dir;
  std::int32_t parent = -1, main = -1, lateral = -1;
  std::int32_t shoot = -1;
  int birth_year = 0;
  double roll = 0.0;  // phyllotaxy angle of this metamer's lateral bud around the heading
  std::uint16_t order = 0;
  bool alive = true;
  bool terminal_bud = false;
  bool lateral_bud = false;
};

struct Shoot {
  std::int32_t first = 0, last = 0;
  int year = 0;
  std::int32_t sphere = -1;  // index of its leaf cluster in this cycle's light scene
  bool alive = true;
};

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
    return finish();
  }

 private:
  Scene light_scene(int year) {
    Scene s = scene_;
    s.sky.directions = p_.light_directions;
    s.sky.significance = p_.light_significance;
    for (auto& sh : shoots_) {
      sh.sphere = -1;
      if (!sh.alive || year - sh.year > p_.leaf_years) continue;
      Eigen::Vector3d c = Eigen::Vector3d::Zero();
      const int n = sh.last - sh.first + 1;
      for (int i = sh.first; i <= sh.last; ++i) c += 0.5 * (ms_[i].start + ms_[i].end);
      c /= n;
      const double r = std::max(p_.cluster_radius_m, 0.5 * n * p_.internode_length_m);
      sh.sphere = static_cast<std::int32_t>(s.spheres.size());
      s.spheres.push_back({c, r, cluster_translucency(r, p_.gamma0), false});
    }
    return s;
  }

  void shed(std::int32_t root) {
    std::vector<std::int32_t> stack{root};
    while (!stack.empty()) {
      const std::int32_t i = stack.back();
      stack.pop_back();
      Metamer& m = ms_[i];
      if (!m.alive) continue;
      m.alive = false;
      ++shed_;
      if (shoots_[m.shoot].first == i) shoots_[m.shoot].alive = false;
      if (m.main >= 0) stack.push_back(m.main);
      if (m.lateral >= 0) stack.push_back(m.lateral);
    }
  }

  void cycle(int year) {
    const std::size_t n = ms_.size();
    // 1. Light at every node that carries a live bud (Q and V, Palubicki step 1).
    for (auto& m : ms_) {
      if (m.alive && m.lateral_bud && year - m.birth_year > p_.lateral_bud_lifetime_years) {
        m.lateral_bud = false;
      }
    }
    const LightModel light(light_scene(year));
    q_bud_.assign(n, 0.0);
    v_dir_.assign(n, Eigen::Vector3d::UnitZ());
    for (std::size_t i = 0; i < n; ++i) {
      const Metamer& m = ms_[i];
      if (!m.alive || !(m.terminal_bud || m.lateral_bud)) continue;
      const std::int32_t own = shoots_[m.shoot].sphere;
      const LightSample s =
          light.evaluate(m.end, own < 0 ? kNoSphere : static_cast<std::uint32_t>(own));
      q_bud_[i] = s.light;
      v_dir_[i] = s.direction;
    }
    // 2. Basipetal accumulation, shedding lateral branches below the pruning factor (step 5).
    q_.assign(n, 0.0);
    count_.assign(n, 0);
    for (std::size_t k = n; k-- > 0;) {
      Metamer& m = ms_[k];
      if (!m.alive) continue;
      double q = (m.terminal_bud ? q_bud_[k] : 0.0) + (m.lateral_bud ? q_bud_[k] : 0.0);
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
    // 3. Acropetal extended Borchert-Honda allocation with apical control lambda (step 3).
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
      const double qm = main_alive ? q_[m.main] : (m.terminal_bud ? q_bud_[k] : 0.0);
      const double ql = lat_alive ? q_[m.lateral] : (m.lateral_bud ? q_bud_[k] : 0.0);
      const double den = lambda * qm + (1.0 - lambda) * ql;
      if (den <= 0.0) continue;
      const double vm = v_[k] * lambda * qm / den;
      const double vl = v_[k] * (1.0 - lambda) * ql / den;
      if (main_alive) {
        v_[m.main] = vm;
      } else {
        v_terminal_[k] = vm;
      }
      if (lat_alive) {
        v_[m.lateral] = vl;
      } else {
        v_lateral_[k] = vl;
      }
    }
    // 4. Bud fate: a bud with v >= 1 grows floor(v) metamers (step 4).
    for (std::size_t k = 0; k < n; ++k) {
      if (!ms_[k].alive) continue;
      if (ms_[k].terminal_bud && v_terminal_[k] >= 1.0) grow_shoot(k, true, v_terminal_[k], year);
      if (ms_[k].lateral_bud && v_lateral_[k] >= 1.0) grow_shoot(k, false, v_lateral_[k], year);
    }
  }

  void grow_shoot(std::size_t from, bool terminal, double v, int year) {
    const int count = std::min(static_cast<int>(std::floor(v)), p_.max_shoot_metamers);
    Eigen::Vector3d d = terminal ? ms_[from].heading : ms_[from].lateral_dir;
    // Tropism direction t (Pirk eq. 4.6): weighted mean of the light and gravity directions.
    Eigen::Vector3d t = Eigen::Vector3d::Zero();
    if (wsum_ > 0) t = (p_.phototropism * v_dir_[from] + p_.gravitropism * gravity_) / wsum_;
    const std::uint16_t order = ms_[from].order + (terminal ? 0 : 1);
    double roll = ms_[from].roll + (terminal ? p_.phyllotaxy_deg : 90.0) * kDeg;
    std::int32_t prev = static_cast<std::int32_t>(from);
    Eigen::Vector3d pos = ms_[from].end;
    const std::int32_t shoot = static_cast<std::int32_t>(shoots_.size());
    int made = 0;
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < count; ++i) {
      Eigen::Vector3d h = ws_ * d + (1.0 - ws_) * t;  // Pirk eq. 4.6
      if (p_.perturbation_deg > 0) {
        const double z = 2.0 * u(rng_) - 1.0, phi = 2.0 * std::numbers::pi * u(rng_);
        const double s = std::sqrt(1.0 - z * z);
        h = h.normalized() + std::sin(p_.perturbation_deg * kDeg) *
                                 Eigen::Vector3d(s * std::cos(phi), s * std::sin(phi), z);
      }
      if (h.norm() < 1e-12) h = d;
      h.normalize();
      const Eigen::Vector3d end = pos + p_.internode_length_m * h;
      if (scene_.segment_blocked(pos, end)) break;  // no growth into solid obstacles
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
      radius[k] = sum > 0 ? std::pow(sum, 1.0 / e) : p_.tip_radius_m;
    }
    std::vector<NodeId> new_id(n, kNoNode);
    out.tree.reserve(n);
    out.tree.add_attribute("light", 0.0);
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
      if (static_cast<std::size_t>(k) < q_bud_.size()) out.tree.attribute("light")[id] = q_bud_[k];
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
    out.clusters = out.cluster_spheres.size();
    out.shed = shed_;
    out.grown = grown_;
    out.height_m = top - base_.z();
    return out;
  }

  GrowthParams p_;
  Scene scene_;
  Eigen::Vector3d base_;
  std::mt19937_64 rng_;
  double wsum_ = 0.0, ws_ = 1.0;
  Eigen::Vector3d gravity_;
  std::vector<Metamer> ms_;
  std::vector<Shoot> shoots_;
  std::vector<double> q_bud_, q_, v_, v_terminal_, v_lateral_;
  std::vector<Eigen::Vector3d> v_dir_;
  std::vector<std::int64_t> count_;
  std::size_t shed_ = 0, grown_ = 0;
};

}  // namespace

GrowthResult grow_tree(const GrowthParams& params, const Scene& scene,
                       const Eigen::Vector3d& base) {
  validate(params);
  return Grower(params, scene, base).run();
}

}  // namespace fspm::environment
