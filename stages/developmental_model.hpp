#pragma once
// Developmental stages of a static tree (Pirk 2013, chapter 5): a reverse growth simulation that
// turns one given tree into a model of its whole development, from which any intermediate stage
// t in [0, 1] (t = 1: the given tree) is computed directly, without simulating the stages before.
//
// Analysis, once per tree (5.2.2, 5.3):
//   - Gravelius order: the root edge has level 1; at a bifurcation the child deviating least
//     from its parent keeps the level and continues the chain, the others start chains one level
//     higher, or of the same level when all children differ by less than 5 % in angle and radius
//     (decurrent trees). A chain is a maximal run of edges without a level change.
//   - Growth rates (eq. 5.3-5.4): the main chain grows from t = 0, a lateral chain from the time
//     its parent chain reaches the branch point; every chain grows at the constant rate that
//     makes it reach its full length at t = 1 ("all branches still growing").
//   - Angle interpolation (eq. 5.5): a lateral chain starts at the mean branching angle of its
//     level and turns at a constant angular velocity to its final angle, which it reaches when
//     its subtree carries five growing tips and turns rigid (pipe model, 5.3.2).
//   - Radius interpolation (eq. 5.6-5.8): tips have the mean radius of the given tree's terminal
//     edges (their own at the end); every other edge has r_p = (sum r_i^u / b_p)^(1/u) over the
//     children present, u = 2.5, with b_p taken from the given tree (eq. 5.7), so t = 1 gives
//     back the given radii.
//   - Leaves and other organs appear when the edge that bears them is complete; until then each
//     tip of a stage carries the organs of its chain's tip in the given tree (5.3.7).
//   - Added structures (5.3.5-5.3.6, optional): copies of the crown's laterals on the bare trunk
//     below the crown, removed as the crown ratio of eq. 5.10 falls (stages/added_structures.hpp).
// Mesh input (5.2.1) is reduced to a tree graph first (stages/mesh_skeleton.hpp). Not modelled:
// filling chains of higher order (5.3.5). Growth-based editing of selected branches (5.4.1):
// stages/branch_edits.hpp.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include "fspm/name_table.hpp"
#include "fspm/tree_graph.hpp"
#include "stages/added_structures.hpp"
#include "stages/branch_edits.hpp"
#include "stages/growth_profile.hpp"
#include "stages/shed_branches.hpp"

namespace fspm::stages {

// Which child continues its parent's axis (and keeps its Gravelius level).
enum class Continuation : std::uint8_t {
  kLeastDeviation,  // Pirk 5.2.2: the child deviating least from the parent's direction
  kThickest,        // the thickest child (the least deviating of those within the tolerance)
};
inline constexpr NameTable<Continuation, 2> kContinuationNames{
    "continuation",
    {{Continuation::kLeastDeviation, "least_deviation",
      "the child deviating least from the parent's direction, Pirk 5.2.2"},
     {Continuation::kThickest, "thickest", "the thickest child"}}};

// "least_deviation", "thickest".
std::string_view continuation_name(Continuation continuation);
// Throws ValueError naming the known names (and the closest one) for anything else.
Continuation continuation_from_name(std::string_view name);

struct StagesParams {
  // The thickest child by default: in grown trees a thin lateral is often straighter than the
  // trunk after a bend, and Pirk's rule then follows it (his input trees are modelled, with
  // straight trunks).
  Continuation continuation = Continuation::kThickest;
  // Pirk 5.3.2: a branch stops bending once its subtree carries this many growing tips.
  int rigid_tip_count = 5;
  double pipe_exponent = 2.5;          // u of eq. 5.7-5.8 (Murray's 2.49)
  double same_level_tolerance = 0.05;  // 5.2.2: children within 5 % keep the parent's level
  AddedStructuresParams added;         // 5.3.5-5.3.6: branches the young tree had (off)
  BranchEdits edits;                   // 5.4.1: branches aged or copied (none)
  // Growth-rate profiles of the chains (5.3.1): eq. 5.3's constant rates, or chosen per chain.
  ProfileChoice profiles = ProfileChoice::kConstant;
  ShedBranchesParams shed;  // branches shed before the given tree, from the pipe model (off)
  void validate() const;    // throws ValueError for values out of range
};

// Pirk eq. 5.11: seasonal growth rhythm, t in [0, 1] remapped over `years` seasons with
// dormancy strength c in [1, 1.4] (c = 1: growth stops once a year) and shift s (0 for growth,
// 0.5 for the angle interpolation).
double seasonal_time(double t, int years, double c = 1.2, double s = 0.0);

class DevelopmentalModel {
 public:
  // Analyses `tree` (internodes as edges; leaves, flowers and buds as organs on them). Throws
  // ValueError for an empty tree or bad parameters.
  explicit DevelopmentalModel(const TreeGraph& tree, const StagesParams& params = {});

