#pragma once
// The memory budget shared by the jobs of one process. `fspm run --jobs N` and `fspm compare
// --jobs N` run N jobs at once; each checks its estimates against the one limit
// (fspm/memory_budget.hpp), so without a shared account N jobs could together take N times the
// limit. A job opens a MemoryAccount on its thread; while it lives, every check_memory() on that
// thread reserves the job's largest estimate so far out of the one limit, and the account returns
// it when the job ends. The estimates of one job are not added up: each is the size of what the
// job holds at that point (a derivation's string, a tree, a distance table), as for one command.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace fspm {

// One job's share of the memory budget, bound to the thread that creates it (and to no other)
// until it is destroyed on that thread. A job whose estimate fits the limit but not beside what
// the other jobs hold waits until they return theirs, so its result does not depend on the number
// of jobs; when every other job is waiting too, none could ever return anything, and the job fails
// with MemoryLimitError naming what the others hold (fewer jobs leave more to each).
class MemoryAccount {
 public:
  MemoryAccount();
  ~MemoryAccount();
  MemoryAccount(const MemoryAccount&) = delete;
  MemoryAccount& operator=(const MemoryAccount&) = delete;

  // The bytes this job holds: its largest estimate so far.
  std::uint64_t held_bytes() const;

  // Grows the thread's account, when there is one, to `bytes` (within the limit, which the
  // caller has checked); check_memory() calls it.
  static void reserve_on_this_thread(std::uint64_t bytes, std::string_view what,
                                     const std::string& file);

 private:
  friend std::uint64_t memory_room_bytes();
  void grow_to(std::uint64_t bytes, std::string_view what, const std::string& file);

  MemoryAccount* previous_;
  std::uint64_t held_ = 0;
};

// What the thread may still take of the limit: the limit less what the other jobs hold (the
// whole limit on a thread without an account). For the cheap caps of loops that check only
// past them (lsystem/derivation.cpp).
std::uint64_t memory_room_bytes();

// The bytes held by all living accounts of the process.
std::uint64_t reserved_memory_bytes();

// The jobs waiting for others to return memory (for progress messages and tests).
std::size_t memory_jobs_waiting();

}  // namespace fspm
