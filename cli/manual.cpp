// Manual pages in man(7) roff and a bash completion script, both walked from the CLI11 app that
// parses the command line, so a new command or option appears in them without another edit.
#include "cli/manual.hpp"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "fspm/atomic_file.hpp"
#include "fspm/error.hpp"

namespace fspm::cli {
namespace {

// Text as roff reads it literally: backslashes escaped, a line starting with a control
// character ('.' or '\'') protected by the zero-width \&, hyphens of names as \- (groff
// otherwise prints a typographic hyphen that cannot be copied into a shell).
std::string roff_text(const std::string& text, bool hyphens_as_minus = false) {
  std::string out;
  bool line_start = true;
  for (const char c : text) {
    if (line_start && (c == '.' || c == '\'')) out += "\\&";
    if (c == '\\') {
      out += "\\e";
    } else if (c == '-' && hyphens_as_minus) {
      out += "\\-";
    } else {
      out += c;
    }
    line_start = c == '\n';
  }
  return out;
}

std::string upper(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return text;
}

// A description as a sentence, so that "See ..." can follow it.
std::string sentence(std::string text) {
  if (!text.empty() && text.back() != '.') text += '.';
  return text;
}

// The one-line description for NAME: the top-level app's starts with its own name ("fspm: ..."),
// which NAME already gives.
std::string summary(const CLI::App& app) {
  const std::string prefix = app.get_name() + ": ";
  std::string text = app.get_description();
  if (text.starts_with(prefix)) text.erase(0, prefix.size());
  return text;
}

bool visible(const CLI::Option* o) { return !o->get_group().empty(); }

// "fspm tree info" for the app of `tree info`.
std::string command_path(const CLI::App& app) {
  const CLI::App* parent = app.get_parent();
  return parent == nullptr ? app.get_name() : command_path(*parent) + " " + app.get_name();
}

std::string page_name(const CLI::App& app) {
  std::string name = command_path(app);
  std::replace(name.begin(), name.end(), ' ', '-');
  return name;
}

bool takes_value(const CLI::Option* o) { return o->get_items_expected_max() != 0; }

// ".B fspm tree info" [OPTIONS] FILE... [COMMAND]
void write_synopsis(std::ostream& out, const CLI::App& app) {
  out << ".B " << roff_text(command_path(app), true) << "\n";
  const auto named = app.get_options([](const CLI::Option* o) { return o->nonpositional(); });
  if (!named.empty()) out << "[\\fIOPTIONS\\fR]\n";
  for (const CLI::Option* o : app.get_options([](const CLI::Option* o) {
         return o->get_positional() && !o->nonpositional() && visible(o);
       })) {
    const bool many = o->get_items_expected_max() > 1;
    const std::string name = "\\fI" + roff_text(upper(o->get_name(true))) + "\\fR";
    out << (o->get_required() ? name : "[" + name + "]") << (many ? "..." : "") << "\n";
  }
  if (!visible_commands(app).empty()) out << "\\fICOMMAND\\fR\n";
}

void write_option(std::ostream& out, const CLI::Option* o) {
  out << ".TP\n";
  std::string names;
  if (o->nonpositional()) {
    for (const std::string& s : o->get_snames()) names += (names.empty() ? "" : ", ") + ("-" + s);
    for (const std::string& l : o->get_lnames()) names += (names.empty() ? "" : ", ") + ("--" + l);
  } else {
    names = upper(o->get_name(true));
  }
  out << "\\fB" << roff_text(names, true) << "\\fR";
  if (o->nonpositional() && takes_value(o)) {
    out << " \\fI" << roff_text(o->get_type_name()) << "\\fR";
  }
  out << "\n" << roff_text(o->get_description());
  if (!o->get_default_str().empty()) out << " (default: " << roff_text(o->get_default_str()) << ")";
  if (o->get_required() && o->nonpositional()) out << " (required)";
  out << "\n";
}

void write_options(std::ostream& out, const CLI::App& app) {
  for (const CLI::Option* o : app.get_options([](const CLI::Option* o) { return visible(o); })) {
    write_option(out, o);
  }
}

// The commands under `app`, each as a subsection with its synopsis, description and options
// (and its own commands below it).
void write_command_sections(std::ostream& out, const CLI::App& app) {
  for (const CLI::App* sub : visible_commands(app)) {
    out << ".SS " << roff_text(command_path(*sub), true) << "\n";
    write_synopsis(out, *sub);
    out << ".PP\n" << roff_text(sub->get_description()) << "\n";
    write_options(out, *sub);
    write_command_sections(out, *sub);
  }
}

// fspm.1: the program's options, the list of commands and where each is described.
void write_top_page_body(std::ostream& out, const CLI::App& app) {
  out << ".SH COMMANDS\n";
  for (const CLI::App* sub : visible_commands(app)) {
    out << ".TP\n\\fB" << roff_text(sub->get_name(), true) << "\\fR\n"
        << roff_text(sentence(sub->get_description())) << " See \\fB"
        << roff_text(page_name(*sub), true) << "\\fR(1).\n";
  }
  out << ".SH EXIT STATUS\n"
         "0 on success; 1 on a user error (a bad option, an unreadable or malformed file, a value "
         "out of range), with one line on standard error saying what was expected; 2 on an "
         "internal error.\n";
  out << ".SH SEE ALSO\n";
  const auto commands = visible_commands(app);
  for (std::size_t k = 0; k < commands.size(); ++k) {
    out << ".BR " << roff_text(page_name(*commands[k]), true) << " (1)"
        << (k + 1 < commands.size() ? "," : "") << "\n";
  }
}

// The completion's tables: for each command path ("fspm", "fspm tree", ...) its commands, its
// options and those of its options that take a value (after which bash completes file names).
struct CompletionTables {
  std::ostringstream commands, options, valued;
};

std::vector<std::string> option_words(const CLI::App& app, bool with_values_only) {
  std::vector<std::string> words;
  for (const CLI::Option* o : app.get_options([](const CLI::Option* o) { return visible(o); })) {
    if (with_values_only && !takes_value(o)) continue;
    for (const std::string& s : o->get_snames()) words.push_back("-" + s);
    for (const std::string& l : o->get_lnames()) words.push_back("--" + l);
  }
  return words;
}

// A command's own options and, after them, those of fspm itself it accepts too (CLI11's
// fallthrough), each once; --version only at the top.
std::string option_row(const CLI::App& app, bool with_values_only) {
  std::vector<std::string> words = option_words(app, with_values_only);
  const CLI::App* top = &app;
  while (top->get_parent() != nullptr) top = top->get_parent();
  if (top != &app) {
    for (const std::string& w : option_words(*top, with_values_only)) {
      if (w != "--version" && std::find(words.begin(), words.end(), w) == words.end()) {
        words.push_back(w);
      }
    }
  }
  std::string row;
  for (const std::string& w : words) row += " " + w;
  return row;
}

void add_completion_rows(CompletionTables& t, const CLI::App& app) {
  const std::string key = "[\"" + command_path(app) + "\"]=\"";
  std::string names;
  for (const CLI::App* sub : visible_commands(app)) names += " " + sub->get_name();
  t.commands << "    " << key << names << "\"\n";
  t.options << "    " << key << option_row(app, false) << "\"\n";
  t.valued << "    " << key << option_row(app, true) << "\"\n";
  for (const CLI::App* sub : visible_commands(app)) add_completion_rows(t, *sub);
}

}  // namespace

std::vector<const CLI::App*> visible_commands(const CLI::App& app) {
  return app.get_subcommands([](const CLI::App* sub) {
    return !sub->get_name().empty() && !sub->get_group().empty() && !sub->get_disabled();
  });
}

std::string man_page(const CLI::App& app, const std::string& version) {
  std::ostringstream out;
  const bool top = app.get_parent() == nullptr;
  out << ".\\\" Written by `fspm-full write-manual` from the command line's definitions.\n"
      << ".TH " << roff_text(upper(page_name(app)), true) << " 1 \"\" \"" << roff_text(version)
      << "\" \"fspm manual\"\n"
      << ".SH NAME\n"
      << roff_text(page_name(app), true) << " \\- " << roff_text(summary(app)) << "\n"
      << ".SH SYNOPSIS\n";
  write_synopsis(out, app);
  out << ".SH DESCRIPTION\n" << roff_text(app.get_description()) << "\n";
  const std::string footer = app.get_footer();
  if (!footer.empty() && footer != "\n") out << ".PP\n" << roff_text(footer) << "\n";
  out << ".SH OPTIONS\n";
  write_options(out, app);
  if (top) {
    write_top_page_body(out, app);
    return out.str();
  }
  out << ".PP\nThe options of \\fBfspm\\fR(1) (\\-v, \\-q, \\-\\-memory\\-limit, \\-\\-json, "
         "...) are accepted after the command too.\n";
  if (!visible_commands(app).empty()) {
    out << ".SH COMMANDS\n";
    write_command_sections(out, app);
  }
  out << ".SH SEE ALSO\n.BR fspm (1)\n";
  return out.str();
}

std::string bash_completion(const CLI::App& app) {
  CompletionTables t;
  add_completion_rows(t, app);
  std::ostringstream out;
  out << "# bash completion for fspm and fspm-full, written by `fspm-full write-manual` from the\n"
         "# command line's definitions.\n"
         "_fspm() {\n"
         "  local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]}\n"
         "  local -A commands=(\n"
      << t.commands.str()
      << "  )\n"
         "  local -A options=(\n"
      << t.options.str()
      << "  )\n"
         "  local -A valued=(\n"
      << t.valued.str()
      << "  )\n"
         "  # The command path so far, skipping the values of options.\n"
         "  local path=fspm word k\n"
         "  for ((k = 1; k < COMP_CWORD; k++)); do\n"
         "    word=${COMP_WORDS[k]}\n"
         "    if [[ \" ${valued[$path]} \" == *\" $word \"* ]]; then\n"
         "      ((k++))\n"
         "    elif [[ \" ${commands[$path]} \" == *\" $word \"* ]]; then\n"
         "      path=\"$path $word\"\n"
         "    fi\n"
         "  done\n"
         "  # After an option that takes a value: file names (complete -o default).\n"
         "  [[ \" ${valued[$path]} \" == *\" $prev \"* ]] && return 0\n"
         "  if [[ $cur == -* ]]; then\n"
         "    mapfile -t COMPREPLY < <(compgen -W \"${options[$path]}\" -- "
         "\"$cur\")\n"
         "  else\n"
         "    mapfile -t COMPREPLY < <(compgen -W \"${commands[$path]}\" -- \"$cur\")\n"
         "  fi\n"
         "}\n"
         "complete -o default -F _fspm fspm fspm-full\n";
  return out.str();
}

void write_manual(const CLI::App& app, const std::string& version,
                  const std::filesystem::path& man_dir,
                  const std::filesystem::path& completion_file) {
  std::error_code ec;
  std::filesystem::create_directories(man_dir, ec);
  if (ec) throw IoError("cannot create " + man_dir.string() + ": " + ec.message());
  const auto write = [](const std::filesystem::path& path, const std::string& text) {
    write_file_atomically(path.string(), [&](std::ostream& out) { out << text; });
  };
  write(man_dir / "fspm.1", man_page(app, version));
  for (const CLI::App* sub : visible_commands(app)) {
    write(man_dir / (page_name(*sub) + ".1"), man_page(*sub, version));
  }
  if (completion_file.has_parent_path()) {
    std::filesystem::create_directories(completion_file.parent_path(), ec);
    if (ec) throw IoError("cannot create " + completion_file.parent_path().string());
  }
  write(completion_file, bash_completion(app));
}

void add_manual_command(CLI::App& app, const std::string& version) {
  CLI::App* sub = app.add_subcommand(
      "write-manual", "Write the manual pages and the bash completion (run by the build)");
  sub->group("");  // hidden: not in --help, the pages or the completion
  auto man_dir = std::make_shared<std::string>();
  auto completion = std::make_shared<std::string>();
  sub->add_option("--man-dir", *man_dir, "Folder for fspm.1 and fspm-COMMAND.1")->required();
  sub->add_option("--bash-completion", *completion, "File for the bash completion script")
      ->required();
  sub->callback(
      [&app, version, man_dir, completion] { write_manual(app, version, *man_dir, *completion); });
}

}  // namespace fspm::cli
