#include "fspm/text_tree_format.hpp"

#include <charconv>
#include <cmath>
#include <istream>
#include <ostream>
#include <vector>

#include "fspm/error.hpp"
#include "fspm/number_text.hpp"

namespace fspm {
namespace {

constexpr std::string_view kMagic = "fspm-tree";
constexpr std::string_view kColumns =
    "# id parent kind age order sx sy sz ex ey ez dx dy dz length radius birth";
constexpr std::size_t kFixedFields = 17;

bool valid_attribute_name(std::string_view name) {
  if (name.empty()) return false;
  for (char c : name) {
    if (c <= ' ' || c == '#' || c > '~') return false;
  }
  return true;
}

struct Token {
  std::string_view text;
  int column;  // 1-based
};

std::vector<Token> split(std::string_view line) {
  std::vector<Token> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    if (i >= line.size()) break;
    const std::size_t b = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    out.push_back({line.substr(b, i - b), static_cast<int>(b + 1)});
  }
  return out;
}

class Reader {
 public:
  Reader(std::istream& in, const std::string& source) : in_(in), source_(source) {}

  // Next line that is neither blank nor a comment; false at end of input.
  bool next(std::vector<Token>& tokens) {
    while (std::getline(in_, line_)) {
      ++line_no_;
      tokens = split(line_);
      if (tokens.empty() || tokens[0].text.front() == '#') continue;
      return true;
    }
    return false;
  }

  [[noreturn]] void fail(const std::string& what, int column = 0) const {
    throw ParseError(what, source_, line_no_, column);
  }

  double number(const Token& t, const char* field) const {
    const auto v = parse_number(t.text);
    if (!v)
      fail(std::string("expected a number for ") + field + ", found '" + std::string(t.text) + "'",
           t.column);
    return *v;
  }

  template <typename Int>
  Int integer(const Token& t, const char* field, Int max_value) const {
    std::uint64_t v = 0;
    const auto res = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v);
    if (res.ec != std::errc() || res.ptr != t.text.data() + t.text.size() ||
        v > static_cast<std::uint64_t>(max_value)) {
      fail(std::string("expected a non-negative integer for ") + field + " (at most " +
               std::to_string(max_value) + "), found '" + std::string(t.text) + "'",
           t.column);
    }
    return static_cast<Int>(v);
  }

  // Geometry is finite: nan and inf are for attributes only.
  double finite_number(const Token& t, const char* field) const {
    const double v = number(t, field);
    if (!std::isfinite(v)) {
      fail(std::string("expected a finite number for ") + field + ", found '" +
               std::string(t.text) + "'",
           t.column);
    }
    return v;
  }

  int line() const { return line_no_; }

 private:
  std::istream& in_;
  const std::string& source_;
  std::string line_;  // tokens point into it until the next call of next()
  int line_no_ = 0;
};

}  // namespace

void write_tree_text(const TreeGraph& tree, std::ostream& out, std::string_view comment) {
  const std::vector<std::string> names = tree.attribute_names();
  std::vector<std::span<const double>> columns;
  std::string buf;
  buf += kMagic;
  buf += ' ' + std::to_string(kTextTreeFormatVersion) + '\n';
  if (!comment.empty()) {
    buf += "# ";
    for (char c : comment) buf += c == '\n' ? ' ' : c;
    buf += '\n';
  }
  buf += "nodes " + std::to_string(tree.size()) + '\n';
  for (const std::string& name : names) {
    if (!valid_attribute_name(name)) {
      throw ValueError("attribute name '" + name +
                       "' cannot be written: names must be printable without spaces or '#'");
    }
    buf += "attribute " + name + ' ';
    append_number(buf, tree.attribute_default(name));
    buf += '\n';
    columns.push_back(tree.attribute(name));
  }
  buf += kColumns;
  for (const std::string& name : names) buf += ' ' + name;
  buf += '\n';
  for (NodeId n = 0; n < tree.size(); ++n) {
    buf += std::to_string(n);
    buf += ' ';
    if (tree.parent(n) == kNoNode) {
      buf += '-';
    } else {
      buf += std::to_string(tree.parent(n));
    }
    buf += ' ';
    buf += organ_kind_name(tree.kind(n));
    buf += ' ' + std::to_string(tree.physiological_age(n)) + ' ' + std::to_string(tree.order(n));
    for (const Eigen::Vector3d* v : {&tree.start(n), &tree.end(n), &tree.direction(n)}) {
      for (int k = 0; k < 3; ++k) {
        buf += ' ';
        append_number(buf, (*v)[k]);
      }
    }
    for (double x : {tree.length(n), tree.radius(n), tree.birth_time(n)}) {
      buf += ' ';
      append_number(buf, x);
    }
    for (const auto& col : columns) {
      buf += ' ';
      append_number(buf, col[n]);
    }
    buf += '\n';
    if (buf.size() > (1 << 16)) {
      out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
      buf.clear();
    }
  }
  out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
}

