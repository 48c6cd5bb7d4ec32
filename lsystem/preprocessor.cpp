#include "lsystem/preprocessor.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

#include "fspm/closest_name.hpp"
#include "fspm/error.hpp"
#include "fspm/input_file.hpp"
#include "lsystem/expression.hpp"

namespace fspm::lsystem {
namespace {

constexpr std::size_t kMaxExpandedLine = 1 << 20;
constexpr int kMaxIncludeDepth = 16;

bool ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

struct Macro {
  bool function_like = false;
  std::vector<std::string> params;
  std::string body;
};

struct Conditional {
  bool parent_active;
  bool taken;  // some branch of this #if chain was already active
  bool active;
  bool seen_else;
};

class EmptyScope : public NameScope {
 public:
  int find_local(const std::string&) const override { return -1; }
  int find_global(const std::string&) const override { return -1; }
  int create_variable(const std::string&, bool& is_global) override {
    is_global = false;
    return -1;
  }
};

class Preprocessor {
 public:
  explicit Preprocessor(const MacroOverrides& overrides) : overrides_(overrides) {
    for (const auto& [name, value] : overrides) macros_[name] = Macro{false, {}, value};
  }

  void run(std::string_view text, const std::string& name, const std::string& dir, int depth) {
    if (depth > kMaxIncludeDepth) {
      throw ParseError("#include nested too deeply (more than 16 levels)", name, 0, 0);
    }
    // Physical lines, with comments blanked out (columns preserved).
    std::vector<std::string> lines;
    {
      std::string current;
      bool in_comment = false;
      for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '\n') {
          lines.push_back(std::move(current));
          current.clear();
          continue;
        }
        if (in_comment) {
          if (c == '*' && i + 1 < text.size() && text[i + 1] == '/') {
            in_comment = false;
            current += "  ";
            ++i;
          } else {
            current += ' ';
          }
          continue;
        }
        if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
          in_comment = true;
          current += "  ";
          ++i;
          continue;
        }
        if (c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
          while (i + 1 < text.size() && text[i + 1] != '\n') ++i;
          continue;
        }
        current += (c == '\r' || c == '\t') ? ' ' : c;
      }
      lines.push_back(std::move(current));
    }
    note_overridden_names(lines);
    const std::size_t stack_depth = conditionals_.size();
    for (std::size_t i = 0; i < lines.size(); ++i) {
      const int line_no = static_cast<int>(i) + 1;
      std::string line = lines[i];
      // Backslash continuation joins physical lines; the logical line maps to the first one.
      while (!line.empty() && line.back() == '\\' && i + 1 < lines.size()) {
        line.pop_back();
        line += ' ';
        line += lines[++i];
      }
      std::size_t first = line.find_first_not_of(' ');
      if (first != std::string::npos && line[first] == '#' && abop_header(line, first)) {
        // ABOP writes `#ignore: +-F`; cpfg `ignore: +-F`.
        line[first] = ' ';
      }
      if (first != std::string::npos && line[first] == '#') {
        directive(line, first, name, dir, line_no, depth);
        out_.append("\n", name, line_no, static_cast<int>(line.size()) + 1);
        continue;
      }
      if (!active()) {
        out_.append("\n", name, line_no, 1);
        continue;
      }
      const std::string expanded = expand(line, {}, name, line_no);
      out_.append(expanded, name, line_no, 1);
      out_.append("\n", name, line_no, static_cast<int>(expanded.size()) + 1);
    }
    if (conditionals_.size() != stack_depth) {
      throw ParseError("expected #endif before the end of the file", name,
                       static_cast<int>(lines.size()), 1);
    }
  }

  SourceText take() { return std::move(out_); }

  // An override of a name the grammar never uses (a misspelled --define or define.NAME) would
  // silently change nothing: refuse it, naming the closest #define.
  void check_overrides_used(const std::string& file) const {
    for (const auto& [name, value] : overrides_) {
      if (used_names_.count(name)) continue;
      throw ValueError("cannot override the macro '" + name + "': the L-system never uses it" +
                           closest_name_hint(name, defined_names_),
                       file);
    }
  }

 private:
  static bool abop_header(const std::string& line, std::size_t hash) {
    for (const char* word : {"ignore", "consider"}) {
      const std::size_t n = std::char_traits<char>::length(word);
      if (line.compare(hash + 1, n, word) == 0) {
        std::size_t p = hash + 1 + n;
        while (p < line.size() && line[p] == ' ') ++p;
        if (p < line.size() && line[p] == ':') return true;
      }
    }
    return false;
  }

  bool active() const { return conditionals_.empty() || conditionals_.back().active; }

  void note_overridden_names(const std::vector<std::string>& lines) {
    if (overrides_.empty()) return;
    for (const std::string& line : lines) {
      for (std::size_t at = 0; at < line.size();) {
        if (!ident_start(line[at]) || (at > 0 && ident_char(line[at - 1]))) {
          ++at;
          continue;
        }
        std::size_t end = at;
        while (end < line.size() && ident_char(line[end])) ++end;
        const std::string word = line.substr(at, end - at);
        if (overrides_.count(word)) used_names_.insert(word);
        at = end;
      }
    }
  }

  void directive(const std::string& line, std::size_t hash, const std::string& file,
                 const std::string& dir, int line_no, int depth) {
    std::size_t p = hash + 1;
    while (p < line.size() && line[p] == ' ') ++p;
    std::size_t q = p;
    while (q < line.size() && ident_char(line[q])) ++q;
    const std::string word = line.substr(p, q - p);
    auto fail = [&](const std::string& msg, std::size_t at) {
      throw ParseError(msg, file, line_no, static_cast<int>(at) + 1);
    };
    auto skip = [&](std::size_t at) {
      while (at < line.size() && line[at] == ' ') ++at;
      return at;
    };
    auto read_ident = [&](std::size_t at, std::string& out) {
      at = skip(at);
      if (at >= line.size() || !ident_start(line[at])) fail("expected a macro name", at);
      std::size_t e = at;
      while (e < line.size() && ident_char(line[e])) ++e;
      out = line.substr(at, e - at);
      return e;
    };
    if (word == "ifdef" || word == "ifndef") {
      std::string name;
      read_ident(q, name);
      const bool defined = macros_.count(name) > 0;
      push(word == "ifdef" ? defined : !defined);
      return;
    }
    if (word == "if") {
      push(active() && evaluate_condition(line.substr(q), file, line_no, static_cast<int>(q)));
      return;
    }
    if (word == "elif" || word == "else" || word == "endif") {
      if (conditionals_.empty()) fail("#" + word + " without a matching #if", hash);
      Conditional& c = conditionals_.back();
      if (word == "endif") {
        conditionals_.pop_back();
        return;
      }
      if (c.seen_else) fail("#" + word + " after #else", hash);
      if (word == "else") {
        c.seen_else = true;
        c.active = c.parent_active && !c.taken;
      } else {
        c.active = c.parent_active && !c.taken &&
                   evaluate_condition(line.substr(q), file, line_no, static_cast<int>(q));
      }
      c.taken = c.taken || c.active;
      return;
    }
    if (!active()) return;
    if (word == "define") {
      std::string name;
      std::size_t at = read_ident(q, name);
      Macro m;
      if (at < line.size() && line[at] == '(') {
        m.function_like = true;
        ++at;
        for (;;) {
          at = skip(at);
          if (at < line.size() && line[at] == ')') {
            ++at;
            break;
          }
          std::string param;
          at = read_ident(at, param);
          m.params.push_back(param);
          at = skip(at);
          if (at < line.size() && line[at] == ',') {
            ++at;
            continue;
          }
          if (at < line.size() && line[at] == ')') {
            ++at;
            break;
          }
          fail("expected ',' or ')' in the parameter list of macro " + name, at);
        }
      }
      at = skip(at);
      std::string body = line.substr(std::min(at, line.size()));
      while (!body.empty() && body.back() == ' ') body.pop_back();
      m.body = body;
      if (std::find(defined_names_.begin(), defined_names_.end(), name) == defined_names_.end()) {
        defined_names_.push_back(name);
      }
      if (!overrides_.count(name)) macros_[name] = m;
      return;
    }
    if (word == "undef") {
      std::string name;
      read_ident(q, name);
      if (!overrides_.count(name)) macros_.erase(name);
      return;
    }
    if (word == "include") {
      std::size_t at = skip(q);
      if (at >= line.size() || (line[at] != '"' && line[at] != '<')) {
        fail("expected \"file\" after #include", at);
      }
      const char close = line[at] == '"' ? '"' : '>';
      const std::size_t end = line.find(close, at + 1);
      if (end == std::string::npos) fail("expected the closing quote of the #include file", at);
      const std::string rel = line.substr(at + 1, end - at - 1);
      const std::filesystem::path path = std::filesystem::path(dir) / rel;
      std::string included;
      try {
        included = read_text_input_file(path.string());
      } catch (const IoError& error) {
        throw IoError("cannot read included file '" + path.string() + "': " + error.message(), file,
                      line_no, static_cast<int>(at) + 1);
      }
      run(included, path.string(), path.parent_path().string(), depth + 1);
      return;
    }
    if (word == "pragma" || word == "line" || word.empty()) return;
    if (word == "error") fail("#error" + line.substr(q), hash);
    fail("unknown preprocessor directive '#" + word + "'", hash);
  }

  void push(bool condition) {
    const bool parent = active();
    conditionals_.push_back({parent, parent && condition, parent && condition, false});
  }

  bool evaluate_condition(const std::string& text, const std::string& file, int line_no,
                          int column) {
    // defined(X) / defined X first, then macro expansion; identifiers left over are 0 (C rule).
    std::string resolved;
    for (std::size_t i = 0; i < text.size();) {
      if (ident_start(text[i])) {
        std::size_t e = i;
        while (e < text.size() && ident_char(text[e])) ++e;
        std::string word = text.substr(i, e - i);
        if (word == "defined") {
          std::size_t a = e;
          while (a < text.size() && text[a] == ' ') ++a;
          const bool paren = a < text.size() && text[a] == '(';
          if (paren) ++a;
          while (a < text.size() && text[a] == ' ') ++a;
          std::size_t b = a;
          while (b < text.size() && ident_char(text[b])) ++b;
          const std::string name = text.substr(a, b - a);
          if (paren) {
            while (b < text.size() && text[b] == ' ') ++b;
            if (b < text.size() && text[b] == ')') ++b;
          }
          resolved += macros_.count(name) ? " 1 " : " 0 ";
          i = b;
          continue;
        }
        resolved += word;
        i = e;
        continue;
      }
      resolved += text[i++];
    }
    std::string expanded = expand(resolved, {}, file, line_no);
    std::string cleaned;
    for (std::size_t i = 0; i < expanded.size();) {
      if (std::isdigit(static_cast<unsigned char>(expanded[i]))) {
        while (i < expanded.size() && (ident_char(expanded[i]) || expanded[i] == '.')) {
          cleaned += expanded[i++];
        }
        continue;
      }
      if (ident_start(expanded[i])) {
        std::size_t e = i;
        while (e < expanded.size() && ident_char(expanded[e])) ++e;
        cleaned += " 0 ";
        i = e;
        continue;
      }
      cleaned += expanded[i++];
    }
    SourceText src;
    src.append(cleaned, file, line_no, column + 1);
    Cursor cur(src, 0, cleaned.size());
    EmptyScope scope;
    ExpressionCompiler compiler(cur, scope);
    Expression e = compiler.compile();
    cur.skip_space();
    if (!cur.at_end()) cur.fail("end of the #if expression");
    std::mt19937_64 rng(0);
    EvalState state{nullptr, nullptr, &rng};
    return e.evaluate(state) != 0.0;
  }

  // Expands macros in `text`; names in `disabled` are not expanded again (C rule against
  // self-reference).
  std::string expand(const std::string& text, const std::set<std::string>& disabled,
                     const std::string& file, int line_no) {
    if (disabled.size() > 256) {
      throw ParseError("macros nested more than 256 deep", file, line_no, 1);
    }
    std::string out;
    for (std::size_t i = 0; i < text.size();) {
      const char c = text[i];
      if (std::isdigit(static_cast<unsigned char>(c)) ||
          (c == '.' && i + 1 < text.size() &&
           std::isdigit(static_cast<unsigned char>(text[i + 1])))) {
        // pp-number: 1e-5, 2.5f ... never contains a macro.
        while (i < text.size() && (ident_char(text[i]) || text[i] == '.' ||
                                   ((text[i] == '+' || text[i] == '-') &&
                                    (text[i - 1] == 'e' || text[i - 1] == 'E')))) {
          out += text[i++];
        }
        continue;
      }
      if (!ident_start(c)) {
        out += c;
        ++i;
        continue;
      }
      std::size_t e = i;
      while (e < text.size() && ident_char(text[e])) ++e;
      const std::string name = text.substr(i, e - i);
      auto it = macros_.find(name);
      if (it == macros_.end() || disabled.count(name)) {
        out += name;
        i = e;
        continue;
      }
      const Macro& m = it->second;
      std::set<std::string> inner = disabled;
      inner.insert(name);
      if (!m.function_like) {
        out += expand(m.body, inner, file, line_no);
        i = e;
      } else {
        std::size_t a = e;
        while (a < text.size() && text[a] == ' ') ++a;
        if (a >= text.size() || text[a] != '(') {
          out += name;
          i = e;
          continue;
        }
        std::vector<std::string> args(1);
        int depth = 0;
        std::size_t b = a + 1;
        for (; b < text.size(); ++b) {
          const char d = text[b];
          if (d == '(') {
            ++depth;
          } else if (d == ')') {
            if (depth == 0) break;
            --depth;
          } else if (d == ',' && depth == 0) {
            args.emplace_back();
            continue;
          }
          args.back() += d;
        }
        if (b >= text.size()) {
          throw ParseError("expected ')' closing the arguments of macro " + name, file, line_no,
                           static_cast<int>(a) + 1);
        }
        if (m.params.empty() && args.size() == 1 &&
            args[0].find_first_not_of(' ') == std::string::npos) {
          args.clear();
        }
        if (args.size() != m.params.size()) {
          throw ParseError("macro " + name + " expects " + std::to_string(m.params.size()) +
                               " argument(s), got " + std::to_string(args.size()),
                           file, line_no, static_cast<int>(i) + 1);
        }
        for (auto& arg : args) arg = expand(arg, disabled, file, line_no);
        std::string body;
        for (std::size_t k = 0; k < m.body.size();) {
          if (ident_start(m.body[k])) {
            std::size_t f = k;
            while (f < m.body.size() && ident_char(m.body[f])) ++f;
            const std::string word = m.body.substr(k, f - k);
            std::size_t idx = 0;
            while (idx < m.params.size() && m.params[idx] != word) ++idx;
            body += idx < m.params.size() ? args[idx] : word;
            k = f;
          } else {
            body += m.body[k++];
          }
        }
        out += expand(body, inner, file, line_no);
        i = b + 1;
      }
      if (out.size() > kMaxExpandedLine) {
        throw ParseError("macro expansion longer than 1 MB (recursive macros?)", file, line_no, 1);
      }
    }
    return out;
  }

  const MacroOverrides& overrides_;
  std::map<std::string, Macro> macros_;
  std::set<std::string> used_names_;        // overridden names the text mentions
  std::vector<std::string> defined_names_;  // every #define, for "did you mean"
  std::vector<Conditional> conditionals_;
  SourceText out_;
};

}  // namespace

SourceText preprocess_text(std::string_view text, const std::string& name,
                           const MacroOverrides& overrides, const std::string& include_dir) {
  Preprocessor pp(overrides);
  pp.run(text, name, include_dir, 0);
  pp.check_overrides_used(name);
  return pp.take();
}

SourceText preprocess_file(const std::string& path, const MacroOverrides& overrides) {
  const std::string text = read_text_input_file(path);
  const std::string dir = std::filesystem::path(path).parent_path().string();
  return preprocess_text(text, path, overrides, dir.empty() ? "." : dir);
}

}  // namespace fspm::lsystem
