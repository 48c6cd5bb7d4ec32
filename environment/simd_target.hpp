#pragma once
// Which vector instruction set the SIMD kernels run (Google Highway's runtime dispatch). By
// default the best the processor has; the environment variable FSPM_SIMD_TARGET, read before the
// first kernel call, or set_simd_target forces one, to compare targets or to avoid one.
#include <string>
#include <string_view>
#include <vector>

namespace fspm::environment {

// The targets compiled in and supported by this processor, best first, by Highway's names in
// lower case: "avx3", "avx2", "sse4", "ssse3", and "scalar" (Highway's portable code without vector
// instructions; "emu128" in builds where Highway emulates four lanes instead).
std::vector<std::string> simd_targets();

// Forces the kernels onto one target of simd_targets(), names ignoring case; "scalar" and "emu128"
// both name the portable one, and "" or "best" returns to the best. Throws ValueError for a name
// that is not available here. Call it before kernels run on other threads: the choice is global.
void set_simd_target(std::string_view name);

// Applies FSPM_SIMD_TARGET once, unless set_simd_target was called first; the kernels call it
// before dispatching. Throws ValueError for a value set_simd_target would reject.
void settle_simd_target();

}  // namespace fspm::environment
