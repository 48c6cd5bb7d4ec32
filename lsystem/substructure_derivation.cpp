#include "lsystem/substructure_derivation.hpp"

#include <algorithm>
#include <cstring>
#include <deque>
#include <limits>
#include <unordered_map>

#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"
#include "fspm/saturating.hpp"

namespace fspm::lsystem {
namespace {

std::string at_line(const Production& p) {
  return " (line " + std::to_string(p.position.line) + ")";
}

bool pure(const std::vector<Expression>& block) {
  for (const Expression& e : block) {
    if (!e.is_pure()) return false;
  }
  return true;
}

// Why productions of `group` ("production" or "decomposition production") depend on where or
// when their module stands.
std::optional<std::string> group_obstacle(const ProductionGroup& group, const char* what,
                                          bool stochastic_allowed = false) {
  for (const Production& p : group.productions) {
    if (!p.context_free()) return std::string("a context-sensitive ") + what + at_line(p);
    if (!p.probability.empty() && !stochastic_allowed) {
      return std::string("a stochastic ") + what + at_line(p);
    }
    bool is_pure = p.condition.is_pure() && pure(p.pre_block) && pure(p.post_block);
    for (const ModuleTemplate& t : p.successor) {
      is_pure = is_pure && pure(t.arguments);
      if (t.symbol == kCut) return std::string("a cut % in a ") + what + at_line(p);
    }
    if (!is_pure) {
      return std::string("ran(), nran() or an assignment to a global variable in a ") + what +
             at_line(p);
    }
  }
  return std::nullopt;
}

// Derivation of one L-system into the graph: memoized substructures, built depth first with an
// explicit stack (derivation lengths may exceed any call stack).
class Builder {
 public:
  Builder(const LSystem& system, const DeriveOptions& options, int variants)
      : file_(system.file),
        derivation_(system, options),
        budget_(options.module_budget),
        variants_(static_cast<std::uint32_t>(std::max(variants, 0))) {}

  SubstructureGraph run() {
    graph_.steps = derivation_.target_steps();
    const ModuleString& axiom = derivation_.string();
    for (std::size_t i = 0; i < axiom.size(); ++i) {
      graph_.axiom.push_back(resolve_to_end(axiom.symbol(i), axiom.parameters(i)));
    }
    return std::move(graph_);
  }

 private:
  struct Frame {
    std::string key;
    SymbolId symbol = 0;
    std::vector<double> parameters;
    int remaining = 0;
    ModuleString successor;  // the module after one step (and decomposition)
    std::size_t next = 0;    // next module of `successor` to resolve
    std::size_t pending_mark = 0;
  };

  // (symbol, remaining, parameters), and with variants the variant's number.
  std::string key_of(SymbolId symbol, std::span<const double> parameters, int remaining,
                     std::uint32_t variant = 0) const {
    const std::size_t variant_bytes = variants_ > 0 ? sizeof variant : 0;
    std::string key(sizeof symbol + sizeof remaining + parameters.size_bytes() + variant_bytes,
                    '\0');
    char* out = key.data();
    std::memcpy(out, &symbol, sizeof symbol);
    std::memcpy(out + sizeof symbol, &remaining, sizeof remaining);
    if (!parameters.empty()) {
      std::memcpy(out + sizeof symbol + sizeof remaining, parameters.data(),
                  parameters.size_bytes());
    }
    if (variant_bytes > 0) {
      std::memcpy(out + sizeof symbol + sizeof remaining + parameters.size_bytes(), &variant,
                  sizeof variant);
    }
    return key;
  }

  // Which variant an occurrence takes (0 without variants).
  std::uint32_t draw_variant() {
    if (variants_ <= 1) return 0;
    return static_cast<std::uint32_t>(derivation_.random()() % variants_);
  }

  // Heap bytes of a string's characters, 0 while they fit in the string itself (libstdc++ keeps
  // 15 characters inline), else its capacity and the allocator's header.
  static double string_heap_bytes(const std::string& s) {
    return s.capacity() > 15 ? static_cast<double>(s.capacity()) + 32.0 : 0.0;
  }

  // What the derivation holds, estimated from its containers: the graph, the memo (a hash node,
  // a bucket and a key per entry, keys as long as the newest frame's) and the frames of the
  // depth-first walk, one per step on the way down, each about as large as the newest (its key,
  // parameters and successor string).
  double held_bytes() const {
    double key = 0.0;
    double frame = sizeof(Frame);
    if (depth_ > 0) {
      const Frame& f = frames_[depth_ - 1];
      key = string_heap_bytes(f.key);
      frame += key + static_cast<double>(f.parameters.capacity() * sizeof(double)) +
               static_cast<double>(f.successor.memory_bytes()) + 3 * 32.0;
    }
    constexpr double kMemoEntry = sizeof(std::pair<const std::string, std::uint32_t>) + 40.0;
    return static_cast<double>(graph_.memory_bytes()) +
           static_cast<double>(memo_.size()) * (kMemoEntry + key) +
           static_cast<double>(frames_.size()) * frame +
           static_cast<double>(pending_.capacity() * sizeof(std::uint32_t));
  }

