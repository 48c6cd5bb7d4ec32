#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "fspm/error.hpp"
#include "lsystem/derivation.hpp"
#include "lsystem/parser.hpp"
#include "tests/scoped_memory_limit.hpp"

namespace fspm::lsystem {
namespace {

std::string example(const std::string& name) {
  return std::string(FSPM_SOURCE_DIR) + "/examples/lsystems/" + name;
}

std::string derived(const std::string& text, int steps) {
  const LSystem sys = parse_lsystem(text, "test.l");
  DeriveOptions options;
  options.steps = steps;
  return to_string(derive(sys, options), sys.symbols);
}

std::map<std::string, std::uint64_t> counts(const ModuleString& s, const SymbolTable& t) {
  std::map<std::string, std::uint64_t> out;
  for (SymbolId id : s.symbols()) ++out[t.name(id)];
  return out;
}

// Independent oracle for D0L systems of one-character modules: the per-symbol count vector
// evolves by the production matrix M[s][t] = occurrences of t in the successor of s
// (identity for symbols without a production). Successors are given as plain strings here,
// not read through the parser.
std::map<char, std::uint64_t> d0l_counts(const std::string& axiom,
                                         const std::map<char, std::string>& rules, int n) {
  std::map<char, std::uint64_t> c;
  for (char ch : axiom) ++c[ch];
  for (int step = 0; step < n; ++step) {
    std::map<char, std::uint64_t> next;
    for (const auto& [sym, k] : c) {
      auto it = rules.find(sym);
      if (it == rules.end()) {
        next[sym] += k;
        continue;
      }
      for (char t : it->second) next[t] += k;
    }
    c = next;
  }
  return c;
}

struct Figure {
  const char* file;
  const char* axiom;
  std::map<char, std::string> rules;
  int n;
};

TEST(LsystemDerivation, Abop124CountsMatchTheProductionMatrixRecurrence) {
  const std::vector<Figure> figures = {
      {"abop_1_24a.l", "F", {{'F', "F[+F]F[-F]F"}}, 5},
      {"abop_1_24b.l", "F", {{'F', "F[+F]F[-F][F]"}}, 5},
      {"abop_1_24c.l", "F", {{'F', "FF-[-F+F+F]+[+F-F-F]"}}, 4},
      {"abop_1_24d.l", "X", {{'X', "F[+X]F[-X]+X"}, {'F', "FF"}}, 7},
      {"abop_1_24e.l", "X", {{'X', "F[+X][-X]FX"}, {'F', "FF"}}, 7},
      {"abop_1_24f.l", "X", {{'X', "F-[[X]+X]+F[+FX]-X"}, {'F', "FF"}}, 5},
  };
  for (const Figure& f : figures) {
    const LSystem sys = parse_lsystem_file(example(f.file));
    EXPECT_EQ(sys.derivation_length, f.n) << f.file;
    int steps = 0;
    const ModuleString s = derive(sys, {}, &steps);
    EXPECT_EQ(steps, f.n);
    const auto got = counts(s, sys.symbols);
    const auto want = d0l_counts(f.axiom, f.rules, f.n);
    std::uint64_t total = 0;
    for (const auto& [sym, k] : want) {
      EXPECT_EQ(got.at(std::string(1, sym)), k) << f.file << " symbol " << sym;
      total += k;
    }
    EXPECT_EQ(s.size(), total) << f.file;
  }
}

TEST(LsystemDerivation, Abop124aClosedForm) {
  // F_n = 5^n; each F adds one [+F] and one [-F]: [ = ] = 2(5^n - 1)/4, + = - = (5^n - 1)/4.
  const LSystem sys = parse_lsystem_file(example("abop_1_24a.l"));
  for (int n : {0, 1, 3, 8}) {
    DeriveOptions o;
    o.steps = n;
    const auto c = counts(derive(sys, o), sys.symbols);
    const auto p5 = static_cast<std::uint64_t>(std::llround(std::pow(5.0, n)));
    EXPECT_EQ(c.at("F"), p5);
    if (n > 0) {
      EXPECT_EQ(c.at("["), (p5 - 1) / 2);
      EXPECT_EQ(c.at("]"), (p5 - 1) / 2);
      EXPECT_EQ(c.at("+"), (p5 - 1) / 4);
      EXPECT_EQ(c.at("-"), (p5 - 1) / 4);
    }
  }
}

TEST(LsystemDerivation, GreenLabCountsFollowClosedForms) {
  // B0 -> M0 [B1] B0, B1 -> M1 [B2] B1, B2 -> M2 B2 from B0: after n steps
  // B0 = 1, M0 = B1 = n, M1 = B2 = n(n-1)/2, M2 = n(n-1)(n-2)/6.
  const LSystem sys = parse_lsystem(
      "Axiom: B0\nB0 --> M0 [B1] B0\nB1 --> M1 [B2] B1\nB2 --> M2 B2\n", "greenlab.l");
  for (std::uint64_t n : {1u, 4u, 9u}) {
    DeriveOptions o;
    o.steps = static_cast<int>(n);
    const auto c = counts(derive(sys, o), sys.symbols);
    EXPECT_EQ(c.at("B0"), 1u);
    EXPECT_EQ(c.at("M0"), n);
    EXPECT_EQ(c.at("B1"), n);
    if (n >= 2) {
      EXPECT_EQ(c.at("M1"), n * (n - 1) / 2);
      EXPECT_EQ(c.at("B2"), n * (n - 1) / 2);
    }
    if (n >= 3) {
      EXPECT_EQ(c.at("M2"), n * (n - 1) * (n - 2) / 6);
    }
  }
  // The example file with geometry has the same module counts for B and M.
  const LSystem file = parse_lsystem_file(example("greenlab.l"));
  const auto c = counts(derive(file), file.symbols);
  EXPECT_EQ(c.at("M0"), 6u);
  EXPECT_EQ(c.at("M1"), 15u);
  EXPECT_EQ(c.at("M2"), 20u);
}

TEST(LsystemDerivation, ParametricExampleOfAbopSection1101) {
  // ABOP figure 1.31 (eq. 1.8): the published derivation of B(2)A(4,4).
  const std::string g =
      "Axiom: B(2)A(4,4)\n"
      "A(x,y) : y <= 3 --> A(x*2,x+y)\n"
      "A(x,y) : y > 3 --> B(x)A(x/y,0)\n"
      "B(x) : x < 1 --> C\n"
      "B(x) : x >= 1 --> B(x-1)\n";
  EXPECT_EQ(derived(g, 1), "B(1)B(4)A(1,0)");
  EXPECT_EQ(derived(g, 2), "B(0)B(3)A(2,1)");
  EXPECT_EQ(derived(g, 3), "CB(2)A(4,3)");
  EXPECT_EQ(derived(g, 4), "CB(1)A(8,7)");
  EXPECT_EQ(derived(g, 5), "CB(0)B(8)A(1.14286,0)");
}

TEST(LsystemDerivation, ParametricTreeMatchesGeometricSeries) {
  // A(s) -> F(s)[+A(s/R)][-A(s/R)]: after n steps 2^n apices of length R^-n and
  // 2^k segments of length R^-k for k < n.
  const LSystem sys = parse_lsystem_file(example("parametric_tree.l"));
  DeriveOptions o;
  o.steps = 6;
  const ModuleString s = derive(sys, o);
  std::map<int, int> f_by_level;
  int apices = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const std::string& name = sys.symbols.name(s.symbol(i));
    if (name == "A") {
      ++apices;
      EXPECT_NEAR(s.parameters(i)[0], std::pow(1.456, -6), 1e-12);
    } else if (name == "F") {
      ++f_by_level[static_cast<int>(std::lround(-std::log(s.parameters(i)[0]) / std::log(1.456)))];
    }
  }
  EXPECT_EQ(apices, 64);
  for (int k = 0; k < 6; ++k) EXPECT_EQ(f_by_level[k], 1 << k);
}

TEST(LsystemDerivation, SignalPropagatesOneModulePerStep) {
  const LSystem sys = parse_lsystem_file(example("signal_propagation.l"));
  for (int k = 0; k <= 8; ++k) {
    DeriveOptions o;
    o.steps = k;
    const std::string want = std::string(k, 'a') + "b" + std::string(8 - k, 'a');
    EXPECT_EQ(to_string(derive(sys, o), sys.symbols), want);
  }
}

TEST(LsystemDerivation, ContextMatchingIsBracketAware) {
  // Right context skips lateral branches; left context passes over ]..[ and through [.
  EXPECT_EQ(derived("Axiom: A[B]C\nA > C --> X\n", 1), "X[B]C");
  EXPECT_EQ(derived("Axiom: A[B]C\nA < C --> Y\n", 1), "A[B]Y");
  EXPECT_EQ(derived("Axiom: A[B]C\nA < B --> Z\n", 1), "A[Z]C");
  // The right context fails at ']' and at the end of the string.
  EXPECT_EQ(derived("Axiom: A[B]C\nB > C --> W\n", 1), "A[B]C");
  EXPECT_EQ(derived("Axiom: A[B]C\nC > A --> W\n", 1), "A[B]C");
  // Brackets in a right context: A > [B]C.
  EXPECT_EQ(derived("Axiom: A[B]C\nA > [B]C --> V\n", 1), "V[B]C");
  EXPECT_EQ(derived("Axiom: A[D]C\nA > [B]C --> V\n", 1), "A[D]C");
  // Ignored symbols are skipped both ways; consider: keeps only the listed ones.
  EXPECT_EQ(derived("ignore: +\nAxiom: A+B+C\nA < B > C --> X\n", 1), "A+X+C");
  EXPECT_EQ(derived("Axiom: A+B+C\nA < B > C --> X\n", 1), "A+B+C");
  EXPECT_EQ(derived("consider: ABC\nAxiom: A+-B&C\nA < B > C --> X\n", 1), "A+-X&C");
  // Context parameters bind.
  EXPECT_EQ(derived("Axiom: A(2)B(3)C(4)\nA(x) < B(y) > C(z) --> B(x+y+z)\n", 1), "A(2)B(9)C(4)");
}

TEST(LsystemDerivation, FirstMatchingProductionInFileOrderWins) {
  EXPECT_EQ(derived("Axiom: A(5)\nA(x) : x > 3 --> B\nA(x) : x > 1 --> C\nA(x) --> D\n", 1), "B");
  EXPECT_EQ(derived("Axiom: A(2)\nA(x) : x > 3 --> B\nA(x) : x > 1 --> C\nA(x) --> D\n", 1), "C");
  EXPECT_EQ(derived("Axiom: A(0)\nA(x) : x > 3 --> B\nA(x) : x > 1 --> C\nA(x) --> D\n", 1), "D");
  // Arity must match.
  EXPECT_EQ(derived("Axiom: A A(1)\nA --> X\nA(x) --> Y\n", 1), "XY");
  // Context-sensitive before context-free when listed first.
  EXPECT_EQ(derived("Axiom: BA\nB < A --> X\nA --> Y\n", 1), "BX");
}

TEST(LsystemDerivation, StochasticChoiceFollowsRelativeWeights) {
  std::string axiom(20000, 'A');
  const std::string g = "seed: 11\nAxiom: " + axiom + "\nA --> B : 1\nA --> C : 3\n";
  const LSystem sys = parse_lsystem(g);
  DeriveOptions o;
  o.steps = 1;
  const auto c = counts(derive(sys, o), sys.symbols);
  // Binomial(20000, 1/4): mean 5000, sd 61; 5 sd tolerance.
  EXPECT_NEAR(static_cast<double>(c.at("B")), 5000.0, 310.0);
  EXPECT_EQ(c.at("B") + c.at("C"), 20000u);
  // Same seed, same string; another seed, another string.
  EXPECT_EQ(derived(g, 1), derived(g, 1));
  const std::string g2 = "seed: 12\nAxiom: " + axiom + "\nA --> B : 1\nA --> C : 3\n";
  EXPECT_NE(derived(g, 1), derived(g2, 1));
  // A seed given in the options wins over the file's seed.
  DeriveOptions s12 = o;
  s12.seed = 12;
  EXPECT_EQ(to_string(derive(sys, s12), sys.symbols), derived(g2, 1));
}

TEST(LsystemDerivation, StochasticChoiceOnlyAmongMatchingProductions) {
  // x = 0: only the unconditioned C applies among the stochastic ones.
  std::string axiom;
  for (int i = 0; i < 200; ++i) axiom += "A(0)";
  const std::string s =
      derived("Axiom: " + axiom + "\nA(x) : x > 0 --> B : 5\nA(x) --> C : 1\n", 1);
  EXPECT_EQ(s.find('B'), std::string::npos);
}

TEST(LsystemDerivation, CutRemovesTheRestOfTheBranch) {
  EXPECT_EQ(derived("Axiom: A[BC%D[E]F]G%H\n", 0), "A[BC]G");
  EXPECT_EQ(derived("Axiom: A[BX]C\nX --> %\n", 1), "A[B]C");
}

TEST(LsystemDerivation, DecompositionRunsAfterEveryStepUpToItsDepth) {
  const std::string g = "Axiom: A\nA --> AS\ndecomposition\nmaximum depth: 5\nS --> TT\nT --> U\n";
  EXPECT_EQ(derived(g, 0), "A");
  EXPECT_EQ(derived(g, 1), "AUU");
  EXPECT_EQ(derived(g, 2), "AUUUU");
  // Depth 1: only one decomposition pass per step.
  const std::string shallow =
      "Axiom: A\nA --> AS\ndecomposition\nmaximum depth: 1\nS --> TT\nT --> U\n";
  EXPECT_EQ(derived(shallow, 1), "ATT");
}

TEST(LsystemDerivation, HomomorphismOnlyForInterpretation) {
  const LSystem sys =
      parse_lsystem("Axiom: A\nA --> AB\nhomomorphism\nmaximum depth: 3\nB --> F(2)\n");
  DeriveOptions o;
  o.steps = 2;
  Derivation d(sys, o);
  d.run();
  EXPECT_EQ(to_string(d.string(), sys.symbols), "ABB");
  EXPECT_EQ(to_string(d.interpretation_string(), sys.symbols), "AF(2)F(2)");
}

TEST(LsystemDerivation, StartEachAndGlobalsEvolve) {
  EXPECT_EQ(derived("define: { t = 0; }\nstartEach: { t = t + 1; }\nAxiom: A(0)\n"
                    "A(x) --> A(t)\n",
                    3),
            "A(3)");
}

TEST(LsystemDerivation, ModuleBudgetStopsExplodingGrammars) {
  const LSystem sys = parse_lsystem("Axiom: F\nF --> FF\n");
  DeriveOptions o;
  o.steps = 40;
  o.module_budget = 1000;
  try {
    derive(sys, o);
    FAIL() << "no error";
  } catch (const ValueError& e) {
    EXPECT_NE(e.message().find("budget"), std::string::npos);
  }
  const LSystem p = parse_lsystem("Axiom: F(1)\nF(x) --> F(x)F(x)\n");
  EXPECT_THROW(derive(p, o), ValueError);
}

TEST(LsystemDerivation, MemoryLimitStopsTheStringInBytes) {
  const test_support::ScopedMemoryLimit limit(std::uint64_t{1} << 20);
  const LSystem sys = parse_lsystem("Axiom: F\nF --> FF\n", "double.l");
  DeriveOptions o;
  o.steps = 40;
  // Step k writes 2^k modules of 2 bytes next to the 2^(k-1) it reads: 3 x 2^k bytes, first
  // above 2^20 at k = 19 (1.5 MiB), long before the module budget of 10^8.
  try {
    derive(sys, o);
    FAIL() << "no error";
  } catch (const MemoryLimitError& e) {
    EXPECT_EQ(e.file(), "double.l");
    EXPECT_EQ(e.message(),
              "the L-system string at derivation step 19 needs about 1.5 MiB, above the memory "
              "limit of 1 MiB (--memory-limit)");
  }
  o.steps = 18;
  EXPECT_EQ(derive(sys, o).size(), std::size_t{1} << 18);
}

TEST(LsystemDerivation, MemoryLimitCountsParametersToo) {
  const test_support::ScopedMemoryLimit limit(std::uint64_t{1} << 20);
  // 14 bytes per module (symbol, offset, one double): 2^16 modules (896 KiB) fit, 2^17 do not.
  const LSystem sys = parse_lsystem("Axiom: F(1)\nF(x) --> F(x)F(x+1)\n");
  DeriveOptions o;
  o.steps = 17;
  EXPECT_THROW(derive(sys, o), MemoryLimitError);
  o.steps = 15;
  const ModuleString s = derive(sys, o);
  ASSERT_EQ(s.size(), std::size_t{1} << 15);
  EXPECT_EQ(s.parameters(s.size() - 1)[0], 16.0);
}

TEST(LsystemDerivation, DivisionByZeroIsAValueError) {
  const LSystem sys = parse_lsystem("Axiom: A(0)\nA(x) --> A(1/x)\n", "div.l");
  DeriveOptions o;
  o.steps = 1;
  try {
    derive(sys, o);
    FAIL() << "no error";
  } catch (const ValueError& e) {
    EXPECT_EQ(e.file(), "div.l");
    EXPECT_EQ(e.line(), 2);
  }
}

TEST(LsystemDerivation, NegativeOrNanProbabilityIsAValueErrorAtTheProduction) {
  for (const char* weight : {"-0.5", "0/0 + 1", "sqrt(-1)"}) {
    const LSystem sys =
        parse_lsystem(std::string("Axiom: A\nA --> B : 1\nA --> C : ") + weight + "\n", "p.l");
    DeriveOptions o;
    o.steps = 1;
    try {
      derive(sys, o);
      FAIL() << weight;
    } catch (const ValueError& e) {
      EXPECT_EQ(e.line(), 3) << e.what();
    }
  }
}

TEST(LsystemDerivation, FastAndGenericPathsAgree) {
  // A condition (always true) forces the generic path; both paths must give the same string.
  const std::string fast = derived("Axiom: X\nX --> F-[[X]+X]+F[+FX]-X\nF --> FF\n", 4);
  const std::string generic = derived("Axiom: X\nX : 1 --> F-[[X]+X]+F[+FX]-X\nF : 1 --> FF\n", 4);
  EXPECT_EQ(fast, generic);
}

TEST(LsystemDerivation, MonopodialTreeHasOneApexAndGeometricLengths) {
  const LSystem sys = parse_lsystem_file(example("monopodial_tree.l"));
  const ModuleString s = derive(sys);
  int apices = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (sys.symbols.name(s.symbol(i)) != "A") continue;
    ++apices;
    EXPECT_NEAR(s.parameters(i)[0], std::pow(0.9, 10), 1e-12);
    EXPECT_NEAR(s.parameters(i)[1], 10 * std::pow(0.707, 10), 1e-9);
  }
  EXPECT_EQ(apices, 1);
  // Every apex (A, B, C) makes one F per step and one new apex per F after the first step:
  // apex count doubles each step, F count = 2^n - 1.
  const auto c = counts(s, sys.symbols);
  EXPECT_EQ(c.at("F"), (1u << 10) - 1);
  EXPECT_EQ(c.at("A") + c.at("B") + c.at("C"), 1u << 10);
}

}  // namespace
}  // namespace fspm::lsystem
