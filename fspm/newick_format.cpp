#include "fspm/newick_format.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include "fspm/error.hpp"
#include "fspm/nesting_depth.hpp"
#include "fspm/number_text.hpp"

namespace fspm {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

class Scanner {
 public:
  Scanner(std::string_view text, const std::string& source) : text_(text), source_(source) {}

  // Blanks and Newick comments in square brackets ("[&R]", "[bootstrap 95]").
  void skip_space() {
    for (;;) {
      const char c = peek();
      if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
        advance();
      } else if (c == '[') {
        skip_comment();
      } else {
        return;
      }
    }
  }
  bool at_end() const { return pos_ >= text_.size(); }
  char peek() const { return at_end() ? '\0' : text_[pos_]; }
  void advance() {
    if (text_[pos_] == '\n') {
      ++line_;
      column_ = 1;
    } else {
      ++column_;
    }
    ++pos_;
  }

  // A label or length token: everything up to a delimiter. Returns {} when empty.
  std::string_view word() {
    const std::size_t b = pos_;
    while (!at_end()) {
      const char c = text_[pos_];
      if (ends_word(c)) break;
      advance();
    }
    return text_.substr(b, pos_ - b);
  }

  // A quoted label at the current "'": its text, with "''" read as one quote.
  std::string quoted() {
    const int open_line = line_;
    const int open_column = column_;
    advance();
    std::string out;
    for (;;) {
      if (at_end()) {
        fail("unterminated quoted label: the quote opened here is never closed", open_line,
             open_column);
      }
      const char c = text_[pos_];
      advance();
      if (c != '\'') {
        out += c;
      } else if (peek() == '\'') {
        out += '\'';
        advance();
      } else {
        return out;
      }
    }
  }

  [[noreturn]] void fail(const std::string& what, int line, int column) const {
    throw ParseError(what, source_, line, column);
  }
  [[noreturn]] void fail(const std::string& what) const { fail(what, line_, column_); }

  std::string found() const {
    return at_end() ? std::string("the end of the input") : "'" + std::string(1, peek()) + "'";
  }

  int line() const { return line_; }
  int column() const { return column_; }

  // The characters an unquoted label or length cannot contain.
  static bool ends_word(char c) {
    return c == '(' || c == ')' || c == ',' || c == ':' || c == ';' || c == '[' || c == '\'' ||
           c == ' ' || c == '\t' || c == '\n' || c == '\r';
  }

 private:
  void skip_comment() {
    const int open_line = line_;
    const int open_column = column_;
    while (!at_end() && peek() != ']') advance();
    if (at_end()) {
      fail("unterminated comment: the '[' opened here is never closed", open_line, open_column);
    }
    advance();
  }

  std::string_view text_;
  const std::string& source_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int column_ = 1;
};

// An unquoted name as Newick writes it: '_' stands for a blank.
std::string unquoted_name(std::string_view word) {
  std::string name(word);
  for (char& c : name) {
    if (c == '_') c = ' ';
  }
  return name;
}

// Reads the optional label and `:length` after a node and stores them: an unquoted number in
// the attribute "label", any other label (a taxon name, or anything quoted) in `names`.
void read_label_and_length(Scanner& s, TreeGraph& tree, NodeId n, std::vector<std::string>& names) {
  s.skip_space();
  names.resize(tree.size());
  if (s.peek() == '\'') {
    names[n] = s.quoted();
  } else if (const std::string_view label = s.word(); !label.empty()) {
    if (const auto v = parse_number(label)) {
      tree.attribute(kNewickLabel)[n] = *v;
    } else {
      names[n] = unquoted_name(label);
    }
  }
  s.skip_space();
  if (s.peek() == ':') {
    s.advance();
    s.skip_space();
    const int lline = s.line();
    const int lcol = s.column();
    const std::string_view len = s.word();
    const auto v = parse_number(len);
    if (!v) {
      s.fail("expected a branch length after ':', found " +
                 (len.empty() ? s.found() : "'" + std::string(len) + "'"),
             lline, lcol);
    }
    tree.attribute(kNewickBranchLength)[n] = *v;
  }
}

// Writes a name so that it reads back as the same name: bare when it is a plain word that is not
// a number, else quoted with its quotes doubled.
void append_name(std::string& out, const std::string& name) {
  bool bare = !parse_number(name).has_value();
  for (const char c : name) {
    if (c == '_' || c == ']' || Scanner::ends_word(c)) bare = false;
  }
  if (bare) {
    out += name;
    return;
  }
  out += '\'';
  for (const char c : name) {
    out += c;
    if (c == '\'') out += '\'';
  }
  out += '\'';
}

}  // namespace

