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

  void skip_space() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' ||
                                   text_[pos_] == '\n' || text_[pos_] == '\r')) {
      advance();
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
      if (c == '(' || c == ')' || c == ',' || c == ':' || c == ';' || c == ' ' || c == '\t' ||
          c == '\n' || c == '\r') {
        break;
      }
      advance();
    }
    return text_.substr(b, pos_ - b);
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

 private:
  std::string_view text_;
  const std::string& source_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int column_ = 1;
};

// Reads the optional `label` and `:length` after a node and stores them.
void read_label_and_length(Scanner& s, TreeGraph& tree, NodeId n) {
  s.skip_space();
  const int line = s.line();
  const int col = s.column();
  const std::string_view label = s.word();
  if (!label.empty()) {
    const auto v = parse_number(label);
    if (!v) {
      s.fail("expected a numeric node label, found '" + std::string(label) + "'", line, col);
    }
    tree.attribute(kNewickLabel)[n] = *v;
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

}  // namespace

TreeGraph parse_newick(std::string_view text, const std::string& source) {
  Scanner s(text, source);
  TreeGraph tree;
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
    read_label_and_length(s, tree, new_node());
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
        read_label_and_length(s, tree, n);
        continue;
      }
      if (open.empty()) {
        if (c != ';') s.fail("expected ';' at the end of the tree, found " + s.found());
        s.advance();
        s.skip_space();
        if (!s.at_end()) s.fail("expected the end of the input after ';', found " + s.found());
        return tree;
      }
      if (s.at_end()) {
        s.fail("unbalanced parentheses: the '(' opened here is never closed", open_line.back(),
               open_col.back());
      }
      s.fail("expected ',' or ')' after a subtree, found " + s.found());
    }
  }
}

std::string to_newick(const TreeGraph& tree, std::string_view label_attribute) {
  std::string out;
  if (tree.empty()) return ";";
  const bool has_label = tree.has_attribute(label_attribute);
  const bool has_length = tree.has_attribute(kNewickBranchLength);
  const auto labels = has_label ? tree.attribute(label_attribute) : std::span<const double>{};
  const auto lengths = has_length ? tree.attribute(kNewickBranchLength) : std::span<const double>{};
  auto suffix = [&](NodeId n) {
    if (has_label && !std::isnan(labels[n])) append_number(out, labels[n]);
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