namespace {

// The header line 'fspm-tree VERSION' and the node count of the line 'nodes COUNT'.
std::uint64_t read_header(Reader& r, std::vector<Token>& t) {
  if (!r.next(t) || t[0].text != kMagic) {
    r.fail("expected the header 'fspm-tree " + std::to_string(kTextTreeFormatVersion) +
           "' (is this a .tree file?)");
  }
  if (t.size() != 2) r.fail("expected a version number after 'fspm-tree'");
  const int version = r.integer<int>(t[1], "the format version", 1000);
  if (version != kTextTreeFormatVersion) {
    r.fail("unsupported .tree format version " + std::to_string(version) + ", expected " +
               std::to_string(kTextTreeFormatVersion),
           t[1].column);
  }
  if (!r.next(t) || t[0].text != "nodes" || t.size() != 2) r.fail("expected 'nodes COUNT'");
  return r.integer<std::uint64_t>(t[1], "the node count", kNoNode - 1);
}

// The fixed fields of a node line after the ids: kind, ages, geometry and birth time.
NodeData read_node_fields(Reader& r, const std::vector<Token>& t) {
  NodeData d;
  try {
    d.kind = organ_kind_from_name(t[2].text);
  } catch (const ValueError& e) {
    r.fail(e.message(), t[2].column);
  }
  d.physiological_age = r.integer<std::uint16_t>(t[3], "the physiological age", 65535);
  d.order = r.integer<std::uint16_t>(t[4], "the branching order", 65535);
  static const char* kVecFields[] = {"start", "end", "direction"};
  for (int v = 0; v < 3; ++v) {
    Eigen::Vector3d& dst = v == 0 ? d.start : (v == 1 ? d.end : d.direction);
    for (int k = 0; k < 3; ++k) dst[k] = r.finite_number(t[5 + 3 * v + k], kVecFields[v]);
  }
  d.length = r.finite_number(t[14], "length");
  d.radius = r.finite_number(t[15], "radius");
  d.birth_time = r.finite_number(t[16], "birth time");
  return d;
}

}  // namespace

TreeGraph read_tree_text(std::istream& in, const std::string& source) {
  Reader r(in, source);
  std::vector<Token> t;
  const std::uint64_t count = read_header(r, t);

  TreeGraph tree;
  bool more = r.next(t);
  while (more && t[0].text == "attribute") {
    if (t.size() != 3) r.fail("expected 'attribute NAME DEFAULT'");
    const std::string name(t[1].text);
    if (tree.has_attribute(name)) r.fail("attribute '" + name + "' is declared twice", t[1].column);
    tree.add_attribute(name, r.number(t[2], "the attribute default"));
    more = r.next(t);
  }
  const std::vector<std::string> names = tree.attribute_names();
  // Reserve only what a plausible file needs, so a corrupt count cannot exhaust memory.
  tree.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(count, 1u << 24)));
  const std::size_t fields = kFixedFields + names.size();
  std::vector<double> attrs(names.size());
  for (std::uint64_t id = 0; id < count; ++id) {
    if (!more)
      r.fail("the file ends after " + std::to_string(id) + " of " + std::to_string(count) +
             " nodes");
    if (t.size() != fields) {
      r.fail("expected " + std::to_string(fields) + " fields (" + std::string(kColumns.substr(2)) +
             (names.empty() ? "" : " and the attributes") + "), found " + std::to_string(t.size()));
    }
    if (r.integer<std::uint64_t>(t[0], "the node id", kNoNode) != id) {
      r.fail("expected node id " + std::to_string(id) + " (ids are consecutive from 0)",
             t[0].column);
    }
    NodeId parent = kNoNode;
    if (t[1].text != "-") {
      parent = r.integer<NodeId>(t[1], "the parent id", kNoNode - 1);
      if (parent >= id)
        r.fail("parent " + std::to_string(parent) + " must come before its child (a smaller id)",
               t[1].column);
    } else if (id != 0) {
      r.fail("only node 0 may be the root ('-' parent)", t[1].column);
    }
    const NodeData d = read_node_fields(r, t);
    for (std::size_t k = 0; k < names.size(); ++k) {
      attrs[k] = r.number(t[kFixedFields + k], names[k].c_str());
    }
    const NodeId n = tree.add_node(parent, d);
    // add_node derives length/direction only from defaults; restore exact stored values.
    tree.set_length(n, d.length);
    tree.set_direction(n, d.direction);
    for (std::size_t k = 0; k < names.size(); ++k) tree.attribute(names[k])[n] = attrs[k];
    more = r.next(t);
  }
  if (more) r.fail("unexpected content after the last of " + std::to_string(count) + " nodes");
  return tree;
}

}  // namespace fspm
