#pragma once
// Derivation with cpfg's semantics: parallel rewriting of the whole string per step; for each
// module the first production in file order whose predecessor, contexts and condition match is
// applied (a stochastic choice by relative weights among the matching productions that carry a
// probability); no match copies the module. Decomposition productions run after every step until
// none applies (at most their maximum depth passes); `%` then cuts the rest of its branch.
// Homomorphism productions are applied only to produce the string that is interpreted.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <span>
#include <vector>

#include "lsystem/lsystem.hpp"
#include "lsystem/module_string.hpp"

namespace fspm::lsystem {

class OpenEnvironment;
struct TurtleSettings;

inline constexpr std::size_t kDefaultModuleBudget = 100'000'000;
inline constexpr std::uint64_t kDefaultSeed = 1;

struct DeriveOptions {
  std::optional<int> steps;                          // overrides `derivation length:`
  std::optional<std::uint64_t> seed;                 // overrides `seed:` (default kDefaultSeed)
  std::size_t module_budget = kDefaultModuleBudget;  // ValueError when a string grows past it
  // The string in bytes (with the one it is rewritten from) also stays within the process's
  // memory limit (fspm/memory_budget.hpp): MemoryLimitError when it would not.
  // Open L-systems: query modules ?P ?H ?U ?L are filled by a turtle pass after every step and
  // communication modules ?E(...) by this environment (may be null: ?E keep their values).
  OpenEnvironment* environment = nullptr;
  const TurtleSettings* turtle = nullptr;  // turtle settings for query passes (defaults if null)
};

class Derivation {
 public:
  // Runs define:/start: blocks and builds the axiom (with decomposition applied).
  Derivation(const LSystem& system, const DeriveOptions& options = {});
  ~Derivation();
  Derivation(const Derivation&) = delete;
  Derivation& operator=(const Derivation&) = delete;

  // Steps until the requested derivation length is reached.
  void run();
  // One derivation step (with decomposition, cut and environment/query passes).
  void step();

  int steps_done() const { return steps_done_; }
  int target_steps() const { return target_steps_; }
  const ModuleString& string() const { return current_; }
  ModuleString& string() { return current_; }
  const LSystem& system() const { return sys_; }
  std::mt19937_64& random() { return rng_; }
  std::vector<double>& globals() { return globals_; }

  // The string to interpret: homomorphism productions applied (a copy; the derived string is
  // unchanged).
  ModuleString interpretation_string();

  // One derivation step of a single module (its production, then decomposition) into `out`.
  // For a context-free L-system without cut, queries or per-step blocks this is exactly the
  // module's part of step() in any string (lsystem/substructure_derivation.hpp relies on it).
  void rewrite_module(SymbolId symbol, std::span<const double> parameters, ModuleString& out);
  // The homomorphism of a single module into `out` (the module itself without homomorphism
  // productions): its part of interpretation_string() when the homomorphism productions are
  // context-free and pure (homomorphism_obstacle() in lsystem/substructure_derivation.hpp).
  void interpret_module(SymbolId symbol, std::span<const double> parameters, ModuleString& out);

 private:
  // Rewrites `in` into `out` with `group`; returns true when some production applied.
  bool rewrite(const ProductionGroup& group, const ModuleString& in, ModuleString& out);
  bool rewrite_fast(const ModuleString& in, ModuleString& out);
  void apply_group_repeatedly(const ProductionGroup& group, ModuleString& s);
  void apply_cut(ModuleString& s);
  void run_block(const std::vector<Expression>& block);
  void update_queries();
  bool match(const Production& p, const ModuleString& in, std::size_t i);
  bool match_left(const std::vector<ModulePattern>& pattern, const ModuleString& in, std::size_t i);
  bool match_right(const std::vector<ModulePattern>& pattern, const ModuleString& in,
                   std::size_t i);
  void bind(const ModulePattern& pattern, const ModuleString& in, std::size_t i);
  void emit(const Production& p, ModuleString& out);
  // Refuses a string of `size` modules above the module budget or the memory limit; `reserve`
  // also reserves its bytes for the job sharing the limit (fspm/memory_account.hpp), as a
  // finished string does, where one still being written is checked only past memory_cap_.
  void check_budget(std::size_t size, bool reserve = false) const;
  // Sets the largest output string the memory limit (less what other jobs hold) allows next to
  // the string `in`.
  void plan_memory(const ModuleString& in);

  const LSystem& sys_;
  DeriveOptions options_;
  std::mt19937_64 rng_;
  std::vector<double> globals_;
  std::vector<double> locals_;
  std::vector<double> args_;
  ModuleString current_, next_;
  ModuleString module_;  // rewrite_module's input
  int steps_done_ = 0;
  int target_steps_ = 0;
  bool parametric_ = false;
  double growth_ = 1.5;        // modules out / modules in of the last rewrite
  double param_growth_ = 1.5;  // same for parameters
  // Memory limit of the string being written (plan_memory): its modules are checked against
  // memory_cap_ as cheaply as against the module budget; only past it are bytes estimated.
  std::size_t memory_cap_ = std::numeric_limits<std::size_t>::max();
  double bytes_per_module_ = 2.0;
  double input_bytes_ = 0.0;
  bool has_cut_ = false;
  bool has_queries_ = false;
  // Fast path for context-free, deterministic, non-parametric productions: successor of every
  // symbol as a slice of one flat table (identity for symbols without a production).
  bool fast_ = false;
  std::vector<std::uint32_t> fast_begin_, fast_length_;
  std::vector<SymbolId> fast_data_;
};

// Derives `system` for the requested number of steps and returns the final string.
ModuleString derive(const LSystem& system, const DeriveOptions& options = {},
                    int* steps_done = nullptr);

}  // namespace fspm::lsystem
