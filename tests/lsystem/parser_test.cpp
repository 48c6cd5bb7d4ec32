#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "fspm/error.hpp"
#include "lsystem/derivation.hpp"
#include "lsystem/parser.hpp"
#include "lsystem/preprocessor.hpp"

namespace fspm::lsystem {
namespace {

std::string derived(const std::string& text, int steps = -1, const MacroOverrides& defines = {}) {
  const LSystem sys = parse_lsystem(text, "test.l", defines);
  DeriveOptions options;
  if (steps >= 0) options.steps = steps;
  return to_string(derive(sys, options), sys.symbols);
}

// The value of a constant expression, through a one-module axiom A(expr).
double value(const std::string& expr) {
  const std::string s = derived("Axiom: A(" + expr + ")\n", 0);
  return std::stod(s.substr(2, s.size() - 3));
}

TEST(LsystemParser, HeadersAreCaseInsensitive) {
  const LSystem sys = parse_lsystem(
      "LSYSTEM: 3\nSeed: 42\nDerivation Length: 7\nMAXIMUM DEPTH: 4\naxiom: F\nF --> FF\n"
      "ENDLSYSTEM\n");
  EXPECT_EQ(sys.number, 3);
  ASSERT_TRUE(sys.seed.has_value());
  EXPECT_EQ(*sys.seed, 42u);
  EXPECT_EQ(sys.derivation_length, 7);
  EXPECT_EQ(sys.maximum_depth, 4);
  EXPECT_EQ(sys.productions.productions.size(), 1u);
}

TEST(LsystemParser, EverythingAfterEndlsystemIsIgnored) {
  EXPECT_EQ(derived("Axiom: A\nA --> B\nendlsystem\nthis is not a production\n", 1), "B");
}

TEST(LsystemParser, ProductionPartsAreOptional) {
  const LSystem sys = parse_lsystem(
      "Axiom: A(1)\nB < A(x) > C : x > 0 --> D(x) : 0.5\n* < A(x) > * : * --> E\nA(x) -> G\n");
  ASSERT_EQ(sys.productions.productions.size(), 3u);
  const Production& p = sys.productions.productions[0];
  EXPECT_EQ(p.left.size(), 1u);
  EXPECT_EQ(p.right.size(), 1u);
  EXPECT_FALSE(p.condition.empty());
  EXPECT_FALSE(p.probability.empty());
  const Production& q = sys.productions.productions[1];
  EXPECT_TRUE(q.left.empty());
  EXPECT_TRUE(q.right.empty());
  EXPECT_TRUE(q.condition.empty());
  EXPECT_TRUE(q.probability.empty());
}

TEST(LsystemParser, EmptySuccessorStarErases) {
  EXPECT_EQ(derived("Axiom: ABA\nA --> *\n", 1), "B");
  EXPECT_EQ(derived("Axiom: ABA\nA -->\n", 1), "B");
}

TEST(LsystemParser, ExpressionsFollowCPrecedence) {
  EXPECT_DOUBLE_EQ(value("1+2*3"), 7.0);
  EXPECT_DOUBLE_EQ(value("(1+2)*3"), 9.0);
  EXPECT_DOUBLE_EQ(value("2^3^2"), 512.0);
  EXPECT_DOUBLE_EQ(value("-2^2"), -4.0);
  EXPECT_DOUBLE_EQ(value("7%4"), 3.0);
  EXPECT_DOUBLE_EQ(value("1<2 && 3>=3"), 1.0);
  EXPECT_DOUBLE_EQ(value("1>2 || 0"), 0.0);
  EXPECT_DOUBLE_EQ(value("!0 == 1"), 1.0);
  EXPECT_DOUBLE_EQ(value("2 > 1 ? 10 : 20"), 10.0);
  EXPECT_DOUBLE_EQ(value("1 != 1 ? 10 : 20"), 20.0);
}

TEST(LsystemParser, FunctionsUseDegreesLikeCpfg) {
  EXPECT_NEAR(value("sin(30)"), 0.5, 1e-6);
  EXPECT_NEAR(value("cos(60)"), 0.5, 1e-6);
  EXPECT_NEAR(value("tan(45)"), 1.0, 1e-6);
  EXPECT_NEAR(value("asin(1)"), 90.0, 1e-4);
  EXPECT_NEAR(value("acos(0)"), 90.0, 1e-4);
  EXPECT_NEAR(value("atan(1)"), 45.0, 1e-4);
  EXPECT_NEAR(value("atan2(1,1)"), 45.0, 1e-4);
  EXPECT_NEAR(value("sqrt(2)"), std::sqrt(2.0), 1e-5);
  EXPECT_NEAR(value("exp(1)"), std::exp(1.0), 1e-5);
  EXPECT_NEAR(value("log(10)"), std::log(10.0), 1e-5);
  EXPECT_DOUBLE_EQ(value("pow(2,10)"), 1024.0);
  EXPECT_DOUBLE_EQ(value("floor(-1.5)"), -2.0);
  EXPECT_DOUBLE_EQ(value("ceil(1.2)"), 2.0);
  EXPECT_DOUBLE_EQ(value("fabs(-3)"), 3.0);
  EXPECT_DOUBLE_EQ(value("abs(-4)"), 4.0);
  EXPECT_DOUBLE_EQ(value("min(3,4)"), 3.0);
  EXPECT_DOUBLE_EQ(value("max(3,4)"), 4.0);
}

TEST(LsystemParser, RanIsSeededAndInRange) {
  const std::string grammar = "seed: 5\nAxiom: A(0)\nA(x) --> A(ran(2))B(ran(2))\n";
  const std::string a = derived(grammar, 3);
  EXPECT_EQ(a, derived(grammar, 3));
  EXPECT_NE(a, derived("seed: 6\nAxiom: A(0)\nA(x) --> A(ran(2))B(ran(2))\n", 3));
  const LSystem sys = parse_lsystem("seed: 9\nAxiom: A(0)\nA(x) --> A(ran(2))B(ran(2))\n");
  DeriveOptions o;
  o.steps = 200;
  const ModuleString s = derive(sys, o);
  for (double v : s.pool()) {
    EXPECT_GE(v, 0.0);
    EXPECT_LT(v, 2.0);
  }
}

TEST(LsystemParser, DefineBlockSetsGlobals) {
  EXPECT_EQ(derived("define: { a = 2; b = a * 3; }\nAxiom: A(b)\n", 0), "A(6)");
  EXPECT_EQ(derived("define: {\n  a = 1;\n  b = 2;\n}\nAxiom: A(a+b)\n", 0), "A(3)");
}

TEST(LsystemParser, BlocksHaveIfElseAndWhile) {
  EXPECT_EQ(
      derived("define: {\n  n = 0; i = 0;\n  while (i < 5) { n = n + i; i = i + 1; }\n"
              "  if (n == 10) { r = 1; } else { r = 2; }\n  if (n > 100) q = 1; else q = 3;\n}\n"
              "Axiom: A(n,r,q)\n",
              0),
      "A(10,1,3)");
  const LSystem forever = parse_lsystem("define: { while (1) { x = 1; } }\nAxiom: A\n");
  EXPECT_THROW(derive(forever), ValueError);
  EXPECT_THROW(parse_lsystem("define: { if 1 { x = 1; } }\nAxiom: A\n"), ParseError);
}

TEST(LsystemParser, ConditionBlocksAssignLocals) {
  EXPECT_EQ(derived("Axiom: A(2)\nA(x) : {y = x * 10;} y > 5 --> B(y)\n", 1), "B(20)");
}

TEST(LsystemParser, SyntaxErrorsNameFileLineColumn) {
  try {
    parse_lsystem("Axiom: F\nF FF\n", "bad.l");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "bad.l");
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.column(), 1);
    EXPECT_NE(std::string(e.what()).find("expected"), std::string::npos);
  }
  try {
    parse_lsystem("Axiom: A(1)\nA(x) --> B(x +)\n", "bad.l");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.column(), 15);
  }
  try {
    parse_lsystem("Axiom: A(1)\nA(x) --> B(y)\n", "bad.l");
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.column(), 12);
    EXPECT_NE(e.message().find("undefined parameter"), std::string::npos);
  }
  EXPECT_THROW(parse_lsystem("Axiom: A(1)\nA(x) --> B(foo(x))\n"), ParseError);
  EXPECT_THROW(parse_lsystem("A --> B\n"), ParseError);  // no axiom
  EXPECT_THROW(parse_lsystem("Axiom: A(1\n"), ParseError);
  EXPECT_THROW(parse_lsystem("Axiom: A\nA B --> C\n"), ParseError);
  EXPECT_THROW(parse_lsystem("define: { a = 1;\nAxiom: A\n"), ParseError);
}

