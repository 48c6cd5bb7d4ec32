#pragma once
// Which vector instructions the processor runs, asked once: the light kernels pick their
// 16-lane AVX-512 paths at run time, so one binary serves every x86-64 machine.

namespace fspm::environment {

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
inline bool has_avx512() {
  static const bool yes = __builtin_cpu_supports("avx512f");
  return yes;
}
#else
inline bool has_avx512() { return false; }
#endif

}  // namespace fspm::environment
