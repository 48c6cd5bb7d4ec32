// libFuzzer target for the L-system reader and derivation. The first byte picks the mode:
//   even: the remaining bytes are an L-system file (parser, preprocessor, expressions); when
//         it is 2 mod 4, the file is derived as far as it says (up to 60 steps, explicitly and
//         into substructures) with no module budget, so that exponential growth (modules of
//         many parameters doubling, deep branching, parameters that are never shared) must end
//         in the memory limit's error;
//   odd:  the bytes drive a generator of small well-formed grammars (contexts, brackets,
//         parameters, conditions, probabilities, cut, decomposition, homomorphism), so most
//         inputs reach derivation and turtle interpretation.
// Everything must succeed or throw fspm::Error; anything else (crash, sanitizer report, other
// exception) is a bug.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"
#include "lsystem/derivation.hpp"
#include "lsystem/parser.hpp"
#include "lsystem/substructure_derivation.hpp"
#include "lsystem/turtle.hpp"

namespace {

class ByteSource {
 public:
  ByteSource(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  unsigned next(unsigned n) { return pos_ < size_ ? data_[pos_++] % n : 0; }
  bool done() const { return pos_ >= size_; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

std::string module(ByteSource& in, bool parametric, bool in_successor) {
  static const char* kNames[] = {"F", "A", "B", "+", "-", "&",  "/", "!",
                                 "f", "{", ".", "}", "%", "?P", "$", "|"};
  std::string m = kNames[in.next(in_successor ? 16 : 3)];
  if (parametric && m != "{" && m != "}" && m != "%") {
    static const char* kArgs[] = {"x", "x*2", "x/2", "x+1", "ran(3)", "1/x", "x>1?x:2", "-x"};
    m += "(";
    m += in_successor ? kArgs[in.next(8)] : "x";
    m += ")";
  }
  return m;
}

std::string successor(ByteSource& in, bool parametric) {
  std::string s;
  const unsigned n = in.next(8);
  int depth = 0;
  for (unsigned i = 0; i < n; ++i) {
    const unsigned k = in.next(10);
    if (k == 0) {
      s += "[";
      ++depth;
    } else if (k == 1 && depth > 0) {
      s += "]";
      --depth;
    } else {
      s += module(in, parametric && in.next(2), true);
    }
  }
  s.append(static_cast<std::size_t>(depth), ']');
  return s.empty() ? "*" : s;
}

std::string generate(ByteSource& in) {
  const bool parametric = in.next(2);
  std::string g = "seed: " + std::to_string(in.next(100)) + "\n";
  if (in.next(2)) g += "ignore: +-/&\n";
  g += "Axiom: " + successor(in, parametric) + "\n";
  const unsigned productions = 1 + in.next(6);
  for (unsigned p = 0; p < productions && !in.done(); ++p) {
    if (p == productions - 1 && in.next(3) == 0)
      g += in.next(2) ? "decomposition\n" : "homomorphism\n";
    std::string line;
    if (in.next(3) == 0) line += module(in, parametric, false) + " < ";
    line += module(in, parametric, false);
    if (in.next(3) == 0) line += " > " + module(in, parametric, false);
    if (parametric && in.next(2)) line += " : x < " + std::to_string(in.next(5));
    line += " --> " + successor(in, parametric);
    if (in.next(3) == 0) line += " : " + std::to_string(in.next(4));
    g += line + "\n";
  }
  return g;
}

void run(std::string_view text) {
  try {
    // Includes resolve in a directory that does not exist, so inputs never read real files.
    const fspm::lsystem::LSystem sys =
        fspm::lsystem::parse_lsystem(text, "fuzz.l", {}, "/nonexistent-fspm-fuzz");
    fspm::lsystem::DeriveOptions options;
    options.steps = std::min(std::max(sys.derivation_length, 4), 6);
    options.module_budget = 20000;
    fspm::lsystem::Derivation derivation(sys, options);
    derivation.run();
    const fspm::lsystem::ModuleString s = derivation.interpretation_string();
    if (s.size() <= 20000) fspm::lsystem::interpret(s, sys.symbols);
  } catch (const fspm::Error&) {
    // Expected for malformed input.
  }
}

constexpr std::size_t kMemoryLimit = std::size_t{64} << 20;

void run_growth(std::string_view text) {
  fspm::set_memory_limit_bytes(std::size_t{16} << 20);
  try {
    const fspm::lsystem::LSystem sys =
        fspm::lsystem::parse_lsystem(text, "fuzz.l", {}, "/nonexistent-fspm-fuzz");
    fspm::lsystem::DeriveOptions options;
    options.steps = std::clamp(sys.derivation_length, 1, 60);
    options.module_budget = std::size_t{1} << 50;  // only the memory limit stops the growth
    fspm::lsystem::Derivation derivation(sys, options);
    derivation.run();
    if (!fspm::lsystem::factorization_obstacle(sys)) {
      fspm::lsystem::derive_substructures(sys, options);
    }
  } catch (const fspm::Error&) {
    // Expected: malformed input, or growth past the memory limit.
  }
  fspm::set_memory_limit_bytes(kMemoryLimit);
}

}  // namespace

// The process's memory limit far below libFuzzer's -malloc_limit_mb: a string that outgrows it
// must be refused by the derivation's check, not by the fuzzer.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  fspm::set_memory_limit_bytes(kMemoryLimit);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  if (data[0] % 4 == 2) {
    run_growth(std::string_view(reinterpret_cast<const char*>(data + 1), size - 1));
  } else if (data[0] % 2 == 0) {
    run(std::string_view(reinterpret_cast<const char*>(data + 1), size - 1));
  } else {
    ByteSource in(data + 1, size - 1);
    run(generate(in));
  }
  return 0;
}