  // The stage at time t (clamped to [0, 1]) into `out`, reusing its memory: the edges grown by
  // then (a growing edge at its partial length), with order = Gravelius level - 1 and
  // birth_time = the time the edge starts growing. Reuses buffers of the model too, so one model
  // computes one stage at a time (use one model per thread).
  void stage(double t, TreeGraph& out) const;
  TreeGraph stage(double t) const;

  // With added structures on, the analysis (chains, levels, the per-node vectors below) is of
  // the given tree with the copies appended (node ids from the given tree's size on), then the
  // branch copies of StagesParams::edits. Times in these vectors are on each chain's own clock,
  // which an age edit or a copy shifts by chain_shift() (stage birth times are on the common one).
  std::size_t chain_count() const { return chain_rate_.size(); }
  // Branches added below the crown (0 unless StagesParams::added is enabled), the given tree's
  // crown (always) and the crown ratio curve of eq. 5.10 fitted to it (with added structures).
  std::size_t added_branch_count() const { return added_.copies; }
  // Of those, the copies in the overlap region above the crown base (AddedStructuresParams::
  // overlap), and the height of that region's top (0: none).
  std::size_t overlap_branch_count() const { return added_.overlap_copies; }
  // Branches shed before the given tree, reconstructed from the pipe model (StagesParams::shed),
  // and the time each is shed, in the order of their first nodes.
  std::size_t shed_branch_count() const { return shed_root_.size(); }
  const std::vector<double>& shed_times() const { return shed_time_; }
  double overlap_top_m() const { return added_.overlap_top_m; }
  const CrownShape& crown() const { return added_.crown; }
  const CrownRatioCurve& crown_ratio_curve() const { return added_.curve; }
  std::size_t lateral_chain_count() const;
  // Per node of the given tree: Gravelius level (1 on the main axis; organs take their edge's),
  // its chain, and the time it starts growing.
  const std::vector<std::uint16_t>& level() const { return level_; }
  const std::vector<std::uint32_t>& chain() const { return chain_; }
  const std::vector<double>& start_time() const { return start_time_; }
  // Per chain: growth rate (length per unit of t) and the time it starts.
  const std::vector<double>& chain_rate() const { return chain_rate_; }
  const std::vector<double>& chain_start() const { return chain_start_; }
  // Per chain: its growth profile (constant for every chain unless StagesParams::profiles says).
  const std::vector<ChainProfile>& chain_profile() const { return chain_profile_; }
  // Per chain: how far its clock runs ahead of t (growth-based editing; empty without edits).
  const std::vector<double>& chain_shift() const { return chain_shift_; }

 private:
  void add_missing_structures();
  void apply_edits();
  bool is_internode(NodeId n) const;
  NodeId edited_branch_base(NodeId node, const char* what) const;
  std::vector<NodeId> subtree(NodeId base, NodeId end = kNoNode) const;
  void mark_edited_ancestors(NodeId from);
  // Returns how far the copy's clock runs ahead of its source's (its chain_shift_ minus the
  // source's); `roll_rad` turns it about the target's heading; `branch`, when given, is the
  // source's subtree(base) to copy.
  double append_branch_copy(const CopyEdit& edit, double roll_rad = 0.0,
                            const std::vector<NodeId>* branch = nullptr);
  void reconstruct_shed_branches();
  void remove_shed(double t, const TreeGraph& grown, TreeGraph& out) const;
  void assign_levels_and_chains();
  NodeId continuation(NodeId p, const std::vector<NodeId>& edges) const;
  void compute_growth_times();
  void propagate_growth_times();
  void choose_chain_profiles();
  double reach_time(std::uint32_t c, double length_m) const;
  double grown_length(std::uint32_t c, double tc) const;
  void compute_bending();
  void compute_radius_coefficients();
  void place_nodes(double t, TreeGraph& out) const;
  bool bend(NodeId i, double tc, Eigen::Quaterniond& q) const;
  void set_radii(TreeGraph& out) const;
  void add_tip_leaves(TreeGraph& out) const;
  void build_plans();
  void build_tip_organs();

