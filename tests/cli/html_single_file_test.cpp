// fspm report --single-file: the HTML report in one page that names no file beside it.
#include "cli/html_single_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "run_command.hpp"

namespace fspm::testing {
namespace {

namespace fs = std::filesystem;

TEST(HtmlSingleFile, ScriptTextCannotEndItsScriptEarly) {
  EXPECT_EQ(cli::script_safe("a = '</script><b>';"), "a = '<\\/script><b>';");
  EXPECT_EQ(cli::script_safe("s = \"</SCRIPT >\""), "s = \"<\\/SCRIPT >\"");
  EXPECT_EQ(cli::script_safe("x = '<!-- y'"), "x = '<\\!-- y'");
  // Everything else as it was: comparisons, tags that are not the end of a script.
  EXPECT_EQ(cli::script_safe("if (a < b && c <= d) e = '<div></div>';"),
            "if (a < b && c <= d) e = '<div></div>';");
}

// Two points of an L-system sweep, two replicates each, trees kept, one rendered.
std::string sweep(const fs::path& dir) {
  const fs::path exp = dir / "e.toml";
  std::ofstream(exp) << "[experiment]\nname = \"s\"\nseed = 5\nreplicates = 2\n[model]\n"
                        "kind = \"lsystem\"\nfile = \""
                     << FSPM_SOURCE_DIR
                     << "/examples/lsystems/stochastic_plant.l\"\n[sweep]\nsteps = [2, 3]\n"
                        "[outputs]\nmetrics = [\"internodes\"]\nkeep = [\"tree\"]\n"
                        "[report]\nrenders = 1\n";
  const std::string out = (dir / "out").string();
  const CommandResult run = run_fspm("run " + exp.string() + " --jobs 2 --out " + out);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  return out;
}

TEST(HtmlSingleFile, OnePageWithItsLibrariesDataAndTreesInside) {
  const fs::path dir = scratch_dir("html_single_file");
  const std::string out = sweep(dir);
  const CommandResult report = run_fspm("report " + out + " --no-figures --single-file --json");
  if (report.err.find("browser files are missing") != std::string::npos) {
    GTEST_SKIP() << report.err;  // built without npm
  }
  ASSERT_EQ(report.exit_code, 0) << report.err;
  const fs::path single = dir / "out" / "report.html";
  EXPECT_EQ(nlohmann::json::parse(report.out)["html"], single.string());
  const std::string page = read_text(single);
  // Nothing loaded from beside it: no script or style sheet by name.
  EXPECT_EQ(page.find("<script src="), std::string::npos);
  EXPECT_EQ(page.find("<link rel=\"stylesheet\""), std::string::npos);
  // Each library, the data and the one tree, whole: as large as the folder's files together.
  std::uintmax_t parts = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir / "out" / "report")) {
    if (e.is_regular_file() && e.path().extension() != ".html" && e.path().extension() != ".txt") {
      parts += e.file_size();
    }
  }
  EXPECT_GE(page.size(), parts);
  EXPECT_NE(page.find("window.FSPM_REPORT = "), std::string::npos);
  int trees = 0;
  for (std::size_t at = page.find("<script>fspmGlb(\""); at != std::string::npos;
       at = page.find("<script>fspmGlb(\"", at + 1)) {
    ++trees;
  }
  EXPECT_EQ(trees, 1);
  // The scripts end only where they should: one </script> per <script>.
  const auto count = [&](const std::string& s) {
    int n = 0;
    for (std::size_t at = page.find(s); at != std::string::npos; at = page.find(s, at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count("<script>"), count("</script>"));
}

}  // namespace
}  // namespace fspm::testing
