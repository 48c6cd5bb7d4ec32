#include "fspm/memory_budget.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "fspm/error.hpp"
#include "fspm/memory_account.hpp"

namespace fspm {
namespace {

constexpr std::uint64_t kFallbackLimit = std::uint64_t{4} << 30;
// Largest limit accepted: far above any machine, and exactly representable as a double.
constexpr double kMaxLimit = 0x1.0p62;

std::atomic<std::uint64_t> g_limit{0};  // 0: the default

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

// Multiplier of a unit suffix, or 0 when it is not one.
double unit_factor(const std::string& unit) {
  if (unit.empty() || unit == "b") return 1.0;
  static constexpr const char* kUnits[] = {"k", "m", "g", "t"};
  for (int i = 0; i < 4; ++i) {
    const std::string u = kUnits[i];
    if (unit == u || unit == u + "b" || unit == u + "ib") return std::ldexp(1.0, 10 * (i + 1));
  }
  return 0.0;
}

}  // namespace

// The memory this process may really use: the physical memory, or less where a resource limit
// (ulimit -v, -d) or the control group (a container, a batch job's cgroup) allows less.
std::uint64_t usable_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGE_SIZE);
  std::uint64_t usable = pages > 0 && page_size > 0 ? static_cast<std::uint64_t>(pages) *
                                                          static_cast<std::uint64_t>(page_size)
                                                    : 2 * kFallbackLimit;
  for (int resource : {RLIMIT_AS, RLIMIT_DATA}) {
    struct rlimit r {};
    if (::getrlimit(resource, &r) == 0 && r.rlim_cur != RLIM_INFINITY) {
      usable = std::min<std::uint64_t>(usable, r.rlim_cur);
    }
  }
  // cgroup v2, then v1; "max" or an absurd v1 value means no limit.
  for (const char* path :
       {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"}) {
    if (std::FILE* f = std::fopen(path, "r")) {
      unsigned long long v = 0;
      if (std::fscanf(f, "%llu", &v) == 1 && v > 0) usable = std::min<std::uint64_t>(usable, v);
      std::fclose(f);
    }
  }
  return usable;
}

std::uint64_t default_memory_limit_bytes() { return usable_memory_bytes() / 2; }

std::uint64_t memory_limit_bytes() {
  const std::uint64_t set = g_limit.load(std::memory_order_relaxed);
  if (set != 0) return set;
  static const std::uint64_t kDefault = default_memory_limit_bytes();
  return kDefault;
}

void set_memory_limit_bytes(std::uint64_t bytes) {
  g_limit.store(bytes, std::memory_order_relaxed);
}

std::string memory_text(double bytes) {
  if (!(bytes < 0x1.0p80)) return "more than 1 YiB";
  static constexpr const char* kUnits[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB", "ZiB"};
  if (bytes < 1024.0) return std::to_string(static_cast<long long>(bytes)) + " bytes";
  int unit = -1;
  while (bytes >= 1024.0 && unit < 6) {
    bytes /= 1024.0;
    ++unit;
  }
  char text[32];
  // Whole numbers without a decimal ("2 GiB"), others with one ("3.2 GiB").
  if (std::abs(bytes - std::round(bytes)) < 0.05) {
    std::snprintf(text, sizeof text, "%.0f %s", std::round(bytes), kUnits[unit]);
  } else {
    std::snprintf(text, sizeof text, "%.1f %s", bytes, kUnits[unit]);
  }
  return text;
}

namespace {

// Three significant digits in the unit memory_text chooses ("1.04 GiB").
std::string precise_memory_text(double bytes) {
  static constexpr const char* kUnits[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  int unit = 0;
  while (bytes >= 1024.0 && unit < 6) bytes /= 1024.0, ++unit;
  char text[32];
  std::snprintf(text, sizeof text, "%.3g %s", bytes, kUnits[unit]);
  return text;
}

}  // namespace

void check_memory(double bytes, std::string_view what, const std::string& file) {
  const auto limit = static_cast<double>(memory_limit_bytes());
  if (bytes <= limit) {  // false for NaN: an overflowed estimate fails too
    // A job of several (fspm/memory_account.hpp) takes its share of the one limit.
    if (bytes > 0) {
      MemoryAccount::reserve_on_this_thread(static_cast<std::uint64_t>(std::ceil(bytes)), what,
                                            file);
    }
    return;
  }
  std::string need = memory_text(bytes);
  // Just above the limit both may round alike ("1 GiB, above the memory limit of 1 GiB").
  if (need == memory_text(limit)) need = precise_memory_text(bytes);
  throw MemoryLimitError(std::string(what) + " needs about " + need +
                             ", above the memory limit of " + memory_text(limit) +
                             " (--memory-limit)",
                         file);
}

std::uint64_t parse_memory_size(std::string_view text, std::string_view what) {
  const auto fail = [&]() -> std::uint64_t {
    throw ValueError(std::string(what) + ": expected a size such as 512M or 2G, got '" +
                     std::string(text.substr(0, 40)) + "'");
  };
  double number = 0.0;
  const char* end = text.data() + text.size();
  const auto [rest, ec] = std::from_chars(text.data(), end, number);
  if (ec != std::errc() || rest == text.data()) return fail();
  const double factor = unit_factor(lower(std::string_view(rest, end)));
  const double bytes = number * factor;
  if (factor == 0.0 || !(bytes >= 1.0) || !(bytes <= kMaxLimit)) return fail();
  return static_cast<std::uint64_t>(bytes);
}

}  // namespace fspm
