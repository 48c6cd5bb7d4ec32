#pragma once
// One memory limit for the whole process. Every path that allocates in proportion to its input
// (L-system strings, reconstructed trees, meshes, edit-distance tables, sampled experiment
// plans) estimates its bytes first and calls check_memory(), so an impossible request fails at
// once with a message naming the estimate and the limit, instead of swapping or being killed.
// The limit defaults to half of the memory the process may use (the physical memory, or less under
// a resource limit or a control group); the command line sets it with --memory-limit and Python
// with fspm.set_memory_limit().
#include <cstdint>
#include <string>
#include <string_view>

namespace fspm {

// Half of the memory the process may use: the physical memory (sysconf), or the address-space or
// data-segment resource limit (ulimit -v, -d), or the cgroup's memory.max, whichever is least;
// 4 GiB when the system says nothing.
std::uint64_t default_memory_limit_bytes();

// The current limit in bytes (default_memory_limit_bytes() until set).
std::uint64_t memory_limit_bytes();

// Sets the limit; 0 restores the default. Thread-safe; affects later checks only.
void set_memory_limit_bytes(std::uint64_t bytes);

// Throws MemoryLimitError "WHAT needs about 3.2 GiB, above the memory limit of 2 GiB
// (--memory-limit)" when `bytes` (an estimate; may be huge, infinite or NaN from an overflowing
// product) exceeds the limit. `file` becomes the error's file when given. On the thread of a job
// (fspm/memory_account.hpp) the estimate is also reserved out of the limit the jobs share.
void check_memory(double bytes, std::string_view what, const std::string& file = {});

// Byte count in a short human form: "512 bytes", "1.5 KiB", "3.2 GiB".
std::string memory_text(double bytes);

// Parses a size as written on a command line: a number with an optional unit, binary (K, M, G,
// T, KiB, MiB, GiB, TiB; K = 1024) or B for bytes, case-insensitive ("2G", "512MiB", "1.5g",
// "1000000"). Throws ValueError naming `what` and the text when it is not a positive size.
std::uint64_t parse_memory_size(std::string_view text, std::string_view what);

}  // namespace fspm
