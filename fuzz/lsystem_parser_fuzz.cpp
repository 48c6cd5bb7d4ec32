// libFuzzer target: arbitrary bytes as a cpfg L-system file. Parsing, a short derivation with a
// small module budget and the turtle interpretation must either succeed or throw fspm::Error;
// anything else (crash, sanitizer report, other exception) is a bug.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fspm/error.hpp"
#include "lsystem/derivation.hpp"
#include "lsystem/parser.hpp"
#include "lsystem/turtle.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    // Includes resolve in a directory that does not exist, so inputs never read real files.
    const fspm::lsystem::LSystem sys =
        fspm::lsystem::parse_lsystem(text, "fuzz.l", {}, "/nonexistent-fspm-fuzz");
    fspm::lsystem::DeriveOptions options;
    options.steps = std::min(sys.derivation_length, 6);
    options.module_budget = 20000;
    fspm::lsystem::Derivation derivation(sys, options);
    derivation.run();
    const fspm::lsystem::ModuleString s = derivation.interpretation_string();
    if (s.size() <= 20000) fspm::lsystem::interpret(s, sys.symbols);
  } catch (const fspm::Error&) {
    // Expected for malformed input.
  }
  return 0;
}
