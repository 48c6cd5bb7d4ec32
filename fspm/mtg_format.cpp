#include "fspm/mtg_format.hpp"

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <ostream>
#include <vector>

#include "fspm/error.hpp"
#include "fspm/nesting_depth.hpp"

#include "fspm/number_text.hpp"

namespace fspm {
namespace {

char symbol(OrganKind k) {
  switch (k) {
    case OrganKind::kInternode:
      return 'I';
    case OrganKind::kLeaf:
      return 'L';
    case OrganKind::kFlower:
      return 'F';
    case OrganKind::kBud:
      return 'B';
  }
  return 'I';
}

// The child that continues n's axis ('<' in MTG): the first child of the same order.
NodeId successor(const TreeGraph& t, NodeId n) {
  for (NodeId c : t.children(n)) {
    if (t.order(c) == t.order(n)) return c;
  }
  return kNoNode;
}

}  // namespace

void write_mtg(const TreeGraph& tree, std::ostream& out) {
  const std::vector<std::string> names = tree.attribute_names();
  out << "CODE:\tFORM-A\n\nCLASSES:\nSYMBOL\tSCALE\tDECOMPOSITION\tINDEXATION\tDEFINITION\n"
         "$\t0\tFREE\tFREE\tIMPLICIT\nP\t1\tFREE\tFREE\tIMPLICIT\n"
         "I\t2\tFREE\tFREE\tIMPLICIT\nL\t2\tFREE\tFREE\tIMPLICIT\n"
         "F\t2\tFREE\tFREE\tIMPLICIT\nB\t2\tFREE\tFREE\tIMPLICIT\n\n"
         "DESCRIPTION:\nLEFT\tRIGHT\tRELTYPE\tMAX\nI\tI,L,F,B\t<\t?\nI\tI,L,F,B\t+\t?\n\n"
         "FEATURES:\nNAME\tTYPE\nXX\tREAL\nYY\tREAL\nZZ\tREAL\nLength\tREAL\nRadius\tREAL\n"
         "BirthTime\tREAL\nOrder\tINT\n";
  for (const std::string& n : names) out << n << "\tREAL\n";
  if (tree.empty()) {
    out << "\nMTG:\nENTITY-CODE\n/P1\n";
    return;
  }

  // Column of each node in the MTG table: branches ('+') move one column to the right.
  // Ids are topologically ordered, so a forward pass suffices.
  std::vector<int> column(tree.size(), 0);
  int columns = 1;
  for (NodeId n = 1; n < tree.size(); ++n) {
    const NodeId p = tree.parent(n);
    column[n] = column[p] + (successor(tree, p) == n ? 0 : 1);
    columns = std::max(columns, column[n] + 1);
  }
  out << "\nMTG:\nENTITY-CODE";
  for (int c = 0; c < columns; ++c) out << '\t';
  out << "XX\tYY\tZZ\tLength\tRadius\tBirthTime\tOrder";
  for (const std::string& n : names) out << '\t' << n;
  out << "\n/P1\n";

  std::vector<std::span<const double>> attrs;
  for (const std::string& n : names) attrs.push_back(tree.attribute(n));
  std::string line;
  auto emit = [&](NodeId n, const char* relation) {
    line.assign(static_cast<std::size_t>(column[n]), '\t');
    line += relation;
    line += symbol(tree.kind(n));
    line += std::to_string(n + 1);
    line.append(static_cast<std::size_t>(columns - column[n]), '\t');
    const Eigen::Vector3d& e = tree.end(n);
    for (double v : {e.x(), e.y(), e.z(), tree.length(n), tree.radius(n), tree.birth_time(n)}) {
      append_number(line, v);
      line += '\t';
    }
    line += std::to_string(tree.order(n));
    for (const auto& a : attrs) {
      line += '\t';
      if (!std::isnan(a[n])) append_number(line, a[n]);
    }
    line += '\n';
    out << line;
  };

  // Depth first: a node, then its branches ('+', one column right), then its successor ('<',
  // same column, written "^<" to refer to the last entity of that column: this node).
  struct Item {
    NodeId node;
    const char* relation;
  };
  std::vector<Item> stack{{0, "^/"}};
  while (!stack.empty()) {
    const Item it = stack.back();
    stack.pop_back();
    emit(it.node, it.relation);
    const NodeId succ = successor(tree, it.node);
    if (succ != kNoNode) stack.push_back({succ, "^<"});
    std::vector<NodeId> branches;
    for (NodeId c : tree.children(it.node)) {
      if (c != succ) branches.push_back(c);
    }
    for (auto b = branches.rbegin(); b != branches.rend(); ++b) stack.push_back({*b, "+"});
  }
}

}  // namespace fspm

