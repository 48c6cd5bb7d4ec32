// fspm hands the commands that need graphics or experiments to fspm-full: both list the same
// commands, a handed-over command behaves as fspm-full's own, and fspm itself does not link the
// graphics, MPI and database libraries.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>

#include "tests/cli/run_command.hpp"
#include "tests/cli/shell_output.hpp"

namespace fspm {
namespace {

using testing::run_fspm;
using testing::shell_output;

// The "Subcommands:" block of a --help text, one line per command.
std::set<std::string> subcommand_lines(const std::string& help) {
  std::set<std::string> out;
  std::istringstream in(help);
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line == "Subcommands:") {
      inside = true;
    } else if (inside && !line.empty()) {
      out.insert(line);
    }
  }
  return out;
}

const std::string kFullExe = (std::filesystem::path(FSPM_EXE).parent_path() / "fspm-full").string();

TEST(CommandSplit, BothExecutablesListTheSameCommands) {
  const auto lean = run_fspm("--help");
  ASSERT_EQ(lean.exit_code, 0);
  int status = -1;
  const std::string full = shell_output(kFullExe + " --help", status);
  ASSERT_EQ(status, 0);
  const std::set<std::string> lean_lines = subcommand_lines(lean.out);
  EXPECT_EQ(lean_lines, subcommand_lines(full));
  EXPECT_GE(lean_lines.size(), 15u);
}

TEST(CommandSplit, HandedOverCommandsKeepTheirHelpOutputAndExitCode) {
  const auto help = run_fspm("render --help");
  EXPECT_EQ(help.exit_code, 0) << help.err;
  EXPECT_NE(help.out.find("--view"), std::string::npos) << help.out;
  // Global options before the command are handed over too, with their values.
  for (const char* options : {"-q", "--memory-limit 1G -q", "--memory-limit=1G"}) {
    const auto missing = run_fspm(std::string(options) + " results show /nonexistent-fspm-dir");
    EXPECT_EQ(missing.exit_code, 1) << options;
    EXPECT_NE(missing.err.find("/nonexistent-fspm-dir"), std::string::npos) << missing.err;
  }
}

TEST(CommandSplit, LeanExecutableLinksNoGraphicsMpiOrDatabaseLibrary) {
  int status = -1;
  const std::string libs = shell_output("ldd " + std::string(FSPM_EXE), status);
  ASSERT_EQ(status, 0);
  ASSERT_NE(libs.find("libc.so"), std::string::npos) << libs;
  for (const char* lib : {"libvtk", "libOpenImageIO", "libmpi", "libglfw", "libsqlite3"}) {
    EXPECT_EQ(libs.find(lib), std::string::npos) << lib;
  }
  const std::string full_libs = shell_output("ldd " + kFullExe, status);
  EXPECT_NE(full_libs.find("libvtk"), std::string::npos);
  // OpenImageIO (about 260 libraries with its own dependencies) is loaded on the first image
  // read or written (fspm/image_codec.hpp), not at start.
  EXPECT_EQ(full_libs.find("libOpenImageIO"), std::string::npos) << full_libs;
}

}  // namespace
}  // namespace fspm