  // Every kCheckEvery new substructures or frames, the memory held against the limit, so that a
  // derivation a billion steps deep stops with a clean error long before it takes the machine.
  void check_growth() {
    constexpr std::size_t kCheckEvery = 1024;
    if (++growth_ % kCheckEvery != 0) return;
    check_memory(held_bytes(),
                 "the substructure derivation (" + std::to_string(graph_.nodes.size()) +
                     " substructures, " + std::to_string(depth_) + " steps deep)",
                 file_);
  }

  std::uint32_t add_node(SymbolId symbol, std::span<const double> parameters, int remaining,
                         std::span<const std::uint32_t> children) {
    check_growth();
    if (graph_.nodes.size() >= budget_) {
      throw ValueError("the substructure graph grows past the budget of " +
                       std::to_string(budget_) +
                       " nodes (real-valued parameters that never repeat? fewer steps or a "
                       "larger budget)");
    }
    Substructure s;
    s.symbol = symbol;
    s.parameter_begin = static_cast<std::uint32_t>(graph_.parameters.size());
    s.parameter_count = static_cast<std::uint32_t>(parameters.size());
    s.child_begin = static_cast<std::uint32_t>(graph_.children.size());
    s.child_count = static_cast<std::uint32_t>(children.size());
    s.remaining = remaining;
    graph_.parameters.insert(graph_.parameters.end(), parameters.begin(), parameters.end());
    graph_.children.insert(graph_.children.end(), children.begin(), children.end());
    graph_.parametric = graph_.parametric || !parameters.empty();
    graph_.nodes.push_back(s);
    return static_cast<std::uint32_t>(graph_.nodes.size() - 1);
  }

  // The substructure of the module after `remaining` steps when it is known or a leaf; otherwise
  // pushes a frame that will build it and returns nothing.
  std::optional<std::uint32_t> resolve(SymbolId symbol, std::span<const double> parameters,
                                       int remaining) {
    std::string key = key_of(symbol, parameters, remaining, remaining > 0 ? draw_variant() : 0);
    if (const auto it = memo_.find(key); it != memo_.end()) return it->second;
    if (remaining > 0) {
      Frame& f = push_frame();
      derivation_.rewrite_module(symbol, parameters, f.successor);
      const bool unchanged = f.successor.size() == 1 && f.successor.symbol(0) == symbol &&
                             same_bits(f.successor.parameters(0), parameters);
      if (!unchanged) {
        f.key = std::move(key);
        f.symbol = symbol;
        f.parameters.assign(parameters.begin(), parameters.end());
        f.remaining = remaining;
        f.next = 0;
        f.pending_mark = pending_.size();
        return std::nullopt;
      }
      // A module no production changes stays itself for ever: the leaf of 0 remaining steps.
      --depth_;
      const std::uint32_t id = leaf(symbol, parameters);
      memo_.emplace(std::move(key), id);
      return id;
    }
    return leaf(symbol, parameters);
  }

  std::uint32_t leaf(SymbolId symbol, std::span<const double> parameters) {
    std::string key = key_of(symbol, parameters, 0);
    if (const auto it = memo_.find(key); it != memo_.end()) return it->second;
    const std::uint32_t id = add_node(symbol, parameters, 0, {});
    memo_.emplace(std::move(key), id);
    return id;
  }

  static bool same_bits(std::span<const double> a, std::span<const double> b) {
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size_bytes()) == 0);
  }

  Frame& push_frame() {
    if (frames_.size() <= depth_) {
      check_growth();
      frames_.emplace_back();
    }
    return frames_[depth_++];
  }

  std::uint32_t resolve_to_end(SymbolId symbol, std::span<const double> parameters) {
    if (const auto id = resolve(symbol, parameters, graph_.steps)) return *id;
    for (;;) {
      Frame& f = frames_[depth_ - 1];
      if (f.next < f.successor.size()) {
        const auto child =
            resolve(f.successor.symbol(f.next), f.successor.parameters(f.next), f.remaining - 1);
        if (child) {  // otherwise a frame for it was pushed above this one
          pending_.push_back(*child);
          ++f.next;
        }
        continue;
      }
      const std::span<const std::uint32_t> children(pending_.data() + f.pending_mark,
                                                    pending_.size() - f.pending_mark);
      const std::uint32_t id = add_node(f.symbol, f.parameters, f.remaining, children);
      pending_.resize(f.pending_mark);
      memo_.emplace(std::move(f.key), id);
      --depth_;
      if (depth_ == 0) return id;
      pending_.push_back(id);
      ++frames_[depth_ - 1].next;
    }
  }

