#pragma once
// Runs the built `fspm` executable as a user would and captures what it prints.
#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace fspm::testing {

struct CommandResult {
  int exit_code = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};

// `args` is appended to the executable path as shell words (quote them yourself); redirections
// of stdout in `args` take the place of the capture. `shell_prefix` runs before, in the same
// shell (e.g. "ulimit -f 4; ").
inline CommandResult run_fspm(const std::string& args, const std::string& shell_prefix = {}) {
  namespace fs = std::filesystem;
  static int counter = 0;
  const fs::path err_file =
      fs::temp_directory_path() /
      ("fspm_cli_err_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  const std::string cmd =
      shell_prefix + std::string(FSPM_EXE) + " " + args + " 2>" + err_file.string() + " </dev/null";
  CommandResult r;
  FILE* pipe = ::popen(cmd.c_str(), "r");
  if (pipe == nullptr) return r;
  std::array<char, 4096> buf;
  std::size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0) r.out.append(buf.data(), n);
  const int status = ::pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (FILE* f = std::fopen(err_file.c_str(), "r")) {
    while ((n = std::fread(buf.data(), 1, buf.size(), f)) > 0) r.err.append(buf.data(), n);
    std::fclose(f);
  }
  fs::remove(err_file);
  return r;
}

// A fresh empty directory for one test's files.
inline std::filesystem::path scratch_dir(const std::string& name) {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() / ("fspm_cli_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Writes a small input file for a test.
inline void write_text(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

// The whole content of a file (empty when it does not exist).
inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace fspm::testing
