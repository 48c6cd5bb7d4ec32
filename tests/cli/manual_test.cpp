// The manual pages and the bash completion written by `fspm-full write-manual` cover every
// command and option the program accepts. The expected commands and options are read from the
// programs' own --help (CLI11's formatter over the same app objects, a path independent of the
// manual writer), never typed here: the lean fspm's --help for the commands, fspm-full's for the
// options and subcommands of each.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/cli/run_command.hpp"
#include "tests/cli/shell_output.hpp"

namespace fspm {
namespace {

namespace fs = std::filesystem;
using testing::read_text;
using testing::run_fspm;
using testing::scratch_dir;
using testing::shell_output;

std::string full_exe() { return (fs::path(FSPM_EXE).parent_path() / "fspm-full").string(); }

// The first words of the entries of one block ("Subcommands:", "Options:") of a --help text;
// an entry is indented by two spaces, a description moved to its own line by more.
std::vector<std::string> help_block(const std::string& help, const std::string& title) {
  std::vector<std::string> out;
  std::istringstream in(help);
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] != ' ') {
      inside = line == title;
    } else if (inside && line.size() > 2 && line[2] != ' ') {  // not a description's own line
      std::istringstream words(line);
      std::string first;
      words >> first;
      out.push_back(first);
    }
  }
  return out;
}

// The long option names of a --help block entry such as "-s,--seed".
std::vector<std::string> long_names(const std::vector<std::string>& entries) {
  std::vector<std::string> out;
  for (const std::string& entry : entries) {
    std::istringstream names(entry);
    std::string name;
    while (std::getline(names, name, ',')) {
      if (name.starts_with("--")) out.push_back(name);
    }
  }
  return out;
}

// fspm-full's --help of a command path, run once per path (fspm-full loads for most of a second).
std::string full_help(const std::string& command_path) {
  static std::map<std::string, std::string> cache;
  if (const auto it = cache.find(command_path); it != cache.end()) return it->second;
  int status = -1;
  const std::string help = shell_output(full_exe() + " " + command_path + " --help", status);
  EXPECT_EQ(status, 0) << command_path;
  return cache[command_path] = help;
}

// roff text back to plain text for the names the pages print (\- is a hyphen).
std::string plain(std::string roff) {
  for (std::size_t at = roff.find("\\-"); at != std::string::npos; at = roff.find("\\-", at)) {
    roff.replace(at, 2, "-");
  }
  return roff;
}

// What bash completes after `words` (the last one being completed), with the script loaded.
std::set<std::string> completions(const fs::path& script, const std::string& words) {
  const fs::path runner = script.parent_path() / "complete.sh";
  testing::write_text(runner,
                      "source \"$1\"; shift; COMP_WORDS=(\"$@\"); COMP_CWORD=$(($# - 1)); "
                      "COMPREPLY=(); _fspm; printf '%s\\n' \"${COMPREPLY[@]}\"\n");
  int status = -1;
  const std::string out =
      shell_output("bash " + runner.string() + " " + script.string() + " fspm " + words, status);
  EXPECT_EQ(status, 0) << words;
  std::set<std::string> items;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) items.insert(line);
  }
  return items;
}

struct Manual {
  fs::path man_dir, completion;
};

// The manual, written once for all tests into a scratch folder.
const Manual& manual() {
  static const Manual m = [] {
    const fs::path dir = scratch_dir("manual");
    Manual written{dir / "man1", dir / "completions" / "fspm"};
    int status = -1;
    shell_output(full_exe() + " write-manual --man-dir " + written.man_dir.string() +
                     " --bash-completion " + written.completion.string(),
                 status);
    EXPECT_EQ(status, 0);
    return written;
  }();
  return m;
}

std::vector<std::string> top_commands() {
  const auto r = run_fspm("--help");
  EXPECT_EQ(r.exit_code, 0);
  return help_block(r.out, "Subcommands:");
}

