#pragma once
// 3D turtle interpretation of a module string (ABOP section 1.5 and chapter 2 conventions) into
// an fspm::TreeGraph. Coordinates: z is up; the turtle starts at the origin heading up (H = +z)
// with L = -x and U = H x L = -y (cpfg's screen frame y-up mapped to z-up: (x, y, z)_cpfg ->
// (x, -z, y)).
//   F, F(l)   forward l (default step 1), one internode        f, f(l)  move without drawing
//   G, g      forward / move, never a polygon vertex           + - (a)  turn left / right about U
//   & ^ (a)   pitch down / up about L                          \ / (a)  roll left / right about H
//   |         turn around                                      $        roll until L is horizontal
//   [ ]       push / pop the turtle state                      ; ' , (c) color index + / set, -
//   ! (w)     decrease the line width / set it                 # (w)    increase it / set it
//   { . }     polygon: begin, record a vertex, end (a leaf)    ~x(s)    predefined surface (a leaf)
//   @o(d)     sphere of diameter d: a flower organ
// The line width is the drawn internode's diameter, in pixels or model units (LineWidthUnit).
// Tropism (ABOP section 2.2, bending by elasticity): after every F the heading turns toward T by
// e |H x T|, e = initial elasticity + elasticity increment * branch depth.
#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "fspm/tree_graph.hpp"
#include "lsystem/module_string.hpp"

namespace fspm::lsystem {

// What a line width (`!`, `#`, `initial line width`) measures, as cpfg's line styles do.
//   kPixel: a line width in pixels of a picture in which the plant's largest extent spans
//     kPixelsAcrossPlant pixels (cpfg's default style, `line style: pixel`, or
//     `initial line width: w pixels`). The internode diameter is w * extent / kPixelsAcrossPlant
//     model units, so the drawn plant keeps the proportions of the line drawing.
//   kModel: a diameter in model units, the units of F (cpfg's `line style: polygon` or
//     `cylinder`, or `initial line width: w` without a unit).
enum class LineWidthUnit : std::uint8_t { kPixel, kModel };

// Size of the reference picture of pixel line widths: the plant's largest extent in pixels.
inline constexpr double kPixelsAcrossPlant = 500.0;

struct TurtleSettings {
  double angle_deg = 90.0;
  double step = 1.0;  // length of F without a parameter
  double initial_line_width = 1.0;
  double line_width_increment = 1.0;
  LineWidthUnit line_width_unit = LineWidthUnit::kPixel;                // cpfg's default line style
  Eigen::Vector3d tropism_direction = Eigen::Vector3d(0.0, 0.0, -1.0);  // z-up coordinates
  double initial_elasticity = 0.0;
  double elasticity_increment = 0.0;
};

// View file keys (case-insensitive, unknown keys ignored as cpfg has many display settings):
// `angle factor: n` (angle = 360/n), `angle increment: deg`, `initial line width: w [pixels]`
// (without a unit the widths become model units, with `p`/`pixels` pixels, as in cpfg),
// `line style: pixel|polygon|cylinder` (pixel widths, or model-unit widths for the other two),
// `line width increment: w`, `tropism direction: x,y,z` (cpfg frame, y up),
// `initial elasticity: e`, `elasticity increment: e`, `step: l` (fspm extension).
TurtleSettings parse_view(std::string_view text, const std::string& name = "<view>",
                          TurtleSettings base = {});
TurtleSettings read_view_file(const std::string& path, TurtleSettings base = {});
// The `.v` file beside an `.l` file (same stem) if it exists, else defaults.
TurtleSettings view_for_lsystem(const std::string& lsystem_path);

struct LeafPolygon {
  NodeId node = kNoNode;
  std::vector<Eigen::Vector3d> vertices;
  double area = 0.0;
};

struct Interpretation {
  TreeGraph tree;  // internodes (F) and leaves ({...} polygons, ~ surfaces); attribute
                   // "color_index" on every node and "leaf_area" when there are leaves
  std::vector<LeafPolygon> leaves;
};

// Draws `s`. Unknown modules are ignored. Throws ValueError on a ']' without '[' or a
// '}' without '{'.
Interpretation interpret(const ModuleString& s, const SymbolTable& symbols,
                         const TurtleSettings& settings = {});

}  // namespace fspm::lsystem
