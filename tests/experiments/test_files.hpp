#pragma once
// Scratch directories and files for the experiment tests.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace fspm::experiments::testing {

inline std::filesystem::path scratch(const std::string& name) {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() / ("fspm_exp_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

inline std::string write(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path.string();
}

// A straight axis: after n steps n internodes of length L stacked up the z axis.
inline constexpr const char* kLineLSystem =
    "#define L 2\n"
    "Lsystem: 1\n"
    "derivation length: 3\n"
    "Axiom: A\n"
    "A --> F(L)A\n"
    "endlsystem\n";

}  // namespace fspm::experiments::testing
