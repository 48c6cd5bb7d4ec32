#include "fspm/mtg_writer.hpp"

#include <algorithm>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"

namespace fspm {
namespace {

// One line of the code: its column, code and the entity whose features it carries.
struct CodeLine {
  int column = 0;
  std::string code;
  MtgVertex vertex = kNoMtgVertex;
  std::size_t observation = static_cast<std::size_t>(-1);
};

class MtgWriter {
 public:
  explicit MtgWriter(const Mtg& mtg)
      : mtg_(mtg), attached_(mtg.size()), detached_(mtg.size()), observed_(mtg.size()) {
    for (std::size_t k = 0; k < mtg.observations.size(); ++k) {
      observed_[mtg.observations[k].vertex].push_back(k);
    }
  }

  void write(std::ostream& out, const std::string& path, std::uint64_t max_code_bytes) {
    attach_coarse_entities();
    for (MtgVertex v = 1; v < mtg_.size(); ++v) {
      if (mtg_.components(v).empty() && is_start(v)) walk(v);
    }
    check_code_size(path, max_code_bytes);
    write_header(out);
    write_code(out);
  }

 private:
  bool decomposed(MtgVertex v) const { return !mtg_.components(v).empty(); }

  // The component of x that starts its decomposition: one whose parent is not in x.
  MtgVertex first_component(MtgVertex x) const {
    for (MtgVertex c : mtg_.components(x)) {
      if (mtg_.parent(c) == kNoMtgVertex || mtg_.complex(mtg_.parent(c)) != x) return c;
    }
    return mtg_.components(x).front();
  }
  MtgVertex first_leaf(MtgVertex x) const {
    while (decomposed(x)) x = first_component(x);
    return x;
  }
  // The last entity without components along x's first axis (its successors inside x).
  MtgVertex anchor(MtgVertex x) const {
    MtgVertex w = first_leaf(x);
    for (bool more = true; more;) {
      more = false;
      for (MtgVertex c : mtg_.children(w)) {
        if (mtg_.edge(c) == MtgEdge::kSuccessor && mtg_.complex_at_scale(c, mtg_.scale(x)) == x) {
          w = first_leaf(c);
          more = true;
          break;
        }
      }
    }
    return w;
  }

  // The complexes that a leaf entity starts (it is the first component of each), coarsest
  // first, then the leaf itself.
  std::vector<MtgVertex> chain(MtgVertex w) const {
    std::vector<MtgVertex> c{w};
    for (MtgVertex x = w; mtg_.complex(x) != Mtg::root() && mtg_.complex(x) != kNoMtgVertex;) {
      const MtgVertex up = mtg_.complex(x);
      if (first_component(up) != x) break;
      c.push_back(up);
      x = up;
    }
    std::reverse(c.begin(), c.end());
    return c;
  }

  // A leaf that starts a plant, or a series whose top entity has no parent to be reached from.
  bool is_start(MtgVertex w) const {
    const std::vector<MtgVertex> c = chain(w);
    return mtg_.parent(c.front()) == kNoMtgVertex && mtg_.complex(c.front()) == Mtg::root();
  }

  // Entities reached from a decomposed parent other than through the finest scale: coarse
  // entities without components are written after the parent's last leaf on its first axis
  // (the reader climbs from there to their scale); complexes whose first leaf has no parent
  // after the parent itself, its components bracketed in the next column (so the reader is back
  // at the parent's scale when it meets them).
  void attach_coarse_entities() {
    for (MtgVertex y = 1; y < mtg_.size(); ++y) {
      const MtgVertex x = mtg_.parent(y);
      if (x == kNoMtgVertex || !decomposed(x)) continue;
      if (!decomposed(y)) {
        attached_[anchor(x)].push_back(y);
      } else if (mtg_.parent(first_leaf(y)) == kNoMtgVertex) {
        detached_[x].push_back(y);
      }
    }
  }

  // The entities to write after leaf w: its children (or their first leaves), attached ones.
  std::vector<MtgVertex> next_of(MtgVertex w) const {
    std::vector<MtgVertex> next;
    for (MtgVertex c : mtg_.children(w)) next.push_back(decomposed(c) ? first_leaf(c) : c);
    for (MtgVertex y : attached_[w]) next.push_back(y);
    return next;
  }

  struct Item {
    MtgVertex leaf;
    int column;
    bool opening;  // the first line of a new column (no '^')
    char tag;
    std::size_t from = 0;  // the first entity of the leaf's chain still to write
  };

  static char tag_of(MtgEdge e) { return e == MtgEdge::kBranch ? '+' : '<'; }

  void walk(MtgVertex start) {
    std::vector<Item> stack{{start, 0, true, '/'}};
    while (!stack.empty()) {
      const Item it = stack.back();
      stack.pop_back();
      if (!emit(it, stack)) continue;
      std::vector<MtgVertex> branches;
      MtgVertex successor = kNoMtgVertex;
      for (MtgVertex n : next_of(it.leaf)) {
        const MtgVertex top = chain(n).front();
        if (mtg_.edge(top) == MtgEdge::kSuccessor && successor == kNoMtgVertex) {
          successor = n;
        } else {
          branches.push_back(n);
        }
      }
      if (successor != kNoMtgVertex) stack.push_back({successor, it.column, false, '<'});
      for (auto b = branches.rbegin(); b != branches.rend(); ++b) {
        stack.push_back({*b, it.column + 1, true, '+'});
      }
    }
  }