namespace fspm {
namespace {

// One entity of the MTG table, at any scale.
struct Entity {
  char symbol = 'I';
  char relation = 0;  // '/', '<', '+', or 0 for a top-level entity
  int ref = -1;       // the entity it relates to
  int scale = 1;
  int complex = -1;  // the entity it is a component of (-1: none)
  // The complex whose main axis it continues: its complex for a first component ('/'), its
  // predecessor's for '<', none (-1) for a branch ('+').
  int axis_of = -1;
  int line = 0;
  double index = std::numeric_limits<double>::quiet_NaN();  // the label's number (I12: 12)
  std::vector<std::string_view> values;  // feature cells (the last entity of a line only)
};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) {
    s.remove_prefix(1);
  }
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split_tabs(std::string_view line) {
  std::vector<std::string_view> cells;
  std::size_t from = 0;
  while (true) {
    const std::size_t tab = line.find('\t', from);
    cells.push_back(line.substr(from, tab == std::string_view::npos ? tab : tab - from));
    if (tab == std::string_view::npos) break;
    from = tab + 1;
  }
  return cells;
}

bool is_letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

OrganKind kind_of(char symbol) {
  switch (symbol) {
    case 'L':
      return OrganKind::kLeaf;
    case 'F':
      return OrganKind::kFlower;
    case 'B':
      return OrganKind::kBud;
    default:
      return OrganKind::kInternode;
  }
}

// A unit vector perpendicular to d.
Eigen::Vector3d perpendicular(const Eigen::Vector3d& d) {
  const Eigen::Vector3d a =
      std::abs(d.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  return d.cross(a).normalized();
}

// The MTG FORM-A reader: the sections in file order (CLASSES, the table header, the entity
// table), then the tree of the finest scale's entities.
class MtgParser {
 public:
  MtgParser(std::string_view text, const std::string& file) : file_(file) {
    split_lines(text);
    class_scale_.fill(-1);
    seen_scale_.fill(-1);
  }

  TreeGraph parse() {
    std::size_t k = read_classes();
    k = read_header(k);
    for (; k < lines_.size(); ++k) {
      if (!trim(lines_[k]).empty()) read_entity_line(k);
    }
    if (entities_.empty()) {
      fail("the MTG: table has no entity after its ENTITY-CODE header (is the file truncated?)",
           header_index_);
    }
    return build_tree();
  }

 private:
  [[noreturn]] void fail(const std::string& what, std::size_t index) const {
    throw ParseError(what, file_, static_cast<int>(index + 1));
  }

  // Lines without comments ('#' to the end of the line).
  void split_lines(std::string_view text) {
    for (std::size_t from = 0; from <= text.size();) {
      std::size_t end = text.find('\n', from);
      if (end == std::string_view::npos) end = text.size();
      std::string_view line = text.substr(from, end - from);
      if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) {
        line = line.substr(0, hash);
      }
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      lines_.push_back(line);
      from = end + 1;
    }
  }

  // CLASSES gives each symbol's scale (used to find what '^' and a branch refer to). Returns the
  // index of the "MTG:" line.
  std::size_t read_classes() {
    std::size_t k = 0;
    while (k < lines_.size() && trim(lines_[k]) != "MTG:") {
      if (trim(lines_[k]) != "CLASSES:") {
        ++k;
        continue;
      }
      for (++k; k < lines_.size(); ++k) {
        const std::string_view row = trim(lines_[k]);
        if (row.empty() || row.starts_with("SYMBOL")) continue;
        if (row.back() == ':' || row.starts_with("DESCRIPTION") || row.starts_with("FEATURES") ||
            row == "MTG:") {
          break;
        }
        const std::vector<std::string_view> cells = split_tabs(row);
        const std::string_view sym = trim(cells[0]);
        if (sym.size() == 1 && cells.size() > 1) {
          const auto sc = parse_number(trim(cells[1]));
          if (sc && *sc >= 0.0 && *sc <= 1000.0) {  // a scale is a small whole number
            class_scale_[static_cast<unsigned char>(sym[0]) & 127] = static_cast<int>(*sc);
          }
        }
      }
    }
    if (k == lines_.size()) fail("no 'MTG:' section: expected an MTG (FORM-A) file", 0);
    return k;
  }

  // Header: ENTITY-CODE, empty cells for the code columns, then the feature names (the features
  // are named in the table's own header). Returns the index of the first table line.
  std::size_t read_header(std::size_t k) {
    ++k;
    while (k < lines_.size() && trim(lines_[k]).empty()) ++k;
    if (k == lines_.size() || !trim(lines_[k]).starts_with("ENTITY-CODE")) {
      fail("expected the header line 'ENTITY-CODE' after 'MTG:'", std::min(k, lines_.size() - 1));
    }
    header_index_ = k;
    const std::vector<std::string_view> header = split_tabs(lines_[k]);
    code_columns_ = 1;
    while (code_columns_ < header.size() && trim(header[code_columns_]).empty()) ++code_columns_;
    // Each code column is one more level of branching.
    if (code_columns_ > static_cast<std::size_t>(kMaxTreeDepth)) {
      fail(nesting_too_deep(kMaxTreeDepth, "ENTITY-CODE columns"), k);
    }
    for (std::size_t c = code_columns_; c < header.size(); ++c) {
      features_.emplace_back(trim(header[c]));
    }
    column_entities_.resize(code_columns_);
    return k + 1;
  }

  // A symbol's scale: CLASSES', else the scale it had where it appeared first in the table.
  int scale_of_symbol(char c) const {
    const int from_classes = class_scale_[static_cast<unsigned char>(c) & 127];
    return from_classes >= 0 ? from_classes : seen_scale_[static_cast<unsigned char>(c) & 127];
  }

  // Whether an entity already in the table has the scale of a new entity's symbol (unknown for
  // a symbol not seen yet: then any entity will do).
  bool same_scale(const Entity& candidate, char symbol) const {
    const int want = scale_of_symbol(symbol);
    if (want < 0) return true;
    const int have = class_scale_[static_cast<unsigned char>(candidate.symbol) & 127];
    return (have >= 0 ? have : candidate.scale) == want;
  }

  // What a line's first entity refers to in a column: for '/', the last entity there; for '<'
  // and '+', the last one of the same scale (so that "^<U2" follows the unit U1 above, not the
  // internodes written after it).
  int last_in_column(std::size_t col, char relation, char symbol) const {
    const std::vector<int>& list = column_entities_[col];
    for (auto it = list.rbegin(); it != list.rend(); ++it) {
      if (relation == '/' || same_scale(entities_[static_cast<std::size_t>(*it)], symbol)) {
        return *it;
      }
    }
    return -1;
  }

  // One table line: its entity code (one or more entities) in the first non-empty code column,
  // and the feature cells of its last entity.
  void read_entity_line(std::size_t k) {
    const std::vector<std::string_view> cells = split_tabs(lines_[k]);
    std::size_t column = 0;
    while (column < cells.size() && column < code_columns_ && trim(cells[column]).empty()) {
      ++column;
    }
    if (column >= code_columns_ || column >= cells.size()) {
      fail("expected an entity code in the first " + std::to_string(code_columns_) +
               " columns (the ENTITY-CODE columns of the header)",
           k);
    }
    const std::string_view code = trim(cells[column]);
    int previous = -1;
    for (std::size_t p = 0; p < code.size();) {
      previous = read_entity(code, p, column, previous, k);
    }
    if (previous < 0) fail("empty entity code", k);
    Entity& last = entities_[static_cast<std::size_t>(previous)];
    for (std::size_t c = code_columns_; c < cells.size(); ++c) last.values.push_back(cells[c]);
    if (last.values.size() > features_.size()) {
      bool extra = false;
      for (std::size_t c = features_.size(); c < last.values.size(); ++c) {
        extra = extra || !trim(last.values[c]).empty();
      }
      if (extra) fail("more feature values than feature names in the header", k);
    }
  }

  // The entity at code[p...] ('^'? relation, symbol, digits), related to `previous` on the same
  // line or to an entity of the column; advances p and returns the entity's index.
  int read_entity(std::string_view code, std::size_t& p, std::size_t column, int previous,
                  std::size_t k) {
    Entity e;
    e.line = static_cast<int>(k + 1);
    bool same_column = false;
    if (code[p] == '^') {
      same_column = true;
      ++p;
    }
    if (p >= code.size() || (code[p] != '/' && code[p] != '<' && code[p] != '+')) {
      fail("entity code '" + std::string(code) +
               "': expected a relation '/', '<' or '+' (optionally after '^')",
           k);
    }
    e.relation = code[p++];
    if (p >= code.size() || !is_letter(code[p])) {
      fail("entity code '" + std::string(code) + "': expected a symbol letter after '" +
               std::string(1, e.relation) + "'",
           k);
    }
    e.symbol = code[p++];
    const std::size_t digits = p;
    while (p < code.size() && is_digit(code[p]) && p - digits < 15) ++p;
    if (p > digits) e.index = *parse_number(code.substr(digits, p - digits));
    while (p < code.size() && is_digit(code[p])) ++p;  // beyond 15 digits: not kept
    e.ref = entity_reference(e, code, column, previous, same_column, k);
    if (e.ref >= 0) {
      const Entity& r = entities_[static_cast<std::size_t>(e.ref)];
      e.scale = e.relation == '/' ? r.scale + 1 : r.scale;
      e.complex = e.relation == '/' ? e.ref : r.complex;
      e.axis_of = e.relation == '/' ? e.ref : e.relation == '<' ? r.axis_of : -1;
    }
    int& seen = seen_scale_[static_cast<unsigned char>(e.symbol) & 127];
    if (seen < 0) seen = e.scale;
    const int index = static_cast<int>(entities_.size());
    column_entities_[column].push_back(index);
    entities_.push_back(std::move(e));
    return index;
  }

  // The entity `e` relates to: the previous one on its line, the last suitable one in its own
  // column ('^') or in the column on its left; -1 for the first plant.
  int entity_reference(const Entity& e, std::string_view code, std::size_t column, int previous,
                       bool same_column, std::size_t k) const {
    int ref = -1;
    if (previous >= 0) {
      if (same_column) fail("entity code '" + std::string(code) + "': '^' only at its start", k);
      ref = previous;
    } else if (same_column) {
      ref = last_in_column(column, e.relation, e.symbol);
      if (ref < 0) {
        fail("'^' refers to an entity above in this column (of the same scale), but there is none",
             k);
      }
    } else if (column > 0) {
      ref = last_in_column(column - 1, e.relation, e.symbol);
      if (ref < 0) {
        fail("the entity refers to the column on its left, which holds none of its scale", k);
      }
    }
    if (ref < 0 && e.relation != '/') {
      fail("the first entity must be a plant or component ('/'), not '" +
               std::string(1, e.relation) + "'",
           k);
    }
    return ref;
  }

  int find_feature(std::initializer_list<const char*> names) const {
    for (const char* n : names) {
      for (std::size_t f = 0; f < features_.size(); ++f) {
        if (features_[f] == n) return static_cast<int>(f);
      }
    }
    return -1;
  }

  // Feature columns by role; every other named feature becomes a numeric attribute when all its
  // values are numbers (text features such as dates are kept out of the tree's attributes).
  void assign_feature_roles(TreeGraph& tree) {
    fx_ = find_feature({"XX"});
    fy_ = find_feature({"YY"});
    fz_ = find_feature({"ZZ"});
    f_length_ = find_feature({"Length", "length"});
    f_radius_ = find_feature({"Radius", "radius"});
    f_diameter_ = find_feature({"Diameter", "diameter", "TopDia", "TopDiameter"});
    f_birth_ = find_feature({"BirthTime"});
    f_order_ = find_feature({"Order"});
    for (std::size_t f = 0; f < features_.size(); ++f) {
      const int fi = static_cast<int>(f);
      if (fi == fx_ || fi == fy_ || fi == fz_ || fi == f_length_ || fi == f_radius_ ||
          fi == f_diameter_ || fi == f_birth_ || fi == f_order_ || features_[f].empty()) {
        continue;
      }
      attributes_.emplace_back(fi, features_[f]);
    }
    numeric_.assign(features_.size(), 1);
    for (const Entity& e : entities_) {
      for (std::size_t f = 0; f < e.values.size() && f < features_.size(); ++f) {
        const std::string_view v = trim(e.values[f]);
        if (!v.empty() && !parse_number(v)) numeric_[f] = 0;
      }
    }
    for (const auto& [f, name] : attributes_) {
      if (numeric_[static_cast<std::size_t>(f)] && !tree.has_attribute(name)) {
        tree.add_attribute(name, std::numeric_limits<double>::quiet_NaN());
      }
    }
  }

  static std::string index_name(char symbol) { return std::string(1, symbol) + "_index"; }

  // The label numbers: each node's own ("index") and those of the complexes it belongs to, one
  // attribute per coarser symbol ("U_index": the growth unit of an internode), so that what the
  // coarser scales group stays available. A feature of the same name (a file fspm wrote from an
  // imported tree) keeps its values.
  void add_index_attributes(TreeGraph& tree) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const Entity& e : entities_) {
      if (e.scale != finest_) continue;
      for (int c = e.complex; c >= 0; c = entities_[static_cast<std::size_t>(c)].complex) {
        complex_symbol_[static_cast<unsigned char>(entities_[static_cast<std::size_t>(c)].symbol) &
                        127] = 1;
      }
    }
    own_index_ = !tree.has_attribute("index");
    if (own_index_) tree.add_attribute("index", nan);
    for (int c = 0; c < 128; ++c) {
      if (complex_symbol_[static_cast<std::size_t>(c)] && tree.has_attribute(index_name(char(c)))) {
        complex_symbol_[static_cast<std::size_t>(c)] = 0;
      } else if (complex_symbol_[static_cast<std::size_t>(c)]) {
        tree.add_attribute(index_name(static_cast<char>(c)), nan);
      }
    }
  }

  std::optional<double> value(const Entity& e, int f) const {
    if (f < 0 || static_cast<std::size_t>(f) >= e.values.size()) return std::nullopt;
    const std::string_view v = trim(e.values[static_cast<std::size_t>(f)]);
    if (v.empty()) return std::nullopt;
    const std::optional<double> d = parse_number(v);
    if (!d) {
      throw ParseError("feature " + features_[static_cast<std::size_t>(f)] + ": '" +
                           std::string(v) + "' is not a number",
                       file_, e.line);
    }
    return d;
  }

  // The finest scale's entities are the nodes.
  TreeGraph build_tree() {
    for (const Entity& e : entities_) finest_ = std::max(finest_, e.scale);
    if (finest_ <= 1) return {};  // plants without components (what write_mtg gives for no tree)
    TreeGraph tree;
    assign_feature_roles(tree);
    add_index_attributes(tree);
    node_of_.assign(entities_.size(), kNoNode);
    last_component_.assign(entities_.size(), kNoNode);
    branches_of_.assign(1, 0);
    depth_of_.assign(1, 0);
    for (std::size_t i = 0; i < entities_.size(); ++i) {
      if (entities_[i].scale == finest_) add_node(tree, i);
    }
    return tree;
  }

  // A component's parent at the finest scale: its predecessor or bearer there, or, for the first
  // component of a complex ('/'), the last finest component of whatever that complex follows or
  // is borne by. `relation` becomes the relation toward that parent.
  NodeId parent_node(const Entity& e, char& relation) const {
    relation = e.relation;
    if (e.relation != '/' && e.ref >= 0 && node_of_[static_cast<std::size_t>(e.ref)] != kNoNode) {
      return node_of_[static_cast<std::size_t>(e.ref)];
    }
    // First component of a complex: climb the complexes until one follows or is borne by
    // another entity with finest components.
    NodeId parent = kNoNode;
    int c = e.relation == '/' ? e.ref : -1;
    while (c >= 0 && parent == kNoNode) {
      const Entity& ce = entities_[static_cast<std::size_t>(c)];
      if (ce.relation != '/' && ce.ref >= 0) {
        parent = last_component_[static_cast<std::size_t>(ce.ref)];
        relation = ce.relation;
      }
      c = ce.relation == '/' ? ce.ref : -1;
    }
    return parent;
  }

  // Where a node lies: its XX/YY/ZZ when given, else a turtle that continues the parent's heading
  // or branches off it, turning by the divergence angle from node to node along an axis
  // (phyllotaxis) and between siblings.
  void place(const TreeGraph& tree, const Entity& e, NodeId parent, char relation, NodeData& d) {
    constexpr double kBranchAngle = 45.0 * std::numbers::pi / 180.0;
    constexpr double kDivergence = 137.5 * std::numbers::pi / 180.0;
    const std::optional<double> length = value(e, f_length_);
    const std::optional<double> x = value(e, fx_), y = value(e, fy_), z = value(e, fz_);
    const Eigen::Vector3d base = parent == kNoNode ? Eigen::Vector3d::Zero() : tree.end(parent);
    if (x && y && z) {
      d.end = {*x, *y, *z};
      if (length && *length == 0.0) {
        d.start = d.end;  // a point organ (a leaf cluster, a bud)
      } else if (parent != kNoNode) {
        d.start = base;
      } else {
        d.start = d.end - length.value_or(0.0) * Eigen::Vector3d::UnitZ();
      }
      if (length) d.length = *length;
      return;
    }
    Eigen::Vector3d heading = Eigen::Vector3d::UnitZ();
    if (parent != kNoNode) {
      heading = tree.direction(parent);
      if (heading.squaredNorm() == 0.0) heading = Eigen::Vector3d::UnitZ();
      if (relation == '+') {
        const int k_branch = depth_of_[parent] + branches_of_[parent]++;
        const Eigen::Vector3d side =
            Eigen::AngleAxisd(kDivergence * k_branch, heading) * perpendicular(heading);
        heading = Eigen::AngleAxisd(kBranchAngle, side) * heading;
      }
    }
    const double len = length.value_or(1.0);
    d.start = base;
    d.end = base + len * heading.normalized();
    d.length = len;
    d.direction = heading.normalized();
  }

  // The node of finest entity i: kind, geometry, radius, birth, order and attributes.
  void add_node(TreeGraph& tree, std::size_t i) {
    const Entity& e = entities_[i];
    char relation = 0;
    const NodeId parent = parent_node(e, relation);
    if (parent == kNoNode && !tree.empty()) {
      throw ParseError(
          "a second tree: this entity is connected to nothing before it (fspm reads one plant "
          "per file)",
          file_, e.line);
    }
    NodeData d;
    d.kind = kind_of(e.symbol);
    if (const auto r = value(e, f_radius_)) {
      d.radius = *r;
    } else if (const auto dia = value(e, f_diameter_)) {
      d.radius = 0.5 * *dia;
    }
    if (const auto b = value(e, f_birth_)) d.birth_time = *b;
    place(tree, e, parent, relation, d);
    if (parent != kNoNode) {
      d.order = static_cast<std::uint16_t>(tree.order(parent) + (relation == '+' ? 1 : 0));
    }
    if (const auto o = value(e, f_order_)) {
      if (*o < 0 || *o > 65535 || std::floor(*o) != *o) {
        throw ParseError("feature Order: expected a whole number in [0, 65535]", file_, e.line);
      }
      d.order = static_cast<std::uint16_t>(*o);
    }
    if (d.length >= 0.0 && d.direction.squaredNorm() == 0.0) {
      const Eigen::Vector3d seg = d.end - d.start;
      if (seg.norm() > 0.0) d.direction = seg.normalized();
    }
    const NodeId id = tree.add_node(parent, d);
    node_of_[i] = id;
    branches_of_.resize(tree.size(), 0);
    depth_of_.resize(tree.size(), 0);
    if (parent != kNoNode) depth_of_[id] = depth_of_[parent] + 1;
    set_attributes(tree, e, id);
    // On the main axis of its complexes, this node is now their last finest component.
    for (int c = e.axis_of; c >= 0; c = entities_[static_cast<std::size_t>(c)].axis_of) {
      last_component_[static_cast<std::size_t>(c)] = id;
    }
    last_component_[i] = id;
  }

  void set_attributes(TreeGraph& tree, const Entity& e, NodeId id) const {
    for (const auto& [f, name] : attributes_) {
      if (!numeric_[static_cast<std::size_t>(f)]) continue;
      if (const auto v = value(e, f)) tree.attribute(name)[id] = *v;
    }
    if (own_index_) tree.attribute("index")[id] = e.index;
    for (int c = e.complex; c >= 0; c = entities_[static_cast<std::size_t>(c)].complex) {
      const Entity& ce = entities_[static_cast<std::size_t>(c)];
      if (complex_symbol_[static_cast<unsigned char>(ce.symbol) & 127]) {
        tree.attribute(index_name(ce.symbol))[id] = ce.index;
      }
    }
  }

  const std::string& file_;
  std::vector<std::string_view> lines_;
  std::array<int, 128> class_scale_;
  std::array<int, 128> seen_scale_;
  std::size_t header_index_ = 0;
  std::size_t code_columns_ = 1;
  std::vector<std::string> features_;
  std::vector<Entity> entities_;
  std::vector<std::vector<int>> column_entities_;  // entities written in each code column
  // The tree.
  int finest_ = 0;
  int fx_ = -1, fy_ = -1, fz_ = -1, f_length_ = -1, f_radius_ = -1, f_diameter_ = -1, f_birth_ = -1,
      f_order_ = -1;
  std::vector<std::pair<int, std::string>> attributes_;
  std::vector<std::uint8_t> numeric_;
  std::array<std::uint8_t, 128> complex_symbol_{};
  bool own_index_ = false;
  std::vector<NodeId> node_of_, last_component_;
  std::vector<int> branches_of_, depth_of_;  // branches placed on each node, its depth
};

}  // namespace

TreeGraph parse_mtg(std::string_view text, const std::string& file) {
  return MtgParser(text, file).parse();
}

}  // namespace fspm