TEST(LsystemParser, PreprocessorMacros) {
  EXPECT_EQ(derived("#define N 3\n#define SQ(x) ((x)*(x))\nAxiom: A(SQ(N+1))\n", 0), "A(16)");
  // cpp tokens: FX is one identifier, X alone is expanded.
  EXPECT_EQ(derived("#define X Y\nAxiom: FX X\n", 0), "FXY");
  EXPECT_EQ(derived("/* comment\n over lines */ Axiom: A // tail\n", 0), "A");
  EXPECT_EQ(derived("#define A_LONG 1 + \\\n 2\nAxiom: A(A_LONG)\n", 0), "A(3)");
  EXPECT_EQ(derived("#define R 2\nAxiom: A(R)\n", 0, {{"R", "5"}}), "A(5)");
}

TEST(LsystemParser, PreprocessorConditionals) {
  const std::string text =
      "#define TALL 1\n#ifdef TALL\nAxiom: T\n#else\nAxiom: S\n#endif\n"
      "#ifndef TALL\nT --> X\n#elif TALL > 0\nT --> Y\n#endif\n"
      "#if defined(SHORT) || 0\nT --> Z\n#endif\n";
  EXPECT_EQ(derived(text, 1), "Y");
  EXPECT_EQ(derived(text, 1, {{"SHORT", "1"}}), "Y");  // first matching production wins
  EXPECT_THROW(parse_lsystem("#if 1\nAxiom: A\n"), ParseError);
  EXPECT_THROW(parse_lsystem("#endif\nAxiom: A\n"), ParseError);
  EXPECT_THROW(parse_lsystem("#frobnicate\nAxiom: A\n"), ParseError);
}

