#pragma once
// The growth model's metamers and shoots (environment/growth_model.cpp), as the bud light models
// (environment/bud_light.hpp) read them.
#include <Eigen/Core>
#include <cstdint>

namespace fspm::environment::growth {

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

// A live metamer with a bud: the light models light exactly these.
inline bool has_bud(const Metamer& m) { return m.alive && (m.terminal_bud || m.lateral_bud); }

struct Shoot {
  std::int32_t first = 0, last = 0;
  int year = 0;
  std::int32_t sphere = -1;  // index of its leaf cluster in this cycle's light scene
  bool alive = true;
};

}  // namespace fspm::environment::growth
