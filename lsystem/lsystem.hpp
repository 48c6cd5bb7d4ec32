#pragma once
// A parsed L-system in cpfg's sense: axiom, productions, decomposition and homomorphism
// productions, global variables and header settings. Built by the parser (lsystem/parser.hpp),
// derived by lsystem/derivation.hpp, drawn by lsystem/turtle.hpp.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "lsystem/expression.hpp"
#include "lsystem/module_string.hpp"
#include "lsystem/source_text.hpp"

namespace fspm::lsystem {

// A module in a predecessor or context: name and the local slots its parameters bind to.
struct ModulePattern {
  SymbolId symbol = 0;
  std::vector<int> slots;  // arity = slots.size()
};

// A module in a successor or axiom: name and one expression per parameter.
struct ModuleTemplate {
  SymbolId symbol = 0;
  std::vector<Expression> arguments;
};

struct Production {
  std::vector<ModulePattern> left;  // left context, in string order (may hold [ and ])
  ModulePattern predecessor;
  std::vector<ModulePattern> right;    // right context, in string order (may hold [ and ])
  std::vector<Expression> pre_block;   // {...} before the condition
  Expression condition;                // empty: always true
  std::vector<Expression> post_block;  // {...} after the condition
  std::vector<ModuleTemplate> successor;
  Expression probability;  // empty: deterministic
  int local_count = 0;     // size of the local frame (parameters + block variables)
  bool context_free() const { return left.empty() && right.empty(); }
  SourcePosition position;
};

struct ProductionGroup {
  std::vector<Production> productions;  // file order
  int maximum_depth = 1;                // decomposition / homomorphism recursion bound
  // productions_for[symbol]: indices of productions whose predecessor is `symbol`, file order.
  std::vector<std::vector<std::uint32_t>> productions_for;
  void index(std::size_t symbol_count);
};

struct GlobalVariables {
  std::vector<std::string> names;
  std::vector<double> values;
  int find(const std::string& name) const;
  int add(const std::string& name, double value = 0.0);
};

struct LSystem {
  std::string file;
  int number = 1;  // Lsystem: N
  SymbolTable symbols;
  GlobalVariables globals;
  std::vector<Expression> define_block;      // define: { ... } (run once before the axiom)
  std::vector<Expression> start_block;       // start: { ... }
  std::vector<Expression> start_each_block;  // startEach: { ... } (before every step)
  std::vector<Expression> end_each_block;    // endEach: { ... } (after every step)
  std::vector<Expression> end_block;         // end: { ... }
  std::optional<std::uint64_t> seed;
  int derivation_length = 0;
  int maximum_depth = 1;
  std::vector<ModuleTemplate> axiom;
  ProductionGroup productions;
  ProductionGroup decomposition;
  ProductionGroup homomorphism;
  // Context matching: ignored[symbol] != 0 when `ignore:` lists it or `consider:` does not.
  std::vector<std::uint8_t> ignored;
  int local_frame_size() const;  // largest local frame of any production
};

}  // namespace fspm::lsystem
