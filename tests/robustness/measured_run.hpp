#pragma once
// Runs one shell command line and measures the peak resident memory of what it ran (wait4's
// resource usage of the shell, which execs the command), so a robustness case can check that a
// refused request was refused before its memory was taken, not after.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace fspm::testing {

struct MeasuredRun {
  int exit_code = -1;
  std::string err;
  std::uint64_t peak_rss_kib = 0;
};

// `command` runs under /bin/sh -c with stdin from /dev/null, stdout to /dev/null and stderr
// captured; it should end in `exec PROGRAM ...` so the peak is the program's.
inline MeasuredRun run_measured(const std::string& command, const std::filesystem::path& err_file) {
  MeasuredRun r;
  const pid_t child = ::fork();
  if (child < 0) return r;
  if (child == 0) {
    const int in = ::open("/dev/null", O_RDONLY);
    const int out = ::open("/dev/null", O_WRONLY);
    const int err = ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(in, 0);
    ::dup2(out, 1);
    ::dup2(err, 2);
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  struct rusage usage {};
  ::wait4(child, &status, 0, &usage);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.peak_rss_kib = static_cast<std::uint64_t>(usage.ru_maxrss);  // KiB on Linux
  std::ifstream in(err_file);
  r.err.assign(std::istreambuf_iterator<char>(in), {});
  return r;
}

}  // namespace fspm::testing
