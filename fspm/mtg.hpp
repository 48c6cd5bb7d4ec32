#pragma once
// Mtg: a multiscale tree graph (Godin and Caraglio 1998), as OpenAlea's openalea.mtg holds one.
//
// Vertex 0 is the scale-0 root (`$`, the whole data set). Every other vertex is an entity of the
// plant at some scale (plant, axis, growth unit, internode ...): a component of one vertex of the
// next coarser scale (its complex) and, at its own scale, the successor ('<') or the branch ('+')
// of its parent. The coding file gives these relations explicitly at the finest scale; the
// coarser scales' edges follow from their components' (complete_topology, OpenAlea's fat_mtg).
// Features (the file's attribute columns) are kept as the text of their cells, one column per
// feature, and read as numbers on demand; dated repetitions of an entity ('*' lines of dynamic
// MTGs) are kept as observations.
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace fspm {

using MtgVertex = std::uint32_t;
inline constexpr MtgVertex kNoMtgVertex = std::numeric_limits<MtgVertex>::max();

// The relation of a vertex to its parent at its own scale.
enum class MtgEdge : char { kNone = 0, kSuccessor = '<', kBranch = '+' };

// The feature types of the coding file's FEATURES section (OpenAlea's and AMAPmod's).
enum class MtgFeatureType {
  kInt,
  kReal,
  kAlpha,
  kString,
  kDdMmYy,
  kDdMmYyyy,
  kMmYy,
  kDdMm,
  kGeometry,
  kAppearance,
  kObject
};
std::string_view mtg_feature_type_name(MtgFeatureType type);
std::optional<MtgFeatureType> mtg_feature_type_from_name(std::string_view name);
bool mtg_feature_is_date(MtgFeatureType type);
bool mtg_feature_is_number(MtgFeatureType type);

// One row of CLASSES: a class symbol (one or more letters; `$` is the scale-0 class) and its scale.
struct MtgClass {
  std::string symbol;
  int scale = 0;
  std::string decomposition = "FREE";
  std::string indexation = "FREE";
  std::string definition = "IMPLICIT";
};

// One row of DESCRIPTION: which classes may follow ('<') or be borne by ('+') `left`.
struct MtgRelationRule {
  std::string left;
  std::vector<std::string> right;
  char relation = '<';
  std::string max = "?";
};

struct MtgFeature {
  std::string name;
  MtgFeatureType type = MtgFeatureType::kReal;
  std::string argument;  // the file named after GEOMETRY, APPEARANCE or OBJECT
};

// A dated repetition of one entity's features ('*' lines): its cells in feature order.
struct MtgObservation {
  MtgVertex vertex = kNoMtgVertex;
  std::vector<std::string> values;
  int line = 0;
};

class Mtg {
 public:
  Mtg();

  // --- header ---
  std::string code_form = "FORM-A";
  std::vector<MtgClass> classes;  // in file order; the `$` class first
  std::vector<MtgRelationRule> description;

  const std::vector<MtgFeature>& features() const { return features_; }
  // Adds a feature column (empty cells for the vertices already there); returns its index.
  std::size_t add_feature(MtgFeature feature);
  std::optional<std::size_t> feature_index(std::string_view name) const;
  void set_feature_type(std::size_t feature, MtgFeatureType type) {
    features_[feature].type = type;
  }
  // The class of a symbol (index into `classes`), if declared.
  std::optional<std::size_t> class_index(std::string_view symbol) const;

  // --- vertices ---
  static constexpr MtgVertex root() { return 0; }
  std::size_t size() const { return scale_.size(); }
  // A new entity of class `class_id` (index into `classes`), component of `complex`; `index` is
  // its label's number (E12: 12), -1 when the label has none.
  MtgVertex add_component(MtgVertex complex, std::size_t class_id, long index, int line = 0);
  // Makes `parent` (same scale) the parent of `child`.
  void set_parent(MtgVertex child, MtgVertex parent, MtgEdge edge);

  int scale(MtgVertex v) const { return scale_[v]; }
  std::size_t class_id(MtgVertex v) const { return class_[v]; }
  const std::string& symbol(MtgVertex v) const { return classes[class_[v]].symbol; }
  long index(MtgVertex v) const { return index_[v]; }
  std::string label(MtgVertex v) const;  // symbol and index, "E12"
  MtgVertex complex(MtgVertex v) const { return complex_[v]; }
  MtgVertex parent(MtgVertex v) const { return parent_[v]; }
  MtgEdge edge(MtgVertex v) const { return edge_[v]; }
  int line(MtgVertex v) const { return line_[v]; }
  std::span<const MtgVertex> components(MtgVertex v) const { return components_[v]; }
  std::span<const MtgVertex> children(MtgVertex v) const { return children_[v]; }
  int max_scale() const { return max_scale_; }
  std::vector<MtgVertex> vertices(int scale) const;
  // The complex of `v` at a coarser scale (v itself at its own scale); kNoMtgVertex if none.
  MtgVertex complex_at_scale(MtgVertex v, int scale) const;
  // The plant (scale-1 complex) a vertex belongs to; kNoMtgVertex for the root.
  MtgVertex plant_of(MtgVertex v) const { return complex_at_scale(v, 1); }

  // --- features ---
  std::string_view feature_text(MtgVertex v, std::size_t feature) const {
    return values_[feature][v];
  }
  void set_feature_text(MtgVertex v, std::size_t feature, std::string_view text);
  // The cell as a number (INT, REAL) or, for a date, days since 1970-01-01 (DD/MM: day of the
  // year, from 0); nullopt when empty or not a number.
  std::optional<double> feature_number(MtgVertex v, std::size_t feature) const;
  std::vector<MtgObservation> observations;

  // Derives the edges of coarser scales from the first components' (OpenAlea's fat_mtg): a
  // vertex without a parent whose first component has a parent gets that parent's complex.
  void complete_topology();

 private:
  std::vector<MtgFeature> features_;
  std::vector<std::vector<std::string>> values_;  // [feature][vertex]
  std::vector<int> scale_;
  std::vector<std::uint32_t> class_;
  std::vector<long> index_;
  std::vector<MtgVertex> complex_, parent_;
  std::vector<MtgEdge> edge_;
  std::vector<int> line_;
  std::vector<std::vector<MtgVertex>> components_, children_;
  int max_scale_ = 0;
};

// Days since 1970-01-01 of a date cell of the given type (DD/MM/YY: years 00-49 are 2000-2049,
// 50-99 are 1950-1999; MM/YY: the first of the month; DD/MM: day of the year from 0).
std::optional<double> mtg_date_days(std::string_view text, MtgFeatureType type);

}  // namespace fspm
