#include "lsystem/derivation.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <string>

#include "fspm/error.hpp"
#include "fspm/memory_account.hpp"
#include "fspm/memory_budget.hpp"
#include "fspm/number_text.hpp"
#include "lsystem/query_pass.hpp"
#include "lsystem/turtle.hpp"

namespace fspm::lsystem {
namespace {

bool template_parametric(const std::vector<ModuleTemplate>& ts) {
  for (const ModuleTemplate& t : ts) {
    if (!t.arguments.empty()) return true;
  }
  return false;
}

bool contains_symbol(const std::vector<ModuleTemplate>& ts, SymbolId s) {
  for (const ModuleTemplate& t : ts) {
    if (t.symbol == s) return true;
  }
  return false;
}

}  // namespace

Derivation::Derivation(const LSystem& system, const DeriveOptions& options)
    : sys_(system), options_(options) {
  rng_.seed(options.seed.value_or(system.seed.value_or(kDefaultSeed)));
  globals_ = system.globals.values;
  locals_.assign(static_cast<std::size_t>(system.local_frame_size()) + 1, 0.0);
  target_steps_ = options.steps.value_or(system.derivation_length);
  if (target_steps_ < 0) throw ValueError("the number of derivation steps must be >= 0");

  // Which features does this grammar use? Decides the string layout and the fast path.
  parametric_ = template_parametric(system.axiom);
  has_cut_ = contains_symbol(system.axiom, kCut);
  for (const ProductionGroup* g : {&system.productions, &system.decomposition}) {
    for (const Production& p : g->productions) {
      parametric_ = parametric_ || template_parametric(p.successor);
      has_cut_ = has_cut_ || contains_symbol(p.successor, kCut);
    }
  }
  for (const char* q : {"?P", "?H", "?U", "?L", "?E"}) {
    if (system.symbols.find(q) >= 0) has_queries_ = true;
  }
  fast_ = !parametric_ && !system.productions.productions.empty();
  for (const Production& p : system.productions.productions) {
    if (!p.context_free() || !p.condition.empty() || !p.probability.empty() ||
        !p.pre_block.empty() || !p.post_block.empty() || !p.predecessor.slots.empty()) {
      fast_ = false;
    }
  }
  if (fast_) {
    const std::size_t n = system.symbols.size();
    fast_begin_.assign(n, 0);
    fast_length_.assign(n, 1);
    for (std::size_t s = 0; s < n; ++s) {
      const auto& list = system.productions.productions_for[s];
      fast_begin_[s] = static_cast<std::uint32_t>(fast_data_.size());
      if (list.empty()) {
        fast_data_.push_back(static_cast<SymbolId>(s));
        continue;
      }
      const Production& p = system.productions.productions[list.front()];
      fast_length_[s] = static_cast<std::uint32_t>(p.successor.size());
      for (const ModuleTemplate& t : p.successor) fast_data_.push_back(t.symbol);
    }
  }

  run_block(system.define_block);
  run_block(system.start_block);
  if (parametric_) current_.make_parametric();
  EvalState state{locals_.data(), globals_.data(), &rng_};
  for (const ModuleTemplate& t : system.axiom) {
    args_.clear();
    for (const Expression& e : t.arguments) args_.push_back(e.evaluate(state));
    current_.push_back(t.symbol, args_);
  }
  check_budget(current_.size(), true);
  apply_group_repeatedly(system.decomposition, current_);
  if (has_cut_) apply_cut(current_);
  if (has_queries_) update_queries();
}

Derivation::~Derivation() = default;

void Derivation::run() {
  while (steps_done_ < target_steps_) step();
  run_block(sys_.end_block);
}

void Derivation::step() {
  run_block(sys_.start_each_block);
  if (fast_) {
    rewrite_fast(current_, next_);
  } else {
    rewrite(sys_.productions, current_, next_);
  }
  current_.swap(next_);
  apply_group_repeatedly(sys_.decomposition, current_);
  if (has_cut_) apply_cut(current_);
  ++steps_done_;
  if (has_queries_) update_queries();
  run_block(sys_.end_each_block);
}

void Derivation::rewrite_module(SymbolId symbol, std::span<const double> parameters,
                                ModuleString& out) {
  module_.clear();
  if (parametric_) module_.make_parametric();
  module_.push_back(symbol, parameters);
  if (fast_) {
    rewrite_fast(module_, out);
  } else {
    rewrite(sys_.productions, module_, out);
  }
  apply_group_repeatedly(sys_.decomposition, out);
}

void Derivation::interpret_module(SymbolId symbol, std::span<const double> parameters,
                                  ModuleString& out) {
  out.clear();
  if (parametric_) out.make_parametric();
  out.push_back(symbol, parameters);
  apply_group_repeatedly(sys_.homomorphism, out);
}

void Derivation::check_budget(std::size_t size, bool reserve) const {
  if (size > options_.module_budget) {
    throw ValueError("the string grows past the module budget of " +
                         std::to_string(options_.module_budget) + " modules at derivation step " +
                         std::to_string(steps_done_ + 1) +
                         " (an exploding grammar? fewer steps or a larger budget)",
                     sys_.file);
  }
  if (size > memory_cap_ || reserve) {
    check_memory(input_bytes_ + static_cast<double>(size) * bytes_per_module_,
                 "the L-system string at derivation step " + std::to_string(steps_done_ + 1),
                 sys_.file);
  }
}

void Derivation::plan_memory(const ModuleString& in) {
  // Bytes per module of the layout in module_string.hpp: a symbol id, and for parametric
  // strings an offset and the input's mean number of parameters (at least one).
  bytes_per_module_ = sizeof(SymbolId);
  if (parametric_) {
    const double mean =
        in.empty() ? 1.0 : static_cast<double>(in.pool().size()) / static_cast<double>(in.size());
    bytes_per_module_ += sizeof(std::uint32_t) + sizeof(double) * std::max(1.0, mean);
  }
  input_bytes_ = static_cast<double>(in.memory_bytes());
  const double room = static_cast<double>(memory_room_bytes()) - input_bytes_;
  memory_cap_ = room <= 0.0 ? 0 : static_cast<std::size_t>(room / bytes_per_module_);
}

void Derivation::run_block(const std::vector<Expression>& block) {
  if (block.empty()) return;
  EvalState state{locals_.data(), globals_.data(), &rng_};
  for (const Expression& e : block) e.evaluate(state);
}

bool Derivation::rewrite_fast(const ModuleString& in, ModuleString& out) {
  const std::vector<SymbolId>& src = in.symbols();
  const std::uint32_t* length = fast_length_.data();
  std::size_t total = 0;
  for (SymbolId s : src) total += length[s];
  plan_memory(in);
  check_budget(total, true);
  std::vector<SymbolId>& dst = out.symbols();
  dst.resize(total);
  SymbolId* o = dst.data();
  const std::uint32_t* begin = fast_begin_.data();
  const SymbolId* data = fast_data_.data();
  for (SymbolId s : src) {
    const std::uint32_t n = length[s];
    const SymbolId* from = data + begin[s];
    if (n == 1) {
      *o++ = *from;
    } else if (n != 0) {
      std::memcpy(o, from, n * sizeof(SymbolId));
      o += n;
    }
  }
  return true;
}

void Derivation::bind(const ModulePattern& pattern, const ModuleString& in, std::size_t i) {
  const auto params = in.parameters(i);
  for (std::size_t k = 0; k < pattern.slots.size(); ++k) locals_[pattern.slots[k]] = params[k];
}

bool Derivation::match_right(const std::vector<ModulePattern>& pattern, const ModuleString& in,
                             std::size_t i) {
  const std::size_t n = in.size();
  const auto& sym = in.symbols();
  const auto& ignored = sys_.ignored;
  std::size_t j = i + 1;
  constexpr std::size_t kUnclosed = static_cast<std::size_t>(-1);
  // from: index after '['; returns the index after the matching ']' (kUnclosed if none).
  auto skip_branch = [&](std::size_t from) {
    int depth = 0;
    for (std::size_t k = from; k < n; ++k) {
      if (sym[k] == kOpenBranch) {
        ++depth;
      } else if (sym[k] == kCloseBranch) {
        if (depth == 0) return k + 1;
        --depth;
      }
    }
    return kUnclosed;
  };
  for (const ModulePattern& m : pattern) {
    if (m.symbol == kOpenBranch) {
      while (j < n && ignored[sym[j]]) ++j;
      if (j >= n || sym[j] != kOpenBranch) return false;
      ++j;
      continue;
    }
    if (m.symbol == kCloseBranch) {
      // Skip the rest of the branch the pattern is in.
      const std::size_t after = skip_branch(j);
      if (after == kUnclosed) return false;
      j = after;
      continue;
    }
    for (;;) {
      while (j < n && ignored[sym[j]]) ++j;
      if (j < n && sym[j] == kOpenBranch) {
        j = skip_branch(j + 1);
        if (j == kUnclosed) return false;
        continue;
      }
      break;
    }
    if (j >= n || sym[j] != m.symbol || in.arity(j) != m.slots.size()) return false;
    bind(m, in, j);
    ++j;
  }
  return true;
}

bool Derivation::match_left(const std::vector<ModulePattern>& pattern, const ModuleString& in,
                            std::size_t i) {
  const auto& sym = in.symbols();
  const auto& ignored = sys_.ignored;
  std::size_t j = i;  // candidates are below j
  for (auto it = pattern.rbegin(); it != pattern.rend(); ++it) {
    const ModulePattern& m = *it;
    if (m.symbol == kOpenBranch || m.symbol == kCloseBranch) continue;
    for (;;) {
      while (j > 0 && ignored[sym[j - 1]]) --j;
      if (j == 0) return false;
      const SymbolId s = sym[j - 1];
      if (s == kCloseBranch) {
        // Pass over a complete lateral branch ]...[ to the module before it.
        int depth = 0;
        std::size_t k = j - 1;
        for (;;) {
          if (sym[k] == kCloseBranch) {
            ++depth;
          } else if (sym[k] == kOpenBranch) {
            if (--depth == 0) break;
          }
          if (k == 0) return false;
          --k;
        }
        j = k;
        continue;
      }
      if (s == kOpenBranch) {  // through '[' to the parent module
        --j;
        continue;
      }
      break;
    }
    if (sym[j - 1] != m.symbol || in.arity(j - 1) != m.slots.size()) return false;
    bind(m, in, j - 1);
    --j;
  }
  return true;
}

bool Derivation::match(const Production& p, const ModuleString& in, std::size_t i) {
  if (in.arity(i) != p.predecessor.slots.size()) return false;
  bind(p.predecessor, in, i);
  if (!p.left.empty() && !match_left(p.left, in, i)) return false;
  if (!p.right.empty() && !match_right(p.right, in, i)) return false;
  EvalState state{locals_.data(), globals_.data(), &rng_};
  for (const Expression& e : p.pre_block) e.evaluate(state);
  if (!p.condition.empty() && p.condition.evaluate(state) == 0.0) return false;
  return true;
}

void Derivation::emit(const Production& p, ModuleString& out) {
  EvalState state{locals_.data(), globals_.data(), &rng_};
  for (const Expression& e : p.post_block) e.evaluate(state);
  for (const ModuleTemplate& t : p.successor) {
    if (t.arguments.empty()) {
      out.push_back(t.symbol);
      continue;
    }
    args_.clear();
    for (const Expression& e : t.arguments) args_.push_back(e.evaluate(state));
    out.push_back(t.symbol, args_);
  }
}

bool Derivation::rewrite(const ProductionGroup& group, const ModuleString& in, ModuleString& out) {
  out.clear();
  if (in.parametric()) out.make_parametric();
  plan_memory(in);
  // Reserve by the growth of the previous step so that a growing string is written once,
  // without reallocation copies (they cost a third of the time of a parametric derivation).
  const double modules = static_cast<double>(in.size()) * growth_ * 1.05 + 16;
  const double params = static_cast<double>(in.pool().size()) * param_growth_ * 1.05 + 16;
  out.reserve(
      static_cast<std::size_t>(std::min({modules, static_cast<double>(options_.module_budget) + 16,
                                         static_cast<double>(memory_cap_) + 16})),
      static_cast<std::size_t>(
          std::min({params, 4.0 * static_cast<double>(options_.module_budget) + 16,
                    static_cast<double>(memory_limit_bytes()) / sizeof(double)})));
  bool changed = false;
  const std::size_t n = in.size();
  const auto& productions = group.productions;
  std::vector<std::pair<std::uint32_t, double>> choices;
  for (std::size_t i = 0; i < n; ++i) {
    const SymbolId s = in.symbol(i);
    const auto& candidates = group.productions_for[s];
    const Production* chosen = nullptr;
    for (std::size_t c = 0; c < candidates.size() && !chosen; ++c) {
      const Production& p = productions[candidates[c]];
      if (!match(p, in, i)) continue;
      if (p.probability.empty()) {
        chosen = &p;
        break;
      }
      // Stochastic: weigh every matching production of this predecessor that has a probability.
      choices.clear();
      double total = 0.0;
      for (std::size_t d = c; d < candidates.size(); ++d) {
        const Production& q = productions[candidates[d]];
        if (q.probability.empty() || (d != c && !match(q, in, i))) continue;
        EvalState state{locals_.data(), globals_.data(), &rng_};
        const double w = q.probability.evaluate(state);
        // Relative weights (documented: `: 1` and `: 3`), so any finite w >= 0.
        if (!(w >= 0.0 && w <= std::numeric_limits<double>::max())) {
          std::string value;
          append_number(value, w);
          throw ValueError("a production probability must be a finite weight >= 0, got " + value,
                           q.position.file, q.position.line, q.position.column);
        }
        total += w;
        choices.emplace_back(candidates[d], w);
      }
      std::uint32_t pick = choices.front().first;
      if (total > 0.0) {
        double r = uniform01(rng_) * total;
        for (const auto& [idx, w] : choices) {
          pick = idx;
          if (r < w) break;
          r -= w;
        }
      }
      chosen = &productions[pick];
      match(*chosen, in, i);  // rebind the chosen production's parameters
    }
    if (chosen) {
      emit(*chosen, out);
      changed = true;
      check_budget(out.size());
    } else {
      out.push_back_from(in, i);
    }
  }
  check_budget(out.size(), true);
  if (&group != &sys_.productions) return changed;  // decomposition passes barely grow
  if (!in.empty()) {
    growth_ = std::max(1.0, static_cast<double>(out.size()) / static_cast<double>(in.size()));
  }
  if (!in.pool().empty()) {
    param_growth_ = std::max(
        1.0, static_cast<double>(out.pool().size()) / static_cast<double>(in.pool().size()));
  }
  return changed;
}

void Derivation::apply_group_repeatedly(const ProductionGroup& group, ModuleString& s) {
  if (group.productions.empty()) return;
  ModuleString tmp;
  for (int depth = 0; depth < group.maximum_depth; ++depth) {
    if (!rewrite(group, s, tmp)) return;
    s.swap(tmp);
  }
}

void Derivation::apply_cut(ModuleString& s) {
  const auto& sym = s.symbols();
  std::size_t first = 0;
  while (first < sym.size() && sym[first] != kCut) ++first;
  if (first == sym.size()) return;
  ModuleString out;
  if (s.parametric()) out.make_parametric();
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (sym[i] != kCut) {
      out.push_back_from(s, i);
      continue;
    }
    // Drop everything up to the ']' that closes the current branch (kept), or the end.
    int depth = 0;
    std::size_t k = i + 1;
    for (; k < s.size(); ++k) {
      if (sym[k] == kOpenBranch) {
        ++depth;
      } else if (sym[k] == kCloseBranch) {
        if (depth == 0) break;
        --depth;
      }
    }
    i = k - 1;
  }
  s.swap(out);
}

void Derivation::update_queries() {
  static const TurtleSettings kDefaults{};
  const TurtleSettings& settings = options_.turtle ? *options_.turtle : kDefaults;
  if (sys_.homomorphism.productions.empty()) {
    fill_query_modules(sys_, current_, settings, options_.environment);
  } else {
    const ModuleString drawn = interpretation_string();
    fill_query_modules(sys_, current_, settings, options_.environment, &drawn);
  }
}

ModuleString Derivation::interpretation_string() {
  ModuleString s = current_;
  apply_group_repeatedly(sys_.homomorphism, s);
  return s;
}

ModuleString derive(const LSystem& system, const DeriveOptions& options, int* steps_done) {
  Derivation d(system, options);
  d.run();
  if (steps_done) *steps_done = d.steps_done();
  return std::move(d.string());
}

}  // namespace fspm::lsystem
