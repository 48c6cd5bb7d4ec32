#pragma once
// A p value for people, as journals print it: two significant digits down to 0.001, below it
// "p < 0.001" (APA style). Machine outputs (CSV, JSON, SQLite) keep the exact value; this is for
// every printed line, table and sentence, so a p of 3e-15 never reads as "p = 0".
#include <string>

namespace fspm {

// "p = 0.034", "p = 0.0016", "p < 0.001"; "p undefined" for NaN (a test of two constant groups).
std::string format_p_value(double p);

}  // namespace fspm