  std::string file_;  // the grammar's, for messages
  Derivation derivation_;
  std::size_t budget_;
  std::uint32_t variants_;  // 0: deterministic
  SubstructureGraph graph_;
  std::unordered_map<std::string, std::uint32_t> memo_;
  // frames_[0, depth_) are live; the rest keep their buffers. A deque: growing it keeps the
  // live frames where they are.
  std::deque<Frame> frames_;
  std::size_t depth_ = 0;
  std::vector<std::uint32_t> pending_;  // children resolved so far, of every live frame
  std::size_t growth_ = 0;              // substructures and frames added, for check_growth
};

}  // namespace

std::size_t SubstructureGraph::memory_bytes() const {
  return nodes.capacity() * sizeof(Substructure) + children.capacity() * sizeof(std::uint32_t) +
         parameters.capacity() * sizeof(double) + axiom.capacity() * sizeof(std::uint32_t);
}

std::optional<std::string> factorization_obstacle(const LSystem& system, bool variants) {
  if (auto why = group_obstacle(system.productions, "production", variants)) return why;
  if (auto why = group_obstacle(system.decomposition, "decomposition production", variants)) {
    return why;
  }
  if (!system.start_each_block.empty() || !system.end_each_block.empty()) {
    return std::string("startEach: or endEach: blocks, which run between steps");
  }
  for (const ModuleTemplate& t : system.axiom) {
    if (t.symbol == kCut) return std::string("a cut % in the axiom");
  }
  for (const char* query : {"?P", "?H", "?U", "?L", "?E"}) {
    if (system.symbols.find(query) >= 0) {
      return std::string("environment or turtle queries (") + query + ")";
    }
  }
  return std::nullopt;
}

std::optional<std::string> homomorphism_obstacle(const LSystem& system) {
  return group_obstacle(system.homomorphism, "homomorphism production");
}

SubstructureGraph derive_substructures(const LSystem& system, const DeriveOptions& options,
                                       int variants) {
  if (const auto why = factorization_obstacle(system, variants > 0)) {
    throw ValueError("this L-system cannot be derived into substructures: it has " + *why,
                     system.file);
  }
  return Builder(system, options, variants).run();
}

SubstructureCounts count_modules(const SubstructureGraph& graph, std::size_t symbol_count) {
  // How many times each substructure occurs in the string: parents come after their children,
  // so one backward pass hands every count down.
  std::vector<std::uint64_t> occurrences(graph.nodes.size(), 0);
  for (const std::uint32_t a : graph.axiom) occurrences[a] = add_saturating(occurrences[a], 1);
  SubstructureCounts counts;
  counts.per_symbol.assign(symbol_count, 0);
  for (std::size_t n = graph.nodes.size(); n-- > 0;) {
    const Substructure& s = graph.nodes[n];
    const std::uint64_t times = occurrences[n];
    if (times == 0) continue;
    for (std::uint32_t c = 0; c < s.child_count; ++c) {
      const std::uint32_t child = graph.children[s.child_begin + c];
      occurrences[child] = add_saturating(occurrences[child], times);
    }
    if (!s.leaf()) continue;
    counts.modules = add_saturating(counts.modules, times);
    if (s.symbol < symbol_count) {
      counts.per_symbol[s.symbol] = add_saturating(counts.per_symbol[s.symbol], times);
    }
    const std::uint64_t bytes = graph.parametric ? 2 + 4 + 8 * s.parameter_count : 2;
    counts.explicit_bytes =
        add_saturating(counts.explicit_bytes, multiply_saturating(times, bytes));
  }
  counts.saturated = counts.modules == kSaturated || counts.explicit_bytes == kSaturated;
  return counts;
}

ModuleString expand(const SubstructureGraph& graph, std::size_t module_budget) {
  const SubstructureCounts counts = count_modules(graph, 0);
  if (counts.modules > module_budget) {
    throw ValueError("the expanded string would hold " + std::to_string(counts.modules) +
                     " modules, past the budget of " + std::to_string(module_budget));
  }
  ModuleString out;
  if (graph.parametric) out.make_parametric();
  out.reserve(static_cast<std::size_t>(counts.modules));
  struct Visit {
    std::uint32_t node;
    std::uint32_t next;
  };
  std::vector<Visit> stack;
  for (const std::uint32_t a : graph.axiom) {
    stack.push_back({a, 0});
    while (!stack.empty()) {
      Visit& v = stack.back();
      const Substructure& s = graph.nodes[v.node];
      if (s.leaf()) {
        out.push_back(s.symbol, std::span<const double>(graph.parameters.data() + s.parameter_begin,
                                                        s.parameter_count));
        stack.pop_back();
      } else if (v.next < s.child_count) {
        const std::uint32_t child = graph.children[s.child_begin + v.next++];
        stack.push_back({child, 0});
      } else {
        stack.pop_back();
      }
    }
  }
  return out;
}

}  // namespace fspm::lsystem
