#include "environment/simd_target.hpp"

#include "fspm/error.hpp"

#include <hwy/targets.h>

#include <atomic>
#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <mutex>

namespace fspm::environment {
namespace {

constexpr const char* kEnvironmentVariable = "FSPM_SIMD_TARGET";

std::mutex& target_mutex() {
  static std::mutex m;
  return m;
}
std::atomic<bool>& settled() {
  static std::atomic<bool> yes{false};
  return yes;
}
// The target bits dispatch is restricted to; 0: every supported target (guarded by the mutex).
std::int64_t& forced_bits() {
  static std::int64_t bits = 0;
  return bits;
}

// Restricts dispatch to `bits` (0: every supported target); the next dispatched call re-chooses.
void force(std::int64_t bits) {
  forced_bits() = bits;
  hwy::SetSupportedTargetsForTest(bits);
  hwy::GetChosenTarget().Update(hwy::SupportedTargets());
}

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// The processor's real targets: a forced target narrows what Highway reports, so the restriction
// is lifted while asking and put back after (the caller holds the mutex).
std::vector<std::int64_t> real_targets() {
  const std::int64_t kept = forced_bits();
  force(0);
  std::vector<std::int64_t> out = hwy::SupportedAndGeneratedTargets();
  force(kept);
  return out;
}

// Highway's portable code without vector instructions: "scalar" (one lane) or, where the compiler
// allows it, "emu128" (four emulated lanes); either name selects whichever is built.
bool is_portable(std::string_view name) { return name == "scalar" || name == "emu128"; }

// Highway's target bit for `name`, or a ValueError naming `source` and the choices.
std::int64_t target_bit(std::string_view name, std::string_view source) {
  const std::string wanted = lower(name);
  std::string choices;
  for (const std::int64_t t : real_targets()) {
    const std::string n = lower(hwy::TargetName(t));
    if (n == wanted || (is_portable(n) && is_portable(wanted))) return t;
    choices += (choices.empty() ? "" : ", ") + n;
  }
  throw ValueError(std::string(source) + ": unknown or unsupported SIMD target '" +
                   std::string(name) + "', expected best or one of: " + choices);
}

bool is_best(std::string_view name) { return name.empty() || lower(name) == "best"; }

}  // namespace

std::vector<std::string> simd_targets() {
  std::lock_guard lock(target_mutex());
  std::vector<std::string> out;
  for (const std::int64_t t : real_targets()) out.push_back(lower(hwy::TargetName(t)));
  return out;
}

void set_simd_target(std::string_view name) {
  std::lock_guard lock(target_mutex());
  force(is_best(name) ? 0 : target_bit(name, "set_simd_target"));
  settled().store(true, std::memory_order_release);
}

void settle_simd_target() {
  if (settled().load(std::memory_order_acquire)) return;
  std::lock_guard lock(target_mutex());
  if (settled().load(std::memory_order_relaxed)) return;
  const char* value = std::getenv(kEnvironmentVariable);
  if (value != nullptr && !is_best(value)) force(target_bit(value, kEnvironmentVariable));
  settled().store(true, std::memory_order_release);
}

}  // namespace fspm::environment
