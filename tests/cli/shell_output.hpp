#pragma once
// Standard output of a shell command and its exit status, for tests that look at what a command
// prints without going through run_fspm (ldd, groff, bash completion, fspm-full directly).
#include <cstdio>
#include <string>

namespace fspm::testing {

inline std::string shell_output(const std::string& command, int& status) {
  std::string out;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return out;
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) out.append(buf, n);
  status = ::pclose(pipe);
  return out;
}

}  // namespace fspm::testing
