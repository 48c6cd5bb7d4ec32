#pragma once
// The turtle's state machine shared by interpretation (turtle.cpp) and the query pass
// (query_pass.cpp). A visitor receives the drawing events; geometry lives here only.
#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <span>
#include <vector>

#include "fspm/error.hpp"
#include "lsystem/expression.hpp"
#include "lsystem/module_string.hpp"
#include "lsystem/turtle.hpp"

namespace fspm::lsystem::detail {

enum class Action : std::uint8_t {
  kNone,
  kForward,
  kMove,
  kForwardNoVertex,
  kMoveNoVertex,
  kLeft,
  kRight,
  kPitchDown,
  kPitchUp,
  kRollLeft,
  kRollRight,
  kTurnAround,
  kRollHorizontal,
  kPush,
  kPop,
  kWidthDown,
  kWidthUp,
  kColorUp,
  kColorDown,
  kPolygonBegin,
  kPolygonVertex,
  kPolygonEnd,
  kSurface,
  kQueryP,
  kQueryH,
  kQueryU,
  kQueryL,
  kCommunicate,
  kSphere
};

inline std::vector<Action> action_table(const SymbolTable& symbols) {
  std::vector<Action> t(symbols.size(), Action::kNone);
  for (std::size_t i = 0; i < symbols.size(); ++i) {
    const std::string& n = symbols.name(static_cast<SymbolId>(i));
    Action a = Action::kNone;
    if (n == "F")
      a = Action::kForward;
    else if (n == "f")
      a = Action::kMove;
    else if (n == "G")
      a = Action::kForwardNoVertex;
    else if (n == "g")
      a = Action::kMoveNoVertex;
    else if (n == "+")
      a = Action::kLeft;
    else if (n == "-")
      a = Action::kRight;
    else if (n == "&")
      a = Action::kPitchDown;
    else if (n == "^")
      a = Action::kPitchUp;
    else if (n == "\\")
      a = Action::kRollLeft;
    else if (n == "/")
      a = Action::kRollRight;
    else if (n == "|")
      a = Action::kTurnAround;
    else if (n == "$")
      a = Action::kRollHorizontal;
    else if (n == "[")
      a = Action::kPush;
    else if (n == "]")
      a = Action::kPop;
    else if (n == "!")
      a = Action::kWidthDown;
    else if (n == "#")
      a = Action::kWidthUp;
    else if (n == ";" || n == "'")
      a = Action::kColorUp;
    else if (n == ",")
      a = Action::kColorDown;
    else if (n == "{")
      a = Action::kPolygonBegin;
    else if (n == ".")
      a = Action::kPolygonVertex;
    else if (n == "}")
      a = Action::kPolygonEnd;
    else if (n.size() == 2 && n[0] == '~')
      a = Action::kSurface;
    else if (n == "?P")
      a = Action::kQueryP;
    else if (n == "?H")
      a = Action::kQueryH;
    else if (n == "?U")
      a = Action::kQueryU;
    else if (n == "?L")
      a = Action::kQueryL;
    else if (n == "?E")
      a = Action::kCommunicate;
    else if (n == "@o")
      a = Action::kSphere;
    t[i] = a;
  }
  return t;
}

struct Frame {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d heading = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d left = -Eigen::Vector3d::UnitX();
  Eigen::Vector3d up = -Eigen::Vector3d::UnitY();
  double width = 1.0;
  int color = 0;
  int depth = 0;
  NodeId node = kNoNode;
};

// Rotates a toward b by angle (radians) in their plane: a' = a cos + b sin, b' = -a sin + b cos.
inline void rotate_pair(Eigen::Vector3d& a, Eigen::Vector3d& b, double angle_rad) {
  const double c = std::cos(angle_rad);
  const double s = std::sin(angle_rad);
  const Eigen::Vector3d a2 = a * c + b * s;
  b = b * c - a * s;
  a = a2;
}

// The turtle's state and its response to one module, for walks over a string (walk below) or over
// a graph of substructures (lsystem/instanced_interpretation.cpp). Visitor interface (static):
// forward(start, heading, length, frame) after the move, polygon_begin(frame), vertex(point),
// polygon_end(frame), surface(scale, frame), sphere(diameter, line_width, frame),
// query(i, action, frame).
template <class Visitor>
class Turtle {
 public:
  Turtle(const TurtleSettings& settings, Visitor& visitor)
      : settings_(settings),
        visitor_(visitor),
        default_angle_(settings.angle_deg * kRad),
        t_(settings.tropism_direction) {
    f.width = settings.initial_line_width;
    tropism_ = t_.squaredNorm() > 0.0 &&
               (settings.initial_elasticity != 0.0 || settings.elasticity_increment != 0.0);
    if (tropism_) t_.normalize();
  }