TEST(LsystemParser, IncludeIsRelativeToTheFileAndKeepsLines) {
  const auto dir = std::filesystem::temp_directory_path() / "fspm_lsystem_include_test";
  std::filesystem::create_directories(dir);
  {
    std::ofstream(dir / "params.h") << "#define LEN 2.5\n#define BAD\n";
    std::ofstream(dir / "main.l") << "#include \"params.h\"\nAxiom: F(LEN)\n";
    std::ofstream(dir / "broken.h") << "\n\nF --> F(1 +)\n";
    std::ofstream(dir / "broken.l") << "Axiom: F\n#include \"broken.h\"\n";
  }
  const LSystem sys = parse_lsystem_file((dir / "main.l").string());
  EXPECT_EQ(to_string(derive(sys), sys.symbols), "F(2.5)");
  try {
    parse_lsystem_file((dir / "broken.l").string());
    FAIL() << "no error";
  } catch (const ParseError& e) {
    EXPECT_NE(e.file().find("broken.h"), std::string::npos) << e.what();
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.column(), 12);
  }
  EXPECT_THROW(parse_lsystem("#include \"missing.h\"\nAxiom: A\n"), IoError);
  EXPECT_THROW(parse_lsystem_file((dir / "nope.l").string()), IoError);
  std::filesystem::remove_all(dir);
}

TEST(LsystemParser, AbopStyleIgnoreDirective) {
  EXPECT_EQ(derived("#ignore: +\nAxiom: A+B\nA < B --> X\n", 1), "A+X");
}

TEST(LsystemParser, NumberedModuleNamesOnlyForGreenLabStyleFiles) {
  // cpfg: F1F1 is four modules.
  const LSystem cpfg = parse_lsystem("Axiom: F1F1\n1 --> 0\n");
  EXPECT_EQ(derive(cpfg).size(), 4u);
  // GreenLab: B0 is one module because a predecessor is written that way.
  const LSystem gl = parse_lsystem("Axiom: B0\nB0 --> M0 [B1] B0\n");
  DeriveOptions o;
  o.steps = 1;
  const ModuleString s = derive(gl, o);
  EXPECT_EQ(s.size(), 5u);
  EXPECT_EQ(to_string(s, gl.symbols), "M0[B1]B0");
}

TEST(LsystemParser, BracketsBalanceInAxiomsAndSuccessors) {
  const auto error_at = [](const std::string& text) {
    try {
      parse_lsystem(text, "b.l");
    } catch (const ParseError& e) {
      return std::to_string(e.line()) + ":" + std::to_string(e.column()) + " " + e.message();
    }
    return std::string("no error");
  };
  EXPECT_EQ(error_at("Axiom: F]F\n"), "1:9 ']' without a matching '['");
  EXPECT_EQ(error_at("Axiom: F\nF --> F[+F[-F]\n"), "2:8 this '[' is never closed by a ']'");
  EXPECT_EQ(error_at("Axiom: F[[F]F]\nF --> F[+F][-F]\n"), "no error");
  EXPECT_EQ(error_at("Axiom: " + std::string(1000001, '[') + std::string(1000001, ']') + "\n"),
            "1:1000008 nesting deeper than the limit of 1000000 levels (branches '[')");
  EXPECT_EQ(error_at("derivation length: 2e9\nAxiom: F\n"),
            "1:19 derivation length must be an integer in [0, 1000000000]");
}

TEST(LsystemParser, OverrideOfAnUnusedNameIsRefusedWithTheClosestDefine) {
  const std::string text = "#define LEN 2\n#ifdef DEBUG\n#endif\nAxiom: F(LEN)\n";
  EXPECT_EQ(derived(text, 0, {{"LEN", "3"}}), "F(3)");
  EXPECT_NO_THROW(parse_lsystem(text, "o.l", {{"DEBUG", "1"}}));  // tested by #ifdef: used
  try {
    parse_lsystem(text, "o.l", {{"LNE", "3"}});
    FAIL() << "no error";
  } catch (const ValueError& e) {
    EXPECT_EQ(std::string(e.what()),
              "o.l: cannot override the macro 'LNE': the L-system never uses it (did you mean "
              "'LEN'?)");
  }
}

}  // namespace
}  // namespace fspm::lsystem
