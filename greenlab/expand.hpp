#pragma once
// Reconstruction (Jaeger 3): the explicit geometry of the plant at any age up to the simulated
// one, from its compressed tree graph and a few numbers per physiological age (angles, lengths,
// life spans) that the graph carries in its metadata.
#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "fspm/compressed_tree_graph.hpp"
#include "fspm/instanced_lod.hpp"
#include "fspm/instanced_tree.hpp"
#include "fspm/line_tree.hpp"
#include "fspm/tree_graph.hpp"
#include "greenlab/plant_params.hpp"

namespace fspm::greenlab {

struct ReconstructionParams {
  std::vector<AgeGeometry> ages;  // ages[p - 1]
  // GL1 volumes turned into dimensions by the allometry of Jaeger's annex.
  bool from_volumes = false;
  double leaf_thickness = 0.001;
  double reference_length = 5.0;
  double allometry_b = 1.0;

  const AgeGeometry& age(int p) const;
  static ReconstructionParams from_metadata(const std::map<std::string, double>& metadata);
};

// The per-age geometry of a plant description, as stored in a compressed graph's metadata.
std::map<std::string, double> geometry_metadata(const PlantParams& params);

// Leaf insertion (Jaeger 3.1.3: "the insertion angle is smoothly increased, and the leaf origin
// pushed to the branch surface"). The paper gives no formula; the increase is eased in over the
// leaf's first `opening` cycles by the smoothstep s(x) = x^2 (3 - 2x), x = min(age / opening, 1),
// which starts and ends with zero slope:
//   angle(age) = branching + increase * s(x)   (opening 0: branching + increase from birth).
double leaf_insertion_angle_deg(double branching_deg, double increase_deg, double opening_cycles,
                                double leaf_age_cycles);

// Internode height and radii from pith and ring volumes (Jaeger annex):
//   H = H_ref (Vp / V_ref)^(b / (1 + b)),  Rp^2 = V_ref / (pi H_ref) (Vp / V_ref)^(1 / (1 + b)),
//   Ri^2 = Rp^2 + Vr / (pi H),  with V_ref = pi H_ref.
struct InternodeDimensions {
  double length = 0.0;
  double pith_radius = 0.0;
  double radius = 0.0;
};
InternodeDimensions internode_dimensions(double pith_volume, double ring_volume,
                                         double reference_length, double allometry_b);

struct ReconstructionOptions {
  double age = -1.0;  // plant age to rebuild (cycles since its birth); < 0: the final age
  bool leaves = true;
  bool flowers = true;
  // Level of detail (Jaeger 3.1.1): applied by reconstruct() and reconstruct_into() (their
  // stats then count the nodes written: merged internodes once); reconstruct_lines() refuses it
  // and reconstruct_instanced() ignores it (reduce_instanced_tree() applies it to an instanced
  // tree). Leaves count as one order above their axis, as laterals do.
  LevelOfDetail lod{};
};

struct ReconstructionStats {
  double age = 0.0;
  std::uint64_t metamers = 0;
  std::uint64_t leaves = 0;
  std::uint64_t flowers = 0;
  std::uint64_t pruned_axes = 0;
  std::uint64_t components() const { return metamers + leaves; }
};

// Metamers of the plant born by `age` (pruning aside): the size of its explicit tree.
std::uint64_t metamers_at_age(const CompressedTreeGraph& graph, double age);
// The same, counting only the axes of branching order <= max_order (the trunk is order 0): an
// upper bound of the metamers a level of detail keeps (merging only removes more).
std::uint64_t metamers_within_order(const CompressedTreeGraph& graph, double age, double max_order);

// Records (internodes, leaves, flowers) of the plant's line tree at the options' age, as
// reconstruct_lines() writes them (born, not fallen), counted on the compressed graph without
// reconstructing. Summed over the ages 1..final and times LineTree::kBytesPerRecord, Jaeger's
// "sequence size" (Table 1). Graphs with turtle geometry: their organs (birth dates aside).
std::uint64_t line_records_at_age(const CompressedTreeGraph& graph,
                                  const ReconstructionOptions& options);

// An explicit tree holds at most this many metamers (a leaf and a flower each may add nodes).
inline constexpr std::uint64_t kMaxExplicitMetamers = std::uint64_t{1} << 30;

// Traverses oldest node first, axis by axis (trunk, then its laterals, then theirs): internodes
// as kInternode nodes, leaves as kLeaf children at the top of their metamer, terminal flowers as
// kFlower. Leaves and lateral axes are self-pruned by Jaeger's death status (3.2.1); nodes born
// after `age` are left out and diameters interpolated quadratically between birth and the final
// age (3.2.2). Throws ValueError when `age` is beyond the simulated age or the tree would
// exceed kMaxExplicitMetamers.
TreeGraph reconstruct(const CompressedTreeGraph& graph, const ReconstructionOptions& options,
                      ReconstructionStats* stats = nullptr);
// The same into `tree`, whose previous nodes are dropped but whose allocated columns are reused:
// rebuilding a plant at many ages (growth animation) then neither reallocates nor page-faults.
void reconstruct_into(const CompressedTreeGraph& graph, const ReconstructionOptions& options,
                      TreeGraph& tree, ReconstructionStats* stats = nullptr);

// The explicit plant as a LineTree (single precision, 45 bytes per component): the same records
// in the same order as reconstruct() gives nodes, with the same values to single precision. Each
// lateral axis whose subtree knows nothing of the absolute orientation (no straightening, no
// plagiotropy at its physiological age or above) is walked once, in its own frame, and copied
// with the rigid transform of each of its instances (Jaeger 3.1.2: instances of a substructure
// differ only by their placement); the other axes are walked one by one as in reconstruct().
// Throws as reconstruct() does.
LineTree reconstruct_lines(const CompressedTreeGraph& graph, const ReconstructionOptions& options,
                           ReconstructionStats* stats = nullptr);
// The same into `lines`, reusing its allocated columns (growth animation frames).
void reconstruct_lines_into(const CompressedTreeGraph& graph, const ReconstructionOptions& options,
                            LineTree& lines, ReconstructionStats* stats = nullptr);

// Graphs with turtle geometry (.ctree version 2, drawn L-systems) are expanded as drawn by all of
// these: the groups of the graph are the prototypes, birth dates filter, leaves and flowers
// options apply, GreenLab's per-age numbers, death and pruning do not.
//
// The instanced form for renderers (Jaeger 3.1.2): one prototype geometry per substructure that
// starts an axis, in its own frame (base at the origin, heading +z), and its lateral axes as
// references to other prototypes with the rigid transform that places them. Effects that depend
// on the absolute orientation (orthotropic straightening, plagiotropic flattening) are left out,
// as Jaeger notes; everything else (angles, lengths, diameters, pruning, birth-date filtering)
// is as in reconstruct().
//
// Prototypes are numbered as they are met, oldest axis first, so children come after their
// parents; expand_instanced_tree(tree, max_nodes, ExpansionOrder::kAxisByAxis) gives back the
// explicit tree with the nodes in reconstruct()'s order.
InstancedTree reconstruct_instanced(const CompressedTreeGraph& graph,
                                    const ReconstructionOptions& options);

}  // namespace fspm::greenlab
