// Derivation into substructures against two independent oracles: the explicit derivation
// (module by module, for every context-free example at every n whose string fits) and closed
// forms of the module counts at n far beyond any explicit string.
#include "lsystem/substructure_derivation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "fspm/error.hpp"
#include "lsystem/parser.hpp"

namespace fspm::lsystem {
namespace {

std::string example(const std::string& name) {
  return std::string(FSPM_SOURCE_DIR) + "/examples/lsystems/" + name;
}

SubstructureGraph graph_of(const LSystem& sys, int steps) {
  DeriveOptions options;
  options.steps = steps;
  return derive_substructures(sys, options);
}

// Same symbols and bit-identical parameters.
void expect_same_string(const ModuleString& a, const ModuleString& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  ASSERT_EQ(a.symbols(), b.symbols()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto pa = a.parameters(i), pb = b.parameters(i);
    ASSERT_EQ(pa.size(), pb.size()) << what << " module " << i;
    if (!pa.empty()) {
      ASSERT_EQ(std::memcmp(pa.data(), pb.data(), pa.size_bytes()), 0) << what;
    }
  }
}

TEST(SubstructureDerivation, EveryContextFreeExampleExpandsToTheExplicitString) {
  constexpr std::size_t kFits = 300'000;  // explicit strings compared up to this size
  int compared = 0;
  for (const auto& entry : std::filesystem::directory_iterator(example(""))) {
    if (entry.path().extension() != ".l") continue;
    const LSystem sys = parse_lsystem_file(entry.path().string());
    if (factorization_obstacle(sys)) continue;
    for (int n = 0; n <= 40; ++n) {
      DeriveOptions options;
      options.steps = n;
      options.module_budget = kFits;
      ModuleString explicit_string;
      try {
        explicit_string = derive(sys, options);
      } catch (const ValueError&) {
        break;  // past kFits modules
      }
      const SubstructureGraph g = graph_of(sys, n);
      const std::string what = entry.path().filename().string() + " n=" + std::to_string(n);
      expect_same_string(expand(g, kFits), explicit_string, what);
      const SubstructureCounts c = count_modules(g, sys.symbols.size());
      EXPECT_EQ(c.modules, explicit_string.size()) << what;
      std::vector<std::uint64_t> per_symbol(sys.symbols.size(), 0);
      for (const SymbolId s : explicit_string.symbols()) ++per_symbol[s];
      EXPECT_EQ(c.per_symbol, per_symbol) << what;
      ++compared;
    }
  }
  // Figures 1.24a-f, the monopodial and parametric trees, leafy shoot and GreenLab grammar.
  EXPECT_GE(compared, 60);
}

// ABOP Fig. 1.24a, F -> F[+F]F[-F]F from F: after n steps 5^n F, every F of the n - 1 steps
// before left two [ and ] and one + and -; the graph holds one substructure per F and remaining
// steps, and one leaf per other module.
TEST(SubstructureDerivation, Figure124aAtTwentyStepsMatchesItsClosedForm) {
  const LSystem sys = parse_lsystem_file(example("abop_1_24a.l"));
  const SubstructureGraph g = graph_of(sys, 20);
  const SubstructureCounts c = count_modules(g, sys.symbols.size());
  std::uint64_t five_n = 1;
  for (int k = 0; k < 20; ++k) five_n *= 5;
  EXPECT_EQ(c.per_symbol[sys.symbols.find("F")], five_n);
  const std::uint64_t earlier_f = (five_n - 1) / 4;  // 1 + 5 + ... + 5^19
  for (const char* s : {"[", "]"}) EXPECT_EQ(c.per_symbol[sys.symbols.find(s)], 2 * earlier_f);
  for (const char* s : {"+", "-"}) EXPECT_EQ(c.per_symbol[sys.symbols.find(s)], earlier_f);
  EXPECT_EQ(c.modules, five_n + 6 * earlier_f);
  EXPECT_LE(g.nodes.size(), 21u + 4u);  // F at 0..20 remaining steps, and the four leaves
  EXPECT_EQ(c.explicit_bytes, 2 * c.modules);
}

// ABOP eq. 1.9, A(s) -> F(s)[+A(s/R)][-A(s/R)] from A(1): after n steps 2^n apices, 2^n - 1
// segments, the apices' lengths R^-n; one substructure per level.
TEST(SubstructureDerivation, ParametricTreeAtFortyStepsMatchesItsClosedForm) {
  const LSystem sys = parse_lsystem_file(example("parametric_tree.l"));
  const SubstructureGraph g = graph_of(sys, 40);
  const SubstructureCounts c = count_modules(g, sys.symbols.size());
  const std::uint64_t two_n = std::uint64_t{1} << 40;
  EXPECT_EQ(c.per_symbol[sys.symbols.find("A")], two_n);
  EXPECT_EQ(c.per_symbol[sys.symbols.find("F")], two_n - 1);
  EXPECT_LE(g.nodes.size(), 41u + 40u + 4u);  // A per level, F(s) per length, [ ] + -
  // The deepest apex: s = 1 / R^40, with R = 1.456 divided 40 times.
  double s = 1.0;
  for (int k = 0; k < 40; ++k) s /= 1.456;
  bool found = false;
  for (const Substructure& n : g.nodes) {
    if (n.symbol == sys.symbols.find("A") && n.leaf()) {
      found = found || g.parameters[n.parameter_begin] == s;
    }
  }
  EXPECT_TRUE(found);
}

TEST(SubstructureDerivation, GrammarsThatDependOnPlaceOrTimeAreRefusedWithTheReason) {
  const auto obstacle = [](const std::string& text) {
    return factorization_obstacle(parse_lsystem(text, "t.l")).value_or("");
  };
  EXPECT_NE(obstacle("Lsystem: 1\nAxiom: A B\nA < B --> C\nendlsystem\n").find("context-sensitive"),
            std::string::npos);
  EXPECT_NE(obstacle("Lsystem: 1\nAxiom: A\nA --> A B : 0.5\nA --> B : 0.5\nendlsystem\n")
                .find("stochastic"),
            std::string::npos);
  EXPECT_NE(obstacle("Lsystem: 1\nAxiom: A(0)\nA(x) --> A(ran(1))\nendlsystem\n").find("ran()"),
            std::string::npos);
  EXPECT_EQ(obstacle("Lsystem: 1\nAxiom: A(0)\nA(x) : 1 {y = x + 1;} --> A(y)\nendlsystem\n"), "");
  const LSystem sensitive = parse_lsystem_file(example("context_sensitive_plant.l"));
  EXPECT_THROW(derive_substructures(sensitive), ValueError);
}

TEST(SubstructureDerivation, BudgetsBoundTheGraphAndTheExpansion) {
  const LSystem sys = parse_lsystem_file(example("abop_1_24a.l"));
  DeriveOptions options;
  options.steps = 12;
  options.module_budget = 5;
  EXPECT_THROW(derive_substructures(sys, options), ValueError);
  EXPECT_THROW(expand(graph_of(sys, 12), 1000), ValueError);
}

}  // namespace
}  // namespace fspm::lsystem
