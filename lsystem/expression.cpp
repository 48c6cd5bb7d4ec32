#include "lsystem/expression.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string_view>

#include "fspm/error.hpp"

namespace fspm::lsystem {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;
constexpr long kMaxLoopIterations = 1'000'000;

enum Function : std::uint8_t {
  kSin,
  kCos,
  kTan,
  kAsin,
  kAcos,
  kAtan,
  kSqrt,
  kExp,
  kLog,
  kFloor,
  kCeil,
  kTrunc,
  kFabs,
  kSign,
  kAtan2,
  kPow,
  kMin,
  kMax
};

struct FunctionInfo {
  std::string_view name;
  int arity;
  Function id;
};

constexpr FunctionInfo kFunctions[] = {
    {"sin", 1, kSin},   {"cos", 1, kCos},     {"tan", 1, kTan},   {"asin", 1, kAsin},
    {"acos", 1, kAcos}, {"atan", 1, kAtan},   {"sqrt", 1, kSqrt}, {"exp", 1, kExp},
    {"log", 1, kLog},   {"floor", 1, kFloor}, {"ceil", 1, kCeil}, {"trunc", 1, kTrunc},
    {"fabs", 1, kFabs}, {"abs", 1, kFabs},    {"sign", 1, kSign}, {"atan2", 2, kAtan2},
    {"pow", 2, kPow},   {"min", 2, kMin},     {"max", 2, kMax},
};

double call1(std::uint8_t f, double x) {
  switch (f) {
    case kSin:
      return std::sin(x / kDegPerRad);
    case kCos:
      return std::cos(x / kDegPerRad);
    case kTan:
      return std::tan(x / kDegPerRad);
    case kAsin:
      return std::asin(x) * kDegPerRad;
    case kAcos:
      return std::acos(x) * kDegPerRad;
    case kAtan:
      return std::atan(x) * kDegPerRad;
    case kSqrt:
      return std::sqrt(x);
    case kExp:
      return std::exp(x);
    case kLog:
      return std::log(x);
    case kFloor:
      return std::floor(x);
    case kCeil:
      return std::ceil(x);
    case kTrunc:
      return std::trunc(x);
    case kFabs:
      return std::fabs(x);
    case kSign:
      return x > 0 ? 1.0 : (x < 0 ? -1.0 : 0.0);
    default:
      return 0.0;
  }
}

double call2(std::uint8_t f, double x, double y) {
  switch (f) {
    case kAtan2:
      return std::atan2(x, y) * kDegPerRad;
    case kPow:
      return std::pow(x, y);
    case kMin:
      return std::min(x, y);
    case kMax:
      return std::max(x, y);
    default:
      return 0.0;
  }
}

bool is_ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

}  // namespace

bool Expression::is_constant(double* out) const {
  if (nodes_.empty() || nodes_[root_].op != Op::kConst) return false;
  if (out) *out = nodes_[root_].value;
  return true;
}

bool Expression::is_pure() const {
  for (const Node& node : nodes_) {
    if (node.op == Op::kAssignGlobal || node.op == Op::kRan || node.op == Op::kNran) return false;
  }
  return true;
}

void Expression::division_by_zero() const {
  throw ValueError("division by zero", position_.file, position_.line, position_.column);
}

