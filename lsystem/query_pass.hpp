#pragma once
// Open L-systems (Mech and Prusinkiewicz 1996): after each derivation step a turtle pass fills
// the query modules ?P(x,y,z), ?H(x,y,z), ?U(x,y,z), ?L(x,y,z) with the turtle's position and
// orientation at that point of the string, and hands every communication module ?E(...) to the
// environment. The turtle walks `drawn` (the derived string with the homomorphism applied) when
// given and when it holds the same query modules in the same order, else `s` itself.
#include "lsystem/lsystem.hpp"
#include "lsystem/module_string.hpp"
#include "lsystem/open_environment.hpp"

namespace fspm::lsystem {

struct TurtleSettings;

void fill_query_modules(const LSystem& system, ModuleString& s, const TurtleSettings& settings,
                        OpenEnvironment* environment, const ModuleString* drawn = nullptr);

}  // namespace fspm::lsystem
