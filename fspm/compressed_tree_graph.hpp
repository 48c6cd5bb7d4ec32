#pragma once
// CompressedTreeGraph: Jaeger et al. (2010) tree graph with substructure factorization. One node
// record per metamer of each distinct substructure (physiological age, birth cycle); records are
// shared by every instance of the substructure, so the graph is a directed acyclic graph whose
// expansion is the plant's explicit tree. Each record holds Jaeger's node table columns (2.2):
// successor on the same axis, lateral (axillary) successors, physiological age, birth date,
// volumes of pith, rings and leaf, and multiplicity (how many metamers of the plant it stands
// for). File extension .ctree (docs/formats.md, ".ctree").
#include <cstdint>
#include <limits>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "fspm/tree_graph.hpp"

namespace fspm {

using RecordId = std::uint32_t;
inline constexpr RecordId kNoRecord = std::numeric_limits<RecordId>::max();

// What ends an axis at a record without successor.
enum class ApexState : std::uint8_t {
  kNone = 0,    // not the end of an axis, or the apex died
  kBud = 1,     // the apex is alive and may grow again
  kFlower = 2,  // the apex turned into a terminal flower
};

struct CompressedRecord {
  RecordId successor = kNoRecord;
  std::uint32_t axillary_begin = 0;  // into CompressedTreeGraph::axillary_refs()
  std::uint32_t axillary_count = 0;
  std::uint16_t physiological_age = 1;
  ApexState apex = ApexState::kNone;
  double birth = 0.0;  // birth date (growth cycle; may be fractional)
  double pith_volume = 0.0;
  double ring_volume = 0.0;
  double leaf_volume = 0.0;
  std::uint64_t multiplicity = 0;  // filled by compute_multiplicities()
};

inline constexpr std::uint32_t kNoPlacement = std::numeric_limits<std::uint32_t>::max();

// What a record draws when the graph carries turtle geometry (.ctree version 2): an organ in the
// frame of the group it hangs from, or nothing (a group record: a substructure whose members,
// its successor and axillaries, hang from what the group hangs from).
struct RecordGeometry {
  bool group = false;
  OrganKind kind = OrganKind::kInternode;
  std::uint16_t order = 0;  // branching order within its group; placements add theirs
  Eigen::Vector3d start = Eigen::Vector3d::Zero();
  Eigen::Vector3d end = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
  double length = 0.0;
  double radius = 0.0;
};

// A rigid transform placing a group in the frame of its referrer (Jaeger 3.1.2), and the
// branching order it adds.
struct Placement {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // group frame -> referrer frame
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  double order = 0.0;
};

// Turtle geometry of a drawn plant (L-systems), absent from GreenLab graphs, whose geometry comes
// from per-physiological-age numbers. Empty `records`: no geometry.
struct CtreeGeometry {
  std::vector<RecordGeometry> records;  // one per record
  std::vector<Placement> placements;
  // One per axillary reference (CompressedTreeGraph::axillary_refs()): index into placements,
  // or kNoPlacement for the referrer's own frame. Successors are always in the referrer's frame.
  std::vector<std::uint32_t> axillary_placements;
  // Per-record values of named node attributes (color_index, leaf_area, ...).
  std::map<std::string, std::vector<double>> attributes;

  bool empty() const { return records.empty(); }
  bool operator==(const CtreeGeometry& other) const;
};

class CompressedTreeGraph {
 public:
  // Adds a record; `axillaries` are the records starting the lateral axes it bears (a record may
  // be listed several times: that is the multiplicity of Jaeger's 2.2.2 example).
  RecordId add_record(const CompressedRecord& record, std::span<const RecordId> axillaries = {});
  void set_successor(RecordId id, RecordId successor) { records_[id].successor = successor; }
  void set_apex(RecordId id, ApexState apex) { records_[id].apex = apex; }
  void set_volumes(RecordId id, double pith, double rings, double leaf);
  void set_root(RecordId root) { root_ = root; }
  void reserve(std::size_t records, std::size_t axillaries);

  std::size_t size() const { return records_.size(); }
  bool empty() const { return records_.empty(); }
  RecordId root() const { return root_; }
  const CompressedRecord& record(RecordId id) const { return records_[id]; }
  std::span<const CompressedRecord> records() const { return records_; }
  std::span<const RecordId> axillaries(RecordId id) const {
    const auto& r = records_[id];
    return std::span<const RecordId>(axillary_refs_).subspan(r.axillary_begin, r.axillary_count);
  }
  std::span<const RecordId> axillary_refs() const { return axillary_refs_; }

  // Age of the plant when it was simulated (growth cycles) and its birth date; reconstruction
  // at an earlier age filters by birth date (Jaeger 3.2.2).
  double final_age = 0.0;
  double birth_date = 0.0;
  // Named numbers carried with the graph (e.g. per-physiological-age geometry for the
  // reconstruction), stored in the file.
  std::map<std::string, double> metadata;
  // Turtle geometry (docs/formats.md, .ctree version 2); empty for GreenLab graphs. Its rules
  // (checked by validate()): the root is a group, a placed reference leads to a group, a group
  // has at most one member that is not a group.
  CtreeGeometry geometry;
  bool has_geometry() const { return !geometry.empty(); }

  // Checks ids are in range and the graph is acyclic (and the geometry's rules, when it has
  // geometry); throws ValueError otherwise.
  void validate() const;
  // Instance counts: the root counts once, every reference (successor or axillary) adds its
  // referrer's multiplicity. Fills CompressedRecord::multiplicity and returns the total, which is
  // the number of metamers of the expanded tree. Throws ValueError on a cycle.
  std::uint64_t compute_multiplicities();
  // Sum of multiplicities (as last computed or read).
  std::uint64_t expanded_size() const;

  // The explicit tree: one internode per metamer instance, depth first with the successor
  // before the laterals; birth_time, physiological_age and order set, geometry left at zero.
  // Records born after `max_birth` are left out with everything they bear.
  TreeGraph expand(double max_birth = std::numeric_limits<double>::infinity()) const;

  bool operator==(const CompressedTreeGraph& other) const;

 private:
  void validate_geometry() const;

  std::vector<CompressedRecord> records_;
  std::vector<RecordId> axillary_refs_;
  RecordId root_ = kNoRecord;
};

// Binary .ctree files (docs/formats.md, ".ctree"), written atomically. Reading checks the magic,
// the version, every id and the stored multiplicities; throws ParseError/IoError.
void write_ctree_file(const CompressedTreeGraph& graph, const std::string& path);
CompressedTreeGraph read_ctree_file(const std::string& path);
// The same encoding to and from memory (used by the file functions and by tests).
std::string encode_ctree(const CompressedTreeGraph& graph);
CompressedTreeGraph decode_ctree(std::string_view bytes, const std::string& source_name = {});

}  // namespace fspm