double Expression::eval_nran(const Node& node, EvalState& s) const {
  // Box-Muller from two uniforms of the seeded generator (platform independent).
  const double mean = eval(node.a, s);
  const double sd = eval(node.b, s);
  const double u1 = 1.0 - uniform01(*s.rng);
  const double u2 = uniform01(*s.rng);
  return mean + sd * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

double Expression::eval_while(const Node& node, EvalState& s) const {
  long iterations = 0;
  while (eval(node.a, s) != 0.0) {
    if (++iterations > kMaxLoopIterations) {
      throw ValueError("while loop ran more than 1000000 times", position_.file, position_.line,
                       position_.column);
    }
    eval(node.b, s);
  }
  return 0.0;
}

double Expression::eval(std::int32_t n, EvalState& s) const {
  const Node& node = nodes_[n];
  switch (node.op) {
    case Op::kConst:
      return node.value;
    case Op::kLocal:
      return s.locals[node.a];
    case Op::kGlobal:
      return s.globals[node.a];
    case Op::kAssignLocal:
      return s.locals[node.a] = eval(node.b, s);
    case Op::kAssignGlobal:
      return s.globals[node.a] = eval(node.b, s);
    case Op::kNeg:
      return -eval(node.a, s);
    case Op::kNot:
      return eval(node.a, s) == 0.0 ? 1.0 : 0.0;
    case Op::kAdd:
      return eval(node.a, s) + eval(node.b, s);
    case Op::kSub:
      return eval(node.a, s) - eval(node.b, s);
    case Op::kMul:
      return eval(node.a, s) * eval(node.b, s);
    case Op::kDiv: {
      const double x = eval(node.a, s);
      const double y = eval(node.b, s);
      if (y == 0.0) division_by_zero();
      return x / y;
    }
    case Op::kMod: {
      const double x = eval(node.a, s);
      const double y = eval(node.b, s);
      if (y == 0.0) division_by_zero();
      return std::fmod(x, y);
    }
    case Op::kPow:
      return std::pow(eval(node.a, s), eval(node.b, s));
    case Op::kLt:
      return eval(node.a, s) < eval(node.b, s) ? 1.0 : 0.0;
    case Op::kLe:
      return eval(node.a, s) <= eval(node.b, s) ? 1.0 : 0.0;
    case Op::kGt:
      return eval(node.a, s) > eval(node.b, s) ? 1.0 : 0.0;
    case Op::kGe:
      return eval(node.a, s) >= eval(node.b, s) ? 1.0 : 0.0;
    case Op::kEq:
      return eval(node.a, s) == eval(node.b, s) ? 1.0 : 0.0;
    case Op::kNe:
      return eval(node.a, s) != eval(node.b, s) ? 1.0 : 0.0;
    case Op::kAnd:
      return (eval(node.a, s) != 0.0 && eval(node.b, s) != 0.0) ? 1.0 : 0.0;
    case Op::kOr:
      return (eval(node.a, s) != 0.0 || eval(node.b, s) != 0.0) ? 1.0 : 0.0;
    case Op::kCond:
      return eval(node.a, s) != 0.0 ? eval(node.b, s) : eval(node.c, s);
    case Op::kCall1:
      return call1(node.function, eval(node.a, s));
    case Op::kCall2:
      return call2(node.function, eval(node.a, s), eval(node.b, s));
    case Op::kRan: {
      const double x = eval(node.a, s);
      return uniform01(*s.rng) * x;
    }
    case Op::kNran:
      return eval_nran(node, s);
    case Op::kComma:
      eval(node.a, s);
      return eval(node.b, s);
    case Op::kWhile:
      return eval_while(node, s);
  }
  return 0.0;
}

// Bounds that keep compilation and (recursive) evaluation within a small stack; real grammars
// stay far below them.
constexpr std::size_t kMaxNodes = 4096;
constexpr int kMaxNesting = 256;

std::int32_t ExpressionCompiler::add(Expression::Node node) {
  if (out_->nodes_.size() >= kMaxNodes)
    cur_.fail_at(cur_.pos(), "expression too long (more than 4096 terms)");
  out_->nodes_.push_back(node);
  return static_cast<std::int32_t>(out_->nodes_.size() - 1);
}

Expression ExpressionCompiler::compile(bool allow_assignment) {
  Expression e;
  cur_.skip_space();
  e.position_ = cur_.position();
  out_ = &e;
  allow_assignment_ = allow_assignment;
  depth_ = 0;
  e.root_ = assignment();
  out_ = nullptr;
  return e;
}

std::vector<Expression> ExpressionCompiler::compile_statements(char end_char) {
  std::vector<Expression> out;
  for (;;) {
    cur_.skip_space();
    if (cur_.at_end() || cur_.peek() == end_char) break;
    if (cur_.peek() == ';') {
      cur_.advance();
      continue;
    }
    Expression e;
    e.position_ = cur_.position();
    out_ = &e;
    allow_assignment_ = true;
    depth_ = 0;
    e.root_ = statement(end_char);
    out_ = nullptr;
    out.push_back(std::move(e));
  }
  return out;
}

bool ExpressionCompiler::keyword(const char* word) {
  cur_.skip_space();
  const std::size_t n = std::char_traits<char>::length(word);
  if (cur_.rest().substr(0, n) != word || is_ident_char(cur_.peek(n))) return false;
  cur_.advance(n);
  return true;
}

std::int32_t ExpressionCompiler::block_or_statement(char end_char) {
  cur_.skip_space();
  if (cur_.peek() != '{') return statement(end_char);
  cur_.advance();
  Expression::Node zero{Op::kConst};
  std::int32_t seq = add(zero);
  for (;;) {
    cur_.skip_space();
    if (cur_.peek() == '}') {
      cur_.advance();
      return seq;
    }
    if (cur_.at_end()) cur_.fail("'}' closing the statement block");
    if (cur_.peek() == ';') {
      cur_.advance();
      continue;
    }
    Expression::Node n{Op::kComma};
    n.a = seq;
    n.b = statement('}');
    seq = add(n);
  }
}

std::int32_t ExpressionCompiler::statement(char end_char) {
  if (++depth_ > kMaxNesting) cur_.fail_at(cur_.pos(), "statements nested too deeply");
  std::int32_t result;
  if (keyword("if")) {
    cur_.expect('(', "'(' after if");
    const std::int32_t c = assignment();
    cur_.expect(')', "')' closing the if condition");
    const std::int32_t then_part = block_or_statement(end_char);
    Expression::Node n{Op::kCond};
    n.a = c;
    n.b = then_part;
    if (keyword("else")) {
      n.c = block_or_statement(end_char);
    } else {
      Expression::Node zero{Op::kConst};
      n.c = add(zero);
    }
    result = add(n);
  } else if (keyword("while")) {
    cur_.expect('(', "'(' after while");
    const std::int32_t c = assignment();
    cur_.expect(')', "')' closing the while condition");
    Expression::Node n{Op::kWhile};
    n.a = c;
    n.b = block_or_statement(end_char);
    result = add(n);
  } else {
    result = assignment();
    cur_.skip_space();
    if (cur_.peek() == ';') {
      cur_.advance();
    } else if (!(cur_.at_end() || cur_.peek() == end_char || cur_.peek() == '}')) {
      cur_.fail("';' after a statement");
    }
  }
  --depth_;
  return result;
}

std::int32_t ExpressionCompiler::assignment() {
  cur_.skip_space();
  if (allow_assignment_ && is_ident_start(cur_.peek())) {
    const std::size_t start = cur_.pos();
    std::size_t p = 0;
    while (is_ident_char(cur_.peek(p))) ++p;
    std::string name(cur_.rest().substr(0, p));
    cur_.advance(p);
    cur_.skip_space();
    if (cur_.peek() == '=' && cur_.peek(1) != '=') {
      cur_.advance();
      const std::int32_t value = assignment();
      int slot = scope_.find_local(name);
      bool global = false;
      if (slot < 0) {
        slot = scope_.find_global(name);
        global = slot >= 0;
      }
      if (slot < 0) slot = scope_.create_variable(name, global);
      Expression::Node n{global ? Op::kAssignGlobal : Op::kAssignLocal};
      n.a = slot;
      n.b = value;
      return add(n);
    }
    cur_.set_pos(start);
  }
  return ternary();
}

std::int32_t ExpressionCompiler::ternary() {
  const std::int32_t c = logical_or();
  cur_.skip_space();
  if (cur_.peek() == '?') {
    cur_.advance();
    const std::int32_t a = assignment();
    cur_.expect(':', "':' of the conditional expression");
    const std::int32_t b = assignment();
    Expression::Node n{Op::kCond};
    n.a = c;
    n.b = a;
    n.c = b;
    return add(n);
  }
  return c;
}

std::int32_t ExpressionCompiler::logical_or() {
  std::int32_t l = logical_and();
  while (cur_.accept("||")) {
    Expression::Node n{Op::kOr};
    n.a = l;
    n.b = logical_and();
    l = add(n);
  }
  return l;
}

std::int32_t ExpressionCompiler::logical_and() {
  std::int32_t l = equality();
  while (cur_.accept("&&")) {
    Expression::Node n{Op::kAnd};
    n.a = l;
    n.b = equality();
    l = add(n);
  }
  return l;
}

std::int32_t ExpressionCompiler::equality() {
  std::int32_t l = relational();
  for (;;) {
    Op op;
    if (cur_.accept("==")) {
      op = Op::kEq;
    } else if (cur_.accept("!=")) {
      op = Op::kNe;
    } else {
      return l;
    }
    Expression::Node n{op};
    n.a = l;
    n.b = relational();
    l = add(n);
  }
}

std::int32_t ExpressionCompiler::relational() {
  std::int32_t l = additive();
  for (;;) {
    Op op;
    if (cur_.accept("<=")) {
      op = Op::kLe;
    } else if (cur_.accept(">=")) {
      op = Op::kGe;
    } else if (cur_.accept("<")) {
      op = Op::kLt;
    } else if (cur_.accept(">")) {
      op = Op::kGt;
    } else {
      return l;
    }
    Expression::Node n{op};
    n.a = l;
    n.b = additive();
    l = add(n);
  }
}

std::int32_t ExpressionCompiler::additive() {
  std::int32_t l = multiplicative();
  for (;;) {
    cur_.skip_space();
    const char c = cur_.peek();
    if (c != '+' && c != '-') return l;
    cur_.advance();
    Expression::Node n{c == '+' ? Op::kAdd : Op::kSub};
    n.a = l;
    n.b = multiplicative();
    l = add(n);
  }
}

std::int32_t ExpressionCompiler::multiplicative() {
  std::int32_t l = unary();
  for (;;) {
    cur_.skip_space();
    const char c = cur_.peek();
    if (c != '*' && c != '/' && c != '%') return l;
    cur_.advance();
    Expression::Node n{c == '*' ? Op::kMul : (c == '/' ? Op::kDiv : Op::kMod)};
    n.a = l;
    n.b = unary();
    l = add(n);
  }
}

std::int32_t ExpressionCompiler::unary() {
  struct Nesting {
    explicit Nesting(ExpressionCompiler& c) : c_(c) {
      if (++c_.depth_ > kMaxNesting) c_.cur_.fail_at(c_.cur_.pos(), "expression nested too deeply");
    }
    ~Nesting() { --c_.depth_; }
    ExpressionCompiler& c_;
  } nesting(*this);
  cur_.skip_space();
  const char c = cur_.peek();
  if (c == '-' || c == '!' || c == '+') {
    cur_.advance();
    const std::int32_t a = unary();
    if (c == '+') return a;
    Expression::Node n{c == '-' ? Op::kNeg : Op::kNot};
    n.a = a;
    return add(n);
  }
  return power();
}

std::int32_t ExpressionCompiler::power() {
  const std::int32_t base = primary();
  cur_.skip_space();
  if (cur_.peek() == '^') {
    cur_.advance();
    Expression::Node n{Op::kPow};
    n.a = base;
    n.b = unary();  // right associative: 2^3^2 = 2^9
    return add(n);
  }
  return base;
}

std::int32_t ExpressionCompiler::primary() {
  cur_.skip_space();
  const char c = cur_.peek();
  if (c == '(') {
    cur_.advance();
    const std::int32_t e = assignment();
    cur_.expect(')', "')'");
    return e;
  }
  if (std::isdigit(static_cast<unsigned char>(c)) ||
      (c == '.' && std::isdigit(static_cast<unsigned char>(cur_.peek(1))))) {
    return number();
  }
  if (is_ident_start(c)) {
    const std::size_t start = cur_.pos();
    std::size_t p = 0;
    while (is_ident_char(cur_.peek(p))) ++p;
    const std::string name(cur_.rest().substr(0, p));
    cur_.advance(p);
    cur_.skip_space();
    return cur_.peek() == '(' ? call(name, start) : variable(name, start);
  }
  cur_.fail("a number, a parameter, a function call or '('");
}

std::int32_t ExpressionCompiler::number() {
  const std::string_view rest = cur_.rest();
  std::string buffer(rest.substr(0, std::min<std::size_t>(rest.size(), 64)));
  char* end = nullptr;
  const double v = std::strtod(buffer.c_str(), &end);
  std::size_t used = static_cast<std::size_t>(end - buffer.c_str());
  cur_.advance(used);
  if (cur_.peek() == 'f' || cur_.peek() == 'F') {
    if (!is_ident_char(cur_.peek(1))) cur_.advance();  // C float suffix 1.5f
  }
  Expression::Node n{Op::kConst};
  n.value = v;
  return add(n);
}

// A call `name(args)`, the cursor on its '('; `start` is where the name began.
std::int32_t ExpressionCompiler::call(const std::string& name, std::size_t start) {
  cur_.advance();
  std::vector<std::int32_t> args;
  cur_.skip_space();
  if (cur_.peek() != ')') {
    for (;;) {
      args.push_back(assignment());
      if (!cur_.accept(",")) break;
    }
  }
  cur_.expect(')', "')' closing the arguments of " + name);
  auto arity_error = [&](int n) {
    cur_.fail_at(start, "function " + name + " expects " + std::to_string(n) +
                            " argument(s), got " + std::to_string(args.size()));
  };
  if (name == "ran") {
    if (args.size() != 1) arity_error(1);
    Expression::Node n{Op::kRan};
    n.a = args[0];
    return add(n);
  }
  if (name == "nran") {
    if (args.size() != 2) arity_error(2);
    Expression::Node n{Op::kNran};
    n.a = args[0];
    n.b = args[1];
    return add(n);
  }
  for (const FunctionInfo& f : kFunctions) {
    if (f.name != name) continue;
    if (static_cast<int>(args.size()) != f.arity) arity_error(f.arity);
    Expression::Node n{f.arity == 1 ? Op::kCall1 : Op::kCall2};
    n.function = f.id;
    n.a = args[0];
    if (f.arity == 2) n.b = args[1];
    return add(n);
  }
  cur_.fail_at(start, "unknown function '" + name + "'");
}

std::int32_t ExpressionCompiler::variable(const std::string& name, std::size_t start) {
  int slot = scope_.find_local(name);
  if (slot >= 0) {
    Expression::Node n{Op::kLocal};
    n.a = slot;
    return add(n);
  }
  slot = scope_.find_global(name);
  if (slot >= 0) {
    Expression::Node n{Op::kGlobal};
    n.a = slot;
    return add(n);
  }
  cur_.fail_at(start, "undefined parameter or variable '" + name + "'");
}

}  // namespace fspm::lsystem
