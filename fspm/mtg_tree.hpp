#pragma once
// A TreeGraph from one scale of a multiscale tree graph (docs/formats.md, "MTG").
//
// The nodes are the entities of one scale: --scale, or by default the finest scale whose
// entities carry geometry (coordinates, a length or a diameter), else the finest scale. Their
// parents and relations are the MTG's at that scale ('+' raises the branching order). A file of
// several plants gives one tree whose root is a node of length 0 at the origin (the MTG's scale-0
// entity) bearing every plant; plants without coordinates are set side by side along x.
//
// Geometry (plant_frame): coordinates XX YY ZZ are the entity's top point; Length (or length,
// Long, longueur, len) its length; TopDia, TopDiameter, Diameter, diam, diasom (or, when no top
// diameter is given, BotDia, BottomDiameter, diabase) its diameter; Radius its radius; Alpha
// (or insertion, AngBas) the insertion angle of a branch and Azimuth its turn, in degrees.
// Lengths are in `length_unit`, diameters and radii in `diameter_unit`. What the file does not
// give is inferred and flagged in the node attribute "inferred" (1: position, 2: radius).
//
// Attributes: "class" (the symbol's row in CLASSES, from 1), "index" (the label's number: E12 is
// 12), "<S>_index" for each coarser symbol S (the growth unit U of an internode ...), and every
// other feature under its own name: numbers as they are, dates as days since 1970-01-01, text as
// the rank of its value among the feature's distinct values in order of appearance (from 1).
// A feature Organ (leaf, flower, bud, internode) gives the node's kind, BirthTime and Order its
// birth time and order (the features fspm writes).
#include <optional>
#include <string>
#include <vector>

#include "fspm/length_unit.hpp"
#include "fspm/mtg.hpp"
#include "fspm/tree_graph.hpp"

namespace fspm {

struct MtgTreeOptions {
  int scale = -1;     // -1: the finest scale with geometry
  std::string plant;  // keep one plant: its label (P2) or number (2); empty: every plant
  LengthUnit length_unit = LengthUnit::kMetre;
  std::optional<LengthUnit> diameter_unit;  // default: length_unit
};

// What the conversion chose and inferred.
struct MtgTreeReport {
  int scale = 0;
  std::size_t plants = 0;
  std::size_t positions_inferred = 0;
  std::size_t radii_inferred = 0;
  std::size_t entities_left_out = 0;  // coarser entities without components at `scale`
};

// Throws ValueError for a scale the MTG does not have, a plant it does not hold, or no entity
// at the scale. Warnings (a tree taller than 200 m or a radius above 10 m read in metres, the
// entities left out) go to fspm::warn.
TreeGraph mtg_to_tree(const Mtg& mtg, const MtgTreeOptions& options = {},
                      MtgTreeReport* report = nullptr, const std::string& file = "<mtg>");

// The options every reader of MTG files uses when given none (read_tree_file): set once by the
// command line's --length-unit, --diameter-unit, --mtg-scale and --plant.
void set_default_mtg_tree_options(const MtgTreeOptions& options);
MtgTreeOptions default_mtg_tree_options();

}  // namespace fspm
