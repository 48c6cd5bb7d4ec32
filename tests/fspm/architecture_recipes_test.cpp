// docs/architecture.md against the code: every file its recipes name exists, every function,
// type or list a recipe's "- `file`: ..." step names is in that file (the registration points),
// and every module folder has its row in the module table. A renamed file or registration point
// fails here until the page follows.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace fspm {
namespace {

namespace fs = std::filesystem;

const fs::path kRoot = FSPM_SOURCE_DIR;

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The text of the page from `heading` to the next "## " heading.
std::string section(const std::string& page, const std::string& heading) {
  const auto begin = page.find("\n" + heading + "\n");
  if (begin == std::string::npos) return {};
  const auto end = page.find("\n## ", begin + 1);
  return page.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

// The recipes' steps: each "- " item, or each paragraph, joined into one line.
std::vector<std::string> recipe_steps() {
  const std::string recipes = section(read_text(kRoot / "docs/architecture.md"), "## Recipes");
  std::vector<std::string> steps;
  std::string current;
  std::istringstream lines(recipes);
  for (std::string line; std::getline(lines, line);) {
    const bool item = line.rfind("- ", 0) == 0;
    if (line.empty() || item || line.rfind("**", 0) == 0) {
      if (!current.empty()) steps.push_back(current);
      current = line;
    } else {
      current += " " + line;
    }
  }
  if (!current.empty()) steps.push_back(current);
  return steps;
}

std::vector<std::string> backticked(const std::string& text) {
  std::vector<std::string> out;
  static const std::regex kTick("`([^`]+)`");
  for (std::sregex_iterator it(text.begin(), text.end(), kTick), end; it != end; ++it) {
    out.push_back((*it)[1]);
  }
  return out;
}

// A repository path: has a folder, no placeholder (`<model>`), no wildcard, no space.
bool is_path(const std::string& token) {
  return token.find('/') != std::string::npos && token.find_first_of("<>* ") == std::string::npos &&
         token.rfind("--", 0) != 0;
}

// The paths a step names, in backticks or as plain docs/... text.
std::vector<std::string> paths_of(const std::string& step) {
  std::vector<std::string> out;
  for (const std::string& t : backticked(step)) {
    if (is_path(t)) out.push_back(t);
  }
  static const std::regex kPlain(
      R"((?:^|[\s(])((?:docs|tests|scripts)/[\w./-]*\w\.(?:md|cpp|py|sh)))");
  for (std::sregex_iterator it(step.begin(), step.end(), kPlain), end; it != end; ++it) {
    out.push_back((*it)[1]);
  }
  return out;
}

TEST(ArchitectureRecipes, EveryNamedFileExists) {
  std::size_t named = 0;
  for (const std::string& step : recipe_steps()) {
    for (const std::string& path : paths_of(step)) {
      ++named;
      EXPECT_TRUE(fs::exists(kRoot / path)) << path << " named in: " << step.substr(0, 100);
    }
  }
  // The recipes (command, tree format, mesh format, light model, model kind, binding) name
  // several dozen files; far fewer means the page's layout changed under this test.
  EXPECT_GT(named, 40u);
}

// "- `environment/growth_params.cpp`: its name in `kFittedAlpha` ...": every identifier such a
// step names is in one of the files it names.
TEST(ArchitectureRecipes, RegistrationPointsAreInTheirFiles) {
  static const std::regex kIdentifier(R"([A-Za-z_]\w*(::\w+)*)");
  std::size_t checked = 0;
  for (const std::string& step : recipe_steps()) {
    const std::vector<std::string> ticks = backticked(step);
    if (step.rfind("- ", 0) != 0 || ticks.empty() || !is_path(ticks.front())) continue;
    std::string code;
    for (const std::string& path : paths_of(step)) {
      if (fs::is_regular_file(kRoot / path)) code += read_text(kRoot / path);
    }
    for (const std::string& name : ticks) {
      if (!std::regex_match(name, kIdentifier)) continue;
      ++checked;
      EXPECT_NE(code.find(name), std::string::npos)
          << "'" << name << "' is not in the files of: " << step.substr(0, 100);
    }
  }
  // The light-model and mesh-format recipes alone name more than fifteen.
  EXPECT_GT(checked, 15u);
}

// Every folder with a CMakeLists.txt (a module, the command line, the bindings, the tests) has
// its row in the module table.
TEST(ArchitectureRecipes, EveryFolderHasItsModuleRow) {
  const std::string modules = section(read_text(kRoot / "docs/architecture.md"), "## Modules");
  ASSERT_FALSE(modules.empty());
  std::size_t folders = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(kRoot)) {
    if (!e.is_directory() || !fs::exists(e.path() / "CMakeLists.txt")) continue;
    ++folders;
    const std::string folder = e.path().filename().string() + "/";
    EXPECT_NE(modules.find("`" + folder + "`"), std::string::npos) << folder;
  }
  EXPECT_GT(folders, 10u);
}

}  // namespace
}  // namespace fspm
