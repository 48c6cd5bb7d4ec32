#include "fspm/signal_cleanup.hpp"

#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>

namespace fspm {
namespace {

constexpr std::size_t kSlots = 256;
constexpr std::size_t kPathBytes = 4096;

// States of a slot: free, being written by register_signal_cleanup, or holding a path.
enum : int { kFree = 0, kWriting = 1, kHeld = 2 };

struct Slot {
  std::atomic<int> state{kFree};
  char path[kPathBytes] = {};
};

std::array<Slot, kSlots> g_slots;
std::atomic<bool> g_installed{false};

}  // namespace

extern "C" void fspm_signal_cleanup_handler(int signal) {
  // unlink(2) and rmdir(2) are async-signal-safe. Files first, then folders, which go only when
  // empty (a crown's output folder after its temporaries).
  for (Slot& s : g_slots) {
    if (s.state.load() == kHeld) ::unlink(s.path);
  }
  for (Slot& s : g_slots) {
    if (s.state.load() == kHeld) ::rmdir(s.path);
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

void install_signal_cleanup() {
  if (g_installed.exchange(true)) return;
  std::signal(SIGINT, fspm_signal_cleanup_handler);
  std::signal(SIGTERM, fspm_signal_cleanup_handler);
}

int register_signal_cleanup(const std::string& path) {
  if (path.size() >= kPathBytes) return -1;
  for (std::size_t i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (!g_slots[i].state.compare_exchange_strong(expected, kWriting)) continue;
    std::memcpy(g_slots[i].path, path.c_str(), path.size() + 1);
    g_slots[i].state.store(kHeld);
    return static_cast<int>(i);
  }
  return -1;
}

void unregister_signal_cleanup(int handle) {
  if (handle < 0 || static_cast<std::size_t>(handle) >= kSlots) return;
  g_slots[static_cast<std::size_t>(handle)].state.store(kFree);
}

}  // namespace fspm