  // Writes the chain of a leaf from it.from; false when a complex with detached followers split
  // it (the rest and the followers are then on the stack).
  bool emit(const Item& it, std::vector<Item>& stack) {
    const std::vector<MtgVertex> c = chain(it.leaf);
    for (std::size_t j = it.from; j < c.size(); ++j) {
      std::string code = (j == it.from && it.opening) ? "" : "^";
      code += j == it.from ? it.tag : '/';
      code += mtg_.label(c[j]);
      lines_.push_back({it.column, std::move(code), c[j]});
      for (std::size_t k : observed_[c[j]]) lines_.push_back({it.column, "*", c[j], k});
      columns_ = std::max(columns_, it.column + 1);
      if (j + 1 < c.size() && !detached_[c[j]].empty()) {
        const auto& d = detached_[c[j]];
        for (auto y = d.rbegin(); y != d.rend(); ++y) {
          stack.push_back({first_leaf(*y), it.column, false, tag_of(mtg_.edge(*y))});
        }
        stack.push_back({it.leaf, it.column + 1, true, '/', j + 1});
        return false;
      }
    }
    return true;
  }

  void write_header(std::ostream& out) const {
    out << "CODE:\t" << mtg_.code_form << "\n\nCLASSES:\nSYMBOL\tSCALE\tDECOMPOSITION\tINDEXATION"
        << "\tDEFINITION\n";
    for (const MtgClass& c : mtg_.classes) {
      out << c.symbol << '\t' << c.scale << '\t' << c.decomposition << '\t' << c.indexation << '\t'
          << c.definition << '\n';
    }
    out << "\nDESCRIPTION:\nLEFT\tRIGHT\tRELTYPE\tMAX\n";
    for (const MtgRelationRule& r : mtg_.description) {
      out << r.left << '\t';
      for (std::size_t k = 0; k < r.right.size(); ++k) out << (k ? "," : "") << r.right[k];
      out << '\t' << r.relation << '\t' << r.max << '\n';
    }
    out << "\nFEATURES:\nNAME\tTYPE\n";
    for (const MtgFeature& f : mtg_.features()) {
      out << f.name << '\t' << mtg_feature_type_name(f.type);
      if (!f.argument.empty()) out << '\t' << f.argument;
      out << '\n';
    }
  }

  void check_code_size(const std::string& path, std::uint64_t max_bytes) const {
    const bool features = !mtg_.features().empty();
    std::uint64_t bytes = 0;
    for (const CodeLine& l : lines_) {
      bytes += l.code.size() + 1 +
               static_cast<std::uint64_t>(features ? std::max(columns_, 1) : l.column);
    }
    check_mtg_code_size(bytes, columns_, path, max_bytes);
  }

  void write_code(std::ostream& out) const {
    const int columns = std::max(columns_, 1);
    out << "\nMTG:\nENTITY-CODE" << std::string(static_cast<std::size_t>(columns), '\t');
    for (std::size_t f = 0; f < mtg_.features().size(); ++f) {
      out << (f ? "\t" : "") << mtg_.features()[f].name;
    }
    out << '\n';
    std::string line;
    for (const CodeLine& l : lines_) {
      line.assign(static_cast<std::size_t>(l.column), '\t');
      line += l.code;
      line.append(static_cast<std::size_t>(columns - l.column), '\t');
      for (std::size_t f = 0; f < mtg_.features().size(); ++f) {
        if (f) line += '\t';
        if (l.observation != static_cast<std::size_t>(-1)) {
          line += mtg_.observations[l.observation].values[f];
        } else {
          line += mtg_.feature_text(l.vertex, f);
        }
      }
      while (!line.empty() && line.back() == '\t') line.pop_back();
      line += '\n';
      out << line;
    }
  }

  const Mtg& mtg_;
  std::vector<std::vector<MtgVertex>> attached_, detached_;
  std::vector<std::vector<std::size_t>> observed_;
  std::vector<CodeLine> lines_;
  int columns_ = 0;
};

}  // namespace

void check_mtg_code_size(std::uint64_t bytes, int columns, const std::string& path,
                         std::uint64_t max_bytes) {
  if (bytes <= max_bytes) return;
  throw ValueError("the MTG code would take about " + memory_text(static_cast<double>(bytes)) +
                       ", expected at most " + memory_text(static_cast<double>(max_bytes)) +
                       ": its branching nests " + std::to_string(columns) +
                       " levels deep and MTG indents every level by a tab; write the tree as "
                       ".tree or .treeb instead",
                   path);
}

void write_mtg(const Mtg& mtg, std::ostream& out, const std::string& path,
               std::uint64_t max_code_bytes) {
  MtgWriter(mtg).write(out, path, max_code_bytes);
}

}  // namespace fspm
