#pragma once
// Turtle interpretation of a substructure graph by instancing (Jaeger et al. 2010, 3.1.2), without
// expanding the string. Each substructure (lsystem/substructure_derivation.hpp) is drawn once in
// its own frame, the turtle starting at the origin with the identity orientation, and every
// occurrence is placed by the rigid transform of the turtle where the substructure starts; the
// turtle leaves the substructure transformed by the substructure's own exit transform, so the
// next module starts where the explicit interpretation would. What a substructure draws also
// depends on the turtle's line width and colour index where it starts: both are part of the memo
// key (one prototype per substructure and entry width and colour). The bracket depth only offsets
// the branching order (InstancedTree::Child::order).
//
// A substructure is instanced only when it is self-contained: its brackets [ ] and polygon braces
// { } balance and never close one opened before it, and it does not start inside a polygon.
// Others are walked through in the substructure that contains them.
//
// Drawing that depends on the absolute orientation cannot be moved rigidly: tropism (ABOP 2.2,
// `tropism direction` with an elasticity) and `$` (roll until L is horizontal), as well as
// homomorphism productions that are not context-free and pure. Those L-systems are interpreted
// explicitly (one prototype holding the whole plant) and `explicit_reason` says why.
//
// Pixel line widths (LineWidthUnit::kPixel) scale with the plant's largest extent, as in
// interpret(): exactly when the plant has at most kExactExtentPoints drawn points, otherwise from
// the boxes of the substructures (an upper bound, exact for axis-aligned turns).
#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>
#include <string>

#include "fspm/instanced_tree.hpp"
#include "lsystem/derivation.hpp"
#include "lsystem/lsystem.hpp"
#include "lsystem/substructure_derivation.hpp"
#include "lsystem/turtle.hpp"

namespace fspm::lsystem {

inline constexpr double kExactExtentPoints = 2e7;

struct InstancedInterpretationOptions {
  // Level of detail: > 0, a substructure whose drawing fits in a box with a diagonal shorter than
  // this (model units) is drawn as one internode from where it starts to where it leaves the
  // turtle (its chord; nothing when both are the same point). Pictures use about one pixel.
  // 0: every substructure drawn exactly.
  double min_detail = 0.0;
  // Largest explicit string of the explicit fallback, in modules.
  std::size_t module_budget = kDefaultModuleBudget;
};

struct InstancedInterpretation {
  InstancedTree tree;  // prototypes[0] is the axiom; parents come before their children
  // Of the explicit interpretation (counts saturate at 2^64 - 1).
  std::uint64_t internodes = 0;
  std::uint64_t leaves = 0;   // polygons and surfaces
  std::uint64_t flowers = 0;  // spheres @o
  // Occurrences of prototypes that draw something: the instances of the instanced mesh.
  std::uint64_t instances = 0;
  // Occurrences of all prototypes, those that only place others included.
  std::uint64_t occurrences = 0;
  // Box around everything drawn (an upper bound, see above).
  Eigen::AlignedBox3d bounds;
  // Non-empty: interpreted explicitly, because of this (see above).
  std::string explicit_reason;
};

// Draws the string `graph` stands for (homomorphism productions of `system` applied) with
// `settings`. Throws ValueError on a ']' without '[' or a '}' without '{' in the axiom's string,
// or when the explicit fallback exceeds its budget.
InstancedInterpretation interpret_instanced(const SubstructureGraph& graph, const LSystem& system,
                                            const TurtleSettings& settings,
                                            const InstancedInterpretationOptions& options = {});

}  // namespace fspm::lsystem