  TreeGraph tree_;  // the given tree, with the added structures appended when they are on
  StagesParams params_;
  // Branches shed before the given tree (StagesParams::shed): the first node of each copy and
  // the time it is shed.
  std::vector<NodeId> shed_root_;
  std::vector<double> shed_time_;
  std::vector<double> chain_shed_time_;  // per chain, of a shed branch's first chain (else inf)
  std::vector<NodeId> chain_shed_end_;   // per such chain, the id after its branch's last node
  AddedStructures added_;                // its tree is moved into tree_
  NodeId added_end_ = 0;   // nodes added_.first_added..added_end_ - 1 are added structures
  NodeId given_size_ = 0;  // nodes of the given tree
  std::vector<double> chain_shift_;  // per chain, t of its own clock minus t (edits only)
  std::vector<std::uint16_t> level_;
  std::vector<std::uint32_t> chain_;
  std::vector<double> offset_;            // length of the chain before the edge
  std::vector<double> start_time_;        // when the edge starts growing
  std::vector<std::uint8_t> chain_base_;  // first edge of a lateral chain
  std::vector<double> chain_rate_, chain_start_;
  std::vector<double> chain_length_;         // per chain
  std::vector<ChainProfile> chain_profile_;  // per chain (constant: eq. 5.3)
  std::vector<NodeId> chain_last_;           // last edge of each chain
  // Bending of lateral chain bases (eq. 5.5): axis, final angle minus initial angle, and the
  // time span over which it is made up.
  std::vector<Eigen::Vector3d> bend_axis_;
  std::vector<double> bend_angle_, bend_end_;
  std::vector<double> radius_coefficient_;    // b_p of eq. 5.7 (0 for final tips)
  double tip_radius_ = 0.0;                   // r_avg
  double tip_radius_pow_ = 0.0;               // r_avg^u
  std::vector<double> radius_pow_;            // r^u of the given tree
  std::vector<std::uint32_t> edge_children_;  // internode children in the given tree
  std::vector<Eigen::Vector3d> heading_;      // unit directions of the given tree
  // What a stage reads per node, in one cache line (build_plans()); what only organs and nodes
  // that do not start at their parent's end need is in a side record.
  struct alignas(64) PlacePlan {
    // What decides whether the node is present comes first.
    std::uint32_t chain = 0;       // of an organ, its internode's
    std::uint32_t side = kNoNode;  // index in side_plan_, kNoNode for none
    OrganKind kind = OrganKind::kInternode;
    std::uint8_t chain_base = 0;
    std::uint16_t order = 0, age = 1;
    std::uint8_t chain_last = 0;  // the last edge of its chain
    double chain_offset = 0.0, length = 0.0, start_time = 0.0;
    Eigen::Vector3d heading;  // unit heading of an internode, direction of an organ
  };
  struct SidePlan {
    Eigen::Vector3d offset;  // start minus the parent's end
    Eigen::Vector3d span;    // end minus start of an organ
    double radius = 0.0;     // of an organ (set_radii gives the internodes theirs)
  };
  struct RadiusPlan {
    double radius = 0.0, radius_pow = 0.0, coefficient = 0.0;
    std::uint32_t edge_children = 0;
    std::uint8_t edge = 0;
  };
  std::vector<PlacePlan> plan_;
  std::vector<SidePlan> side_plan_;
  struct BendPlan {  // per chain, the bend of its base (eq. 5.5); angle 0 for none
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
    double angle = 0.0, end = 1.0;
  };
  std::vector<BendPlan> bend_plan_;
  std::vector<RadiusPlan> radius_plan_;
  // Per chain, the organs on its last edge in the given tree (5.3.7): their data with start and
  // end relative to that edge's end; chain c has tip_organs_[tip_organ_start_[c] ..
  // tip_organ_start_[c + 1]).
  std::vector<NodeData> tip_organs_;
  std::vector<std::uint32_t> tip_organ_start_;
  Eigen::Vector3d root_start_ = Eigen::Vector3d::Zero();
  // Buffers of stage(), kept between calls (a slider computes stage after stage).
  // Per node of tree_: its id in the stage (kNoNode when absent) and what its children read.
  enum NodeFlag : std::uint8_t { kComplete = 1, kTurned = 2 };  // grown fully; turn_ holds q
  struct Below {  // per stage node: what its children give eq. 5.8
    double sum = 0.0;
    std::uint32_t complete_children = 0;
    std::uint8_t has_child = 0;
  };
  mutable std::vector<NodeId> stage_id_;
  mutable std::vector<std::uint8_t> flags_;
  mutable std::vector<NodeId> given_of_;  // per stage node, the node of tree_ it stands for
  mutable std::vector<Eigen::Quaterniond> turn_;
  mutable std::vector<Below> below_;
  // Per stage node: its chain while it is an internode with nothing placed on it that is not its
  // chain's last edge (it then carries its chain's tip organs, 5.3.7), else ~0.
  mutable std::vector<std::uint32_t> tip_chain_;
  mutable TreeGraph grown_tree_;  // the stage with every added branch, before shedding
  // Per shed branch left out of this stage: its parent's stage node and its r^u.
  mutable std::vector<std::pair<NodeId, double>> shed_pipes_;
  mutable std::vector<NodeId> kept_id_;
};

}  // namespace fspm::stages