TEST(Manual, EveryCommandHasItsPageAndNoOtherPageIsWritten) {
  const Manual& m = manual();
  const std::vector<std::string> commands = top_commands();
  ASSERT_GE(commands.size(), 15u);  // the lean fspm lists every command, its own and fspm-full's
  std::set<std::string> expected = {"fspm.1"};
  for (const std::string& c : commands) expected.insert("fspm-" + c + ".1");
  std::set<std::string> written;
  for (const auto& entry : fs::directory_iterator(m.man_dir)) {
    written.insert(entry.path().filename().string());
  }
  EXPECT_EQ(written, expected);

  const std::string top = plain(read_text(m.man_dir / "fspm.1"));
  for (const std::string& c : commands) {
    EXPECT_NE(top.find("fspm-" + c + "\\fR(1)"), std::string::npos) << c;
  }
}

TEST(Manual, EachPageHasTheOptionsAndSubcommandsOfItsCommand) {
  const Manual& m = manual();
  for (const std::string& c : top_commands()) {
    const std::string page = plain(read_text(m.man_dir / ("fspm-" + c + ".1")));
    const std::string help = full_help(c);
    for (const std::string& option : long_names(help_block(help, "Options:"))) {
      EXPECT_NE(page.find(option), std::string::npos) << "fspm-" << c << ".1 misses " << option;
    }
    for (const std::string& sub : help_block(help, "Subcommands:")) {
      EXPECT_NE(page.find(".SS fspm " + c + " " + sub + "\n"), std::string::npos)
          << "fspm-" << c << ".1 misses " << sub;
      for (const std::string& option :
           long_names(help_block(full_help(c + " " + sub), "Options:"))) {
        EXPECT_NE(page.find(option), std::string::npos) << c << " " << sub << ": " << option;
      }
    }
  }
}

TEST(Manual, PagesAreWellFormedRoff) {
  const Manual& m = manual();
  const bool have_groff = fs::exists("/usr/bin/groff");
  for (const auto& entry : fs::directory_iterator(m.man_dir)) {
    const std::string page = read_text(entry.path());
    const std::string name = entry.path().stem().string();
    // man(7): the title line first (after comments), then NAME as "name \- description".
    EXPECT_NE(page.find("\n.TH "), std::string::npos) << name;
    EXPECT_NE(plain(page).find(".SH NAME\n" + name + " - "), std::string::npos) << name;
    EXPECT_NE(page.find(".SH SYNOPSIS\n"), std::string::npos) << name;
    if (have_groff) {
      // -ww: every warning; -z: no output. A malformed page prints a warning.
      int status = -1;
      const std::string warnings =
          shell_output("groff -man -ww -z " + entry.path().string() + " 2>&1", status);
      EXPECT_EQ(status, 0) << name;
      EXPECT_EQ(warnings, "") << name;
    }
  }
}

TEST(Manual, BashCompletesEveryCommandSubcommandAndOption) {
  const Manual& m = manual();
  const std::vector<std::string> commands = top_commands();
  EXPECT_EQ(completions(m.completion, "''"),
            std::set<std::string>(commands.begin(), commands.end()));
  for (const std::string& c : commands) {
    const std::string help = full_help(c);
    const auto subs = help_block(help, "Subcommands:");
    EXPECT_EQ(completions(m.completion, c + " ''"), std::set<std::string>(subs.begin(), subs.end()))
        << c;
    const std::set<std::string> options = completions(m.completion, c + " --");
    for (const std::string& option : long_names(help_block(help, "Options:"))) {
      EXPECT_TRUE(options.contains(option)) << c << " " << option;
    }
    // fspm's own options are accepted after the command (CLI11's fallthrough).
    EXPECT_TRUE(options.contains("--quiet")) << c;
    for (const std::string& sub : subs) {
      const std::set<std::string> sub_options = completions(m.completion, c + " " + sub + " --");
      for (const std::string& option :
           long_names(help_block(full_help(c + " " + sub), "Options:"))) {
        EXPECT_TRUE(sub_options.contains(option)) << c << " " << sub << " " << option;
      }
    }
  }
  // After an option that takes a value, bash completes file names (nothing from the script),
  // and the value is not taken for a command.
  EXPECT_TRUE(completions(m.completion, "--memory-limit ''").empty());
  EXPECT_EQ(completions(m.completion, "--memory-limit 2G tree ''"),
            (std::set<std::string>{"convert", "info"}));
}

}  // namespace
}  // namespace fspm
