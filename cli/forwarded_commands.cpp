// fspm: the commands that need the graphics and experiments libraries are listed in --help like
// the others, and hand the whole command line to fspm-full, which lies beside this executable.
// Loading VTK, OpenImageIO and MPI (about 300 shared libraries, most of a second) is then paid
// only by the commands that use them; `fspm --version` and `fspm tree info` start at once.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <array>
#include <cerrno>
#include <climits>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include "cli/commands.hpp"
#include "cli/full_command_list.hpp"
#include "cli/lsystem_source.hpp"
#include "cli/output.hpp"
#include "fspm/error.hpp"

namespace fspm::cli {
namespace {

std::filesystem::path full_executable() {
  std::array<char, PATH_MAX> self{};
  const ssize_t n = ::readlink("/proc/self/exe", self.data(), self.size() - 1);
  if (n <= 0) {
    throw IoError(std::string("cannot find this executable's folder (/proc/self/exe): ") +
                  std::strerror(errno));
  }
  return std::filesystem::path(std::string(self.data(), static_cast<std::size_t>(n)))
             .parent_path() /
         "fspm-full";
}

// Replaces this process by fspm-full with the same arguments: its output, exit code and signals
// are the command's own. Returns only by throwing.
[[noreturn]] void hand_over(int argc, char** argv) {
  const std::filesystem::path full = full_executable();
  std::cout.flush();
  finish_standard_output();
  std::string program = full.string();
  std::vector<char*> args(argv, argv + argc);
  args.push_back(nullptr);
  args[0] = program.data();
  ::execv(program.c_str(), args.data());
  throw IoError("this command needs " + program +
                " (installed beside fspm): " + std::strerror(errno));
}

// `lsystem interpret ... -o MESH`: the mesh writers live in fspm-full.
bool writes_lsystem_mesh(int first, int argc, char** argv) {
  bool interpret = false;
  for (int k = first; k < argc; ++k) {
    const std::string_view arg = argv[k];
    interpret = interpret || arg == "interpret";
    std::string output;
    if ((arg == "-o" || arg == "--output") && k + 1 < argc) {
      output = argv[k + 1];
    } else if (arg.starts_with("--output=")) {
      output = std::string(arg.substr(9));
    } else if (arg.starts_with("-o") && arg.size() > 2) {
      output = std::string(arg.substr(2));
    }
    if (interpret && !output.empty() && is_mesh_path(output)) return true;
  }
  return false;
}

}  // namespace

void write_lsystem_mesh(const LsystemDrawing&, const std::string& path, nlohmann::json&) {
  throw ValueError("meshes of L-systems are written by fspm-full (installed beside fspm)", path);
}

void add_full_commands(CLI::App& app) {
  // Listed for --help: hand_over_full_commands() has replaced the process before parsing when
  // the command line names one of them. Reaching a callback means the scan missed it: an error,
  // never a silent success.
  for (const FullCommand& c : kFullCommands) {
    CLI::App* sub = app.add_subcommand(c.name, c.description);
    sub->allow_extras();
    sub->callback([name = std::string(c.name)] {
      throw ValueError("could not hand '" + name +
                       "' to fspm-full: put fspm's own options (-q, -v, --json, "
                       "--memory-limit) after the command");
    });
  }
}

void hand_over_full_commands(int argc, char** argv) {
  // The command is the first argument that is neither an option of fspm's own (-v, -q, --help,
  // --version take no value) nor the value of --memory-limit.
  for (int k = 1; k < argc; ++k) {
    const std::string_view arg = argv[k];
    if (arg == "--memory-limit") {
      ++k;
      continue;
    }
    if (arg.starts_with('-')) continue;
    for (const FullCommand& c : kFullCommands) {
      if (arg == c.name) hand_over(argc, argv);
    }
    if (arg == "lsystem" && writes_lsystem_mesh(k + 1, argc, argv)) hand_over(argc, argv);
    return;
  }
}

}  // namespace fspm::cli
