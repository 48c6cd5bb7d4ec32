#pragma once
// The interface through which an open L-system talks to its environment (Mech and
// Prusinkiewicz 1996; cpfg's communication modules). After each derivation step the string is
// interpreted; every communication module ?E(...) becomes one query carrying the turtle's state
// at that module, and the environment fills in the module's parameters. The environment module
// (fspm::environment) implements it with light and obstacle tests.
#include <Eigen/Core>
#include <span>
#include <vector>

namespace fspm::lsystem {

struct EnvironmentQuery {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();  // turtle position at the module
  Eigen::Vector3d heading = Eigen::Vector3d::UnitZ();  // H
  Eigen::Vector3d left = Eigen::Vector3d::UnitY();     // L
  Eigen::Vector3d up = Eigen::Vector3d::UnitX();       // U
  // In: the module's current parameters. Out: the values the environment returns (the
  // environment may keep or change the count; the module takes the new list).
  std::vector<double> parameters;
};

class OpenEnvironment {
 public:
  virtual ~OpenEnvironment() = default;
  // Answers all communication modules of one step at once, so an environment can batch work
  // (one light pass for all points). Queries are in string order.
  virtual void respond(std::span<EnvironmentQuery> queries) = 0;
};

}  // namespace fspm::lsystem
