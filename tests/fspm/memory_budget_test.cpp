// The process-wide memory limit: parsing of sizes, the check, and its message.
#include "fspm/memory_budget.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <limits>
#include <string>

#include "fspm/error.hpp"

namespace fspm {
namespace {

// Restores the default limit when a test ends, so tests do not leak their limit.
struct LimitGuard {
  ~LimitGuard() { set_memory_limit_bytes(0); }
};

TEST(MemoryBudget, ParsesSizesWithBinaryUnits) {
  EXPECT_EQ(parse_memory_size("1000000", "--memory-limit"), 1000000u);
  EXPECT_EQ(parse_memory_size("512M", "--memory-limit"), 512u * 1024 * 1024);
  EXPECT_EQ(parse_memory_size("2G", "--memory-limit"), 2ull * 1024 * 1024 * 1024);
  EXPECT_EQ(parse_memory_size("2GiB", "--memory-limit"), 2ull << 30);
  EXPECT_EQ(parse_memory_size("1.5g", "--memory-limit"), 3ull << 29);
  EXPECT_EQ(parse_memory_size("64kb", "--memory-limit"), 65536u);
  EXPECT_EQ(parse_memory_size("1T", "--memory-limit"), 1ull << 40);
}

TEST(MemoryBudget, RejectsWhatIsNotAPositiveSize) {
  for (const char* text : {"", "G", "-1G", "0", "0.5", "2X", "nan", "inf", "1e30", "2 G"}) {
    try {
      parse_memory_size(text, "--memory-limit");
      ADD_FAILURE() << "accepted '" << text << "'";
    } catch (const ValueError& e) {
      EXPECT_NE(std::string(e.what()).find("--memory-limit: expected a size"), std::string::npos)
          << e.what();
    }
  }
}

// Half of the physical memory at most (less under a ulimit or cgroup limit: the robustness
// catalogue's DoublingModulesUnderAnAddressSpaceLimit runs fspm under one).
TEST(MemoryBudget, DefaultIsAtMostHalfOfThePhysicalMemory) {
  LimitGuard guard;
  set_memory_limit_bytes(0);
  EXPECT_EQ(memory_limit_bytes(), default_memory_limit_bytes());
  EXPECT_GT(default_memory_limit_bytes(), 0u);
  const auto physical = static_cast<std::uint64_t>(::sysconf(_SC_PHYS_PAGES)) *
                        static_cast<std::uint64_t>(::sysconf(_SC_PAGE_SIZE));
  EXPECT_LE(default_memory_limit_bytes(), physical / 2);
  set_memory_limit_bytes(12345);
  EXPECT_EQ(memory_limit_bytes(), 12345u);
}

TEST(MemoryBudget, CheckPassesAtTheLimitAndThrowsAboveWithBothNumbers) {
  LimitGuard guard;
  set_memory_limit_bytes(2ull << 30);
  EXPECT_NO_THROW(check_memory(2.0 * 1024 * 1024 * 1024, "a table"));
  try {
    check_memory(3.2 * 1024 * 1024 * 1024, "the distance table", "a.tree");
    FAIL() << "no error above the limit";
  } catch (const MemoryLimitError& e) {
    EXPECT_EQ(e.file(), "a.tree");
    EXPECT_EQ(e.message(),
              "the distance table needs about 3.2 GiB, above the memory limit of 2 GiB "
              "(--memory-limit)");
  }
}

// Just above the limit the short forms of both would read alike ("1 GiB ... of 1 GiB").
TEST(MemoryBudget, EstimateJustAboveTheLimitShowsItsDigits) {
  LimitGuard guard;
  set_memory_limit_bytes(1ull << 30);
  try {
    check_memory(1.04 * 1024 * 1024 * 1024, "the crown");
    FAIL() << "no error above the limit";
  } catch (const MemoryLimitError& e) {
    EXPECT_EQ(e.message(),
              "the crown needs about 1.04 GiB, above the memory limit of 1 GiB (--memory-limit)");
  }
}

TEST(MemoryBudget, OverflowedEstimatesFail) {
  LimitGuard guard;
  set_memory_limit_bytes(1ull << 40);
  EXPECT_THROW(check_memory(std::numeric_limits<double>::infinity(), "x"), MemoryLimitError);
  EXPECT_THROW(check_memory(std::nan(""), "x"), MemoryLimitError);
  EXPECT_THROW(check_memory(1e300, "x"), MemoryLimitError);
}

TEST(MemoryBudget, TextOfByteCounts) {
  EXPECT_EQ(memory_text(512), "512 bytes");
  EXPECT_EQ(memory_text(1536), "1.5 KiB");
  EXPECT_EQ(memory_text(1024.0 * 1024 * 1024), "1 GiB");
  EXPECT_EQ(memory_text(1e300), "more than 1 YiB");
}

}  // namespace
}  // namespace fspm
