#pragma once
// C-like arithmetic expressions of cpfg's parametric L-systems (ABOP section 1.10): numbers,
// parameters, global variables, + - * / % ^ (power, as in cpfg), comparisons, && || !, the
// ternary ?:, assignment (in statement blocks) and the functions sin cos tan asin acos atan atan2
// (degrees, as in cpfg) sqrt exp log pow floor ceil trunc fabs abs sign min max ran nran.
// Expressions are compiled once into a flat node array and evaluated without allocation.
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "lsystem/source_text.hpp"

namespace fspm::lsystem {

// Where names in an expression live while it is being compiled.
class NameScope {
 public:
  virtual ~NameScope() = default;
  // Slot of a local variable (parameter of a production), or -1.
  virtual int find_local(const std::string& name) const = 0;
  // Slot of a global variable (define:/start: blocks), or -1.
  virtual int find_global(const std::string& name) const = 0;
  // Creates a new variable assigned in a statement block; returns its slot (local when the scope
  // has a local frame, else global) and whether it is global.
  virtual int create_variable(const std::string& name, bool& is_global) = 0;
};

// Mutable state an expression reads and writes while it runs.
struct EvalState {
  double* locals = nullptr;
  double* globals = nullptr;
  std::mt19937_64* rng = nullptr;
};

// Uniform number in [0, 1) from the generator, identical on every platform (53 random bits).
inline double uniform01(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

// v truncated toward zero and clamped to [lo, hi]; NaN gives lo (no undefined conversions).
inline long long clamp_to_integer(double v, long long lo, long long hi) {
  if (!(v >= static_cast<double>(lo))) return lo;
  if (v >= static_cast<double>(hi)) return hi;
  return static_cast<long long>(v);
}

class Expression {
 public:
  Expression() = default;
  bool empty() const { return nodes_.empty(); }
  // Throws ValueError (with the expression's source position) on division by zero.
  double evaluate(EvalState& state) const { return eval(root_, state); }
  // True when the expression is a plain constant (value in *out).
  bool is_constant(double* out = nullptr) const;
  // True when evaluating it draws no random number and assigns no global variable (local
  // assignments allowed): its value depends only on the locals and globals it reads, so the
  // same module rewrites the same way wherever and whenever it stands.
  bool is_pure() const;
  const SourcePosition& position() const { return position_; }

 private:
  friend class ExpressionCompiler;
  enum class Op : std::uint8_t {
    kConst,
    kLocal,
    kGlobal,
    kAssignLocal,
    kAssignGlobal,
    kNeg,
    kNot,
    kAdd,
    kSub,
    kMul,
    kDiv,
    kMod,
    kPow,
    kLt,
    kLe,
    kGt,
    kGe,
    kEq,
    kNe,
    kAnd,
    kOr,
    kCond,
    kCall1,
    kCall2,
    kRan,
    kNran,
    kComma,
    kWhile
  };
  struct Node {
    Op op;
    std::uint8_t function = 0;
    std::int32_t a = -1, b = -1, c = -1;
    double value = 0.0;
  };
  double eval(std::int32_t n, EvalState& state) const;
  double eval_nran(const Node& node, EvalState& state) const;
  double eval_while(const Node& node, EvalState& state) const;
  [[noreturn]] void division_by_zero() const;

  std::vector<Node> nodes_;
  std::int32_t root_ = -1;
  SourcePosition position_;
};

// Compiles expressions from a cursor; stops at the first character that cannot continue the
// expression (so `A(x*2, y)` is read argument by argument).
class ExpressionCompiler {
 public:
  ExpressionCompiler(Cursor& cursor, NameScope& scope) : cur_(cursor), scope_(scope) {}
  // One expression (assignment allowed only when allow_assignment).
  Expression compile(bool allow_assignment = false);
  // Statements `a = 1; b = a * 2;`, `if (c) {...} else {...}`, `while (c) {...}` up to (not
  // including) `end_char` or the end of the text.
  std::vector<Expression> compile_statements(char end_char);

 private:
  using Op = Expression::Op;
  std::int32_t add(Expression::Node node);
  bool keyword(const char* word);
  std::int32_t statement(char end_char);
  std::int32_t block_or_statement(char end_char);
  std::int32_t assignment();
  std::int32_t ternary();
  std::int32_t logical_or();
  std::int32_t logical_and();
  std::int32_t equality();
  std::int32_t relational();
  std::int32_t additive();
  std::int32_t multiplicative();
  std::int32_t unary();
  std::int32_t power();
  std::int32_t primary();
  std::int32_t number();
  std::int32_t call(const std::string& name, std::size_t start);
  std::int32_t variable(const std::string& name, std::size_t start);

  Cursor& cur_;
  NameScope& scope_;
  Expression* out_ = nullptr;
  bool allow_assignment_ = false;
  int depth_ = 0;  // nesting, bounded so that hostile input cannot exhaust the stack
};

}  // namespace fspm::lsystem
