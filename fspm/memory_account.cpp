#include "fspm/memory_account.hpp"

#include <condition_variable>
#include <mutex>

#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"

namespace fspm {
namespace {

// The process's accounts: what they hold together and how many live. `stuck` counts the jobs that
// found no room since the last release (`releases` counts them); a woken job looks again.
struct Accounts {
  std::mutex mutex;
  std::condition_variable released;
  std::uint64_t held = 0;
  std::size_t alive = 0;
  std::size_t stuck = 0;
  std::uint64_t releases = 0;
};

Accounts& accounts() {
  static Accounts a;
  return a;
}

thread_local MemoryAccount* t_account = nullptr;

std::string jobs_text(std::size_t n) {
  return std::to_string(n) + (n == 1 ? " other job holds" : " other jobs hold");
}

}  // namespace

MemoryAccount::MemoryAccount() : previous_(t_account) {
  Accounts& a = accounts();
  {
    const std::lock_guard lock(a.mutex);
    ++a.alive;
  }
  t_account = this;
}

MemoryAccount::~MemoryAccount() {
  t_account = previous_;
  Accounts& a = accounts();
  {
    const std::lock_guard lock(a.mutex);
    a.held -= held_;
    --a.alive;
    ++a.releases;
    a.stuck = 0;
  }
  a.released.notify_all();
}

std::uint64_t MemoryAccount::held_bytes() const {
  const std::lock_guard lock(accounts().mutex);
  return held_;
}

void MemoryAccount::reserve_on_this_thread(std::uint64_t bytes, std::string_view what,
                                           const std::string& file) {
  if (t_account != nullptr) t_account->grow_to(bytes, what, file);
}

void MemoryAccount::grow_to(std::uint64_t bytes, std::string_view what, const std::string& file) {
  Accounts& a = accounts();
  std::unique_lock lock(a.mutex);
  for (;;) {
    if (bytes <= held_) return;
    const std::uint64_t limit = memory_limit_bytes();
    const std::uint64_t others = a.held - held_;
    if (others <= limit && bytes <= limit - others) {
      a.held += bytes - held_;
      held_ = bytes;
      return;
    }
    // Every other job is stuck too: none will return memory, so this one gives up its share.
    if (a.stuck + 1 >= a.alive) {
      throw MemoryLimitError(
          std::string(what) + " needs about " + memory_text(static_cast<double>(bytes)) + ", but " +
              jobs_text(a.alive - 1) + " " + memory_text(static_cast<double>(others)) +
              " of the memory limit of " + memory_text(static_cast<double>(limit)) +
              " (--memory-limit; fewer --jobs)",
          file);
    }
    const std::uint64_t seen = a.releases;
    ++a.stuck;
    a.released.wait(lock);
    if (a.releases == seen) --a.stuck;  // woken without a release: counted again below
  }
}

std::uint64_t memory_room_bytes() {
  const std::uint64_t limit = memory_limit_bytes();
  if (t_account == nullptr) return limit;
  const std::lock_guard lock(accounts().mutex);
  const std::uint64_t others = accounts().held - t_account->held_;
  return others < limit ? limit - others : 0;
}

std::size_t memory_jobs_waiting() {
  const std::lock_guard lock(accounts().mutex);
  return accounts().stuck;
}

std::uint64_t reserved_memory_bytes() {
  const std::lock_guard lock(accounts().mutex);
  return accounts().held;
}

}  // namespace fspm