  // Module `i` (for error messages and queries) with action `a` and parameters `p`.
  void apply(Action a, std::span<const double> p, std::size_t i) {
    const bool has = !p.empty();
    switch (a) {
      case Action::kForward:
      case Action::kForwardNoVertex:
      case Action::kMove:
      case Action::kMoveNoVertex: {
        const double length = has ? p[0] : settings_.step;
        const Eigen::Vector3d start = f.position;
        const Eigen::Vector3d heading = f.heading;
        f.position += f.heading * length;
        if (polygon_depth > 0) {
          if (a == Action::kForward || a == Action::kMove) visitor_.vertex(f.position);
          break;
        }
        if (a == Action::kForward || a == Action::kForwardNoVertex) {
          visitor_.forward(start, heading, length, f);
          if (tropism_) {
            // ABOP section 2.2: rotate by e |H x T| about H x T.
            const Eigen::Vector3d axis = f.heading.cross(t_);
            const double norm = axis.norm();
            const double e =
                settings_.initial_elasticity + settings_.elasticity_increment * f.depth;
            if (norm > 1e-12 && e != 0.0) {
              const Eigen::AngleAxisd r(e * norm, axis / norm);
              f.heading = (r * f.heading).normalized();
              f.left = (r * f.left).normalized();
              f.up = f.heading.cross(f.left);
            }
          }
        }
        break;
      }
      case Action::kLeft:
        rotate_pair(f.heading, f.left, has ? p[0] * kRad : default_angle_);
        break;
      case Action::kRight:
        rotate_pair(f.heading, f.left, -(has ? p[0] * kRad : default_angle_));
        break;
      case Action::kPitchDown:
        rotate_pair(f.heading, f.up, -(has ? p[0] * kRad : default_angle_));
        break;
      case Action::kPitchUp:
        rotate_pair(f.heading, f.up, has ? p[0] * kRad : default_angle_);
        break;
      case Action::kRollLeft:
        rotate_pair(f.left, f.up, has ? p[0] * kRad : default_angle_);
        break;
      case Action::kRollRight:
        rotate_pair(f.left, f.up, -(has ? p[0] * kRad : default_angle_));
        break;
      case Action::kTurnAround:
        f.heading = -f.heading;
        f.left = -f.left;
        break;
      case Action::kRollHorizontal: {
        // ABOP eq. 2.2: L = V x H / |V x H| with V opposite to gravity, U = H x L.
        const Eigen::Vector3d v = Eigen::Vector3d::UnitZ();
        const Eigen::Vector3d l = v.cross(f.heading);
        if (l.norm() > 1e-12) {
          f.left = l.normalized();
          f.up = f.heading.cross(f.left);
        }
        break;
      }
      case Action::kPush:
        stack.push_back(f);
        ++f.depth;
        break;
      case Action::kPop:
        if (stack.empty()) {
          throw ValueError("']' without a matching '[' at module " + std::to_string(i));
        }
        f = stack.back();
        stack.pop_back();
        break;
      case Action::kWidthDown:
        f.width = has ? p[0] : f.width - settings_.line_width_increment;
        break;
      case Action::kWidthUp:
        f.width = has ? p[0] : f.width + settings_.line_width_increment;
        break;
      case Action::kColorUp:
        f.color = has ? static_cast<int>(clamp_to_integer(p[0], -65535, 65535)) : f.color + 1;
        break;
      case Action::kColorDown:
        f.color = has ? static_cast<int>(clamp_to_integer(p[0], -65535, 65535)) : f.color - 1;
        break;
      case Action::kPolygonBegin:
        ++polygon_depth;
        visitor_.polygon_begin(f);
        break;
      case Action::kPolygonVertex:
        if (polygon_depth > 0) visitor_.vertex(f.position);
        break;
      case Action::kPolygonEnd:
        if (polygon_depth == 0) {
          throw ValueError("'}' without a matching '{' at module " + std::to_string(i));
        }
        --polygon_depth;
        visitor_.polygon_end(f);
        break;
      case Action::kSurface:
        visitor_.surface(has ? p[0] : 1.0, f);
        break;
      case Action::kSphere:
        visitor_.sphere(has ? p[0] : f.width, !has, f);
        break;
      case Action::kQueryP:
      case Action::kQueryH:
      case Action::kQueryU:
      case Action::kQueryL:
      case Action::kCommunicate:
        visitor_.query(i, a, f);
        break;
      case Action::kNone:
        break;
    }
  }

  Frame f;
  std::vector<Frame> stack;
  int polygon_depth = 0;

 private:
  static constexpr double kRad = std::numbers::pi / 180.0;
  const TurtleSettings& settings_;
  Visitor& visitor_;
  double default_angle_;
  Eigen::Vector3d t_;
  bool tropism_ = false;
};

template <class Visitor>
void walk(const ModuleString& s, const std::vector<Action>& actions, const TurtleSettings& settings,
          Visitor& visitor) {
  Turtle<Visitor> turtle(settings, visitor);
  const std::size_t n = s.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Action a = actions[s.symbol(i)];
    if (a != Action::kNone) turtle.apply(a, s.parameters(i), i);
  }
}

}  // namespace fspm::lsystem::detail
