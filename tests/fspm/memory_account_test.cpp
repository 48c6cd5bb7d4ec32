// The memory limit shared by the jobs of one process: what jobs hold together never exceeds the
// limit, a job that does not fit beside the others waits for them, and a job that could only wait
// for jobs that wait themselves fails instead of hanging.
#include "fspm/memory_account.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <string>
#include <thread>

#include "fspm/error.hpp"
#include "fspm/memory_budget.hpp"
#include "tests/scoped_memory_limit.hpp"

namespace fspm {
namespace {

constexpr std::uint64_t kMiB = std::uint64_t{1} << 20;

// Polls until `done` holds or a second passes (threads handing over memory).
template <class Done>
bool eventually(Done done) {
  for (int i = 0; i < 1000 && !done(); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return done();
}

TEST(MemoryAccount, AThreadWithoutAnAccountReservesNothing) {
  const test_support::ScopedMemoryLimit limit(100 * kMiB);
  check_memory(90.0 * kMiB, "a single command");
  EXPECT_EQ(reserved_memory_bytes(), 0u);
  EXPECT_EQ(memory_room_bytes(), 100 * kMiB);
}

TEST(MemoryAccount, KeepsTheLargestEstimateAndReturnsItAtTheEnd) {
  const test_support::ScopedMemoryLimit limit(100 * kMiB);
  {
    const MemoryAccount job;
    check_memory(30.0 * kMiB, "a string");
    check_memory(10.0 * kMiB, "a smaller structure");
    EXPECT_EQ(job.held_bytes(), 30 * kMiB);
    EXPECT_EQ(reserved_memory_bytes(), 30 * kMiB);
  }
  EXPECT_EQ(reserved_memory_bytes(), 0u);
}

TEST(MemoryAccount, AJobThatDoesNotFitBesideAnotherWaitsForIt) {
  const test_support::ScopedMemoryLimit limit(100 * kMiB);
  std::promise<void> release;
  std::atomic<bool> first_holds{false};
  std::thread first([&] {
    const MemoryAccount job;
    check_memory(60.0 * kMiB, "the first job");
    first_holds = true;
    release.get_future().wait();
  });
  ASSERT_TRUE(eventually([&] { return first_holds.load(); }));
  std::atomic<bool> second_done{false};
  std::thread second([&] {
    const MemoryAccount job;
    check_memory(60.0 * kMiB, "the second job");
    EXPECT_LE(reserved_memory_bytes(), 100 * kMiB);
    second_done = true;
  });
  // 60 + 60 MiB would pass the limit: the second job waits.
  ASSERT_TRUE(eventually([] { return memory_jobs_waiting() == 1; }));
  EXPECT_FALSE(second_done.load());
  EXPECT_EQ(reserved_memory_bytes(), 60 * kMiB);
  release.set_value();
  first.join();
  second.join();
  EXPECT_TRUE(second_done.load());
  EXPECT_EQ(reserved_memory_bytes(), 0u);
}

TEST(MemoryAccount, JobsWaitingForEachOtherFailInsteadOfHanging) {
  const test_support::ScopedMemoryLimit limit(100 * kMiB);
  std::atomic<bool> second_holds{false};
  std::atomic<bool> first_holds{false};
  std::string first_error = "none";
  std::thread first([&] {
    const MemoryAccount job;
    check_memory(50.0 * kMiB, "the first job");
    first_holds = true;
    while (!second_holds) std::this_thread::yield();
    try {
      check_memory(70.0 * kMiB, "the first job's growth");  // waits for the second
      first_error.clear();
    } catch (const MemoryLimitError& e) {
      first_error = e.what();
    }
  });
  std::string second_error;
  std::thread second([&] {
    const MemoryAccount job;
    while (!first_holds) std::this_thread::yield();
    check_memory(40.0 * kMiB, "the second job");
    second_holds = true;
    // The first job is waiting for this one: growing too would wait forever.
    ASSERT_TRUE(eventually([&] { return memory_jobs_waiting() == 1; }));
    try {
      check_memory(70.0 * kMiB, "the second job's growth");
    } catch (const MemoryLimitError& e) {
      second_error = e.what();
    }
  });
  second.join();
  first.join();
  EXPECT_EQ(
      second_error,
      "the second job's growth needs about 70 MiB, but 1 other job holds 50 MiB of the memory "
      "limit of 100 MiB (--memory-limit; fewer --jobs)");
  EXPECT_EQ(first_error, "") << "the first job continues once the second gave up";
  EXPECT_EQ(reserved_memory_bytes(), 0u);
}

TEST(MemoryAccount, TheRoomOfAJobIsTheLimitLessWhatOthersHold) {
  const test_support::ScopedMemoryLimit limit(100 * kMiB);
  std::promise<void> release;
  std::atomic<bool> holds{false};
  std::thread other([&] {
    const MemoryAccount job;
    check_memory(30.0 * kMiB, "another job");
    holds = true;
    release.get_future().wait();
  });
  ASSERT_TRUE(eventually([&] { return holds.load(); }));
  {
    const MemoryAccount job;
    check_memory(20.0 * kMiB, "this job");
    EXPECT_EQ(memory_room_bytes(), 70 * kMiB);
  }
  release.set_value();
  other.join();
}

}  // namespace
}  // namespace fspm