NamedTree parse_newick_named(std::string_view text, const std::string& source) {
  Scanner s(text, source);
  NamedTree named;
  TreeGraph& tree = named.tree;
  std::vector<std::string>& names = named.names;
  tree.add_attribute(std::string(kNewickLabel), kNaN);
  tree.add_attribute(std::string(kNewickBranchLength), kNaN);
  std::vector<NodeId> open;  // internal nodes whose ')' has not been read yet
  std::vector<int> open_line, open_col;
  auto new_node = [&]() {
    NodeData d;
    const NodeId parent = open.empty() ? kNoNode : open.back();
    if (parent != kNoNode) d.order = tree.order(parent);
    // Later siblings branch off: the first child continues its parent's axis.
    if (parent != kNoNode && !tree.is_tip(parent)) ++d.order;
    return tree.add_node(parent, d);
  };

  s.skip_space();
  if (s.at_end()) s.fail("expected a Newick tree, found an empty input");
  for (;;) {
    // Expect a subtree.
    s.skip_space();
    if (s.peek() == '(') {
      if (open.size() >= static_cast<std::size_t>(kMaxTreeDepth)) {
        s.fail(nesting_too_deep(kMaxTreeDepth, "parentheses"));
      }
      open_line.push_back(s.line());
      open_col.push_back(s.column());
      s.advance();
      open.push_back(new_node());
      continue;
    }
    // A leaf; its label may be empty, as in "(,)".
    read_label_and_length(s, tree, new_node(), names);
    // After a subtree: ',' for a sibling, ')' to close, ';' at the end.
    for (;;) {
      s.skip_space();
      const char c = s.peek();
      if (c == ',' && !open.empty()) {
        s.advance();
        break;
      }
      if (c == ')' && !open.empty()) {
        s.advance();
        const NodeId n = open.back();
        open.pop_back();
        open_line.pop_back();
        open_col.pop_back();
        read_label_and_length(s, tree, n, names);
        continue;
      }
      if (open.empty()) {
        if (c != ';') s.fail("expected ';' at the end of the tree, found " + s.found());
        s.advance();
        s.skip_space();
        if (!s.at_end()) s.fail("expected the end of the input after ';', found " + s.found());
        names.resize(tree.size());
        return named;
      }
      if (s.at_end()) {
        s.fail("unbalanced parentheses: the '(' opened here is never closed", open_line.back(),
               open_col.back());
      }
      s.fail("expected ',' or ')' after a subtree, found " + s.found());
    }
  }
}

TreeGraph parse_newick(std::string_view text, const std::string& source) {
  return parse_newick_named(text, source).tree;
}

std::string to_newick(const TreeGraph& tree, std::string_view label_attribute) {
  return to_newick_named(tree, {}, label_attribute);
}

std::string to_newick_named(const TreeGraph& tree, std::span<const std::string> names,
                            std::string_view label_attribute) {
  if (!names.empty() && names.size() != tree.size()) {
    throw ValueError("to_newick: " + std::to_string(names.size()) + " names for a tree of " +
                     std::to_string(tree.size()) + " nodes; expected one per node");
  }
  std::string out;
  if (tree.empty()) return ";";
  const bool has_label = tree.has_attribute(label_attribute);
  const bool has_length = tree.has_attribute(kNewickBranchLength);
  const auto labels = has_label ? tree.attribute(label_attribute) : std::span<const double>{};
  const auto lengths = has_length ? tree.attribute(kNewickBranchLength) : std::span<const double>{};
  auto suffix = [&](NodeId n) {
    if (!names.empty() && !names[n].empty()) {
      append_name(out, names[n]);
    } else if (has_label && !std::isnan(labels[n])) {
      append_number(out, labels[n]);
    }
    if (has_length && !std::isnan(lengths[n])) {
      out += ':';
      append_number(out, lengths[n]);
    }
  };
  // (node, next child) stack: '(' on entry to an internal node, ',' between children,
  // ')' and the label on exit.
  std::vector<std::pair<NodeId, NodeId>> stack{{0, tree.first_child(0)}};
  if (!tree.is_tip(0)) out += '(';
  while (!stack.empty()) {
    auto& [n, next] = stack.back();
    if (next == kNoNode) {
      if (!tree.is_tip(n)) out += ')';
      suffix(n);
      stack.pop_back();
      continue;
    }
    const NodeId c = next;
    if (c != tree.first_child(n)) out += ',';
    next = tree.next_sibling(c);
    stack.emplace_back(c, tree.first_child(c));
    if (!tree.is_tip(c)) out += '(';
  }
  out += ';';
  return out;
}

}  // namespace fspm
