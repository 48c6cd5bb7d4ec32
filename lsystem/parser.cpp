#include "lsystem/parser.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <set>

#include "fspm/error.hpp"
#include "fspm/nesting_depth.hpp"

namespace fspm::lsystem {

int GlobalVariables::find(const std::string& name) const {
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (names[i] == name) return static_cast<int>(i);
  }
  return -1;
}

int GlobalVariables::add(const std::string& name, double value) {
  const int existing = find(name);
  if (existing >= 0) return existing;
  names.push_back(name);
  values.push_back(value);
  return static_cast<int>(names.size() - 1);
}

void ProductionGroup::index(std::size_t symbol_count) {
  productions_for.assign(symbol_count, {});
  for (std::size_t i = 0; i < productions.size(); ++i) {
    productions_for[productions[i].predecessor.symbol].push_back(static_cast<std::uint32_t>(i));
  }
}

int LSystem::local_frame_size() const {
  int n = 0;
  for (const ProductionGroup* g : {&productions, &decomposition, &homomorphism}) {
    for (const Production& p : g->productions) n = std::max(n, p.local_count);
  }
  return n;
}

namespace {

bool ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

class LocalScope : public NameScope {
 public:
  LocalScope(GlobalVariables& globals, bool has_frame) : globals_(globals), has_frame_(has_frame) {}
  int find_local(const std::string& name) const override {
    for (std::size_t i = 0; i < locals_.size(); ++i) {
      if (locals_[i] == name) return static_cast<int>(i);
    }
    return -1;
  }
  int find_global(const std::string& name) const override { return globals_.find(name); }
  int create_variable(const std::string& name, bool& is_global) override {
    is_global = !has_frame_;
    if (is_global) return globals_.add(name);
    locals_.push_back(name);
    return static_cast<int>(locals_.size() - 1);
  }
  int add_local(const std::string& name) {
    locals_.push_back(name);
    return static_cast<int>(locals_.size() - 1);
  }
  int size() const { return static_cast<int>(locals_.size()); }

 private:
  GlobalVariables& globals_;
  bool has_frame_;
  std::vector<std::string> locals_;
};

class Parser {
 public:
  explicit Parser(const SourceText& src) : src_(src), text_(src.text()) {}

  LSystem run() {
    sys_.file = src_.position(0).file;
    std::size_t pos = 0;
    ProductionGroup* group = &sys_.productions;
    bool axiom_seen = false;
    detect_numbered_names();
    while (pos < text_.size()) {
      std::size_t eol = text_.find('\n', pos);
      if (eol == std::string::npos) eol = text_.size();
      std::size_t b = pos;
      while (b < eol && std::isspace(static_cast<unsigned char>(text_[b]))) ++b;
      if (b == eol) {
        pos = eol + 1;
        continue;
      }
      std::size_t after = 0;
      if (match_word(b, eol, "endlsystem", after)) break;
      if (match_word(b, eol, "decomposition", after)) {
        group = &sys_.decomposition;
        pos = eol + 1;
        continue;
      }
      if (match_word(b, eol, "homomorphism", after)) {
        group = &sys_.homomorphism;
        pos = eol + 1;
        continue;
      }
      if (match_header(b, eol, "lsystem", after)) {
        sys_.number = static_cast<int>(
            clamp_to_integer(header_number(after, eol, "an L-system number"), 0, 1 << 30));
      } else if (match_header(b, eol, "seed", after)) {
        const double v = header_number(after, eol, "a seed (a non-negative integer)");
        sys_.seed = static_cast<std::uint64_t>(clamp_to_integer(v < 0 ? -v : v, 0, 1LL << 62));
      } else if (match_header(b, eol, "derivation length", after)) {
        const double v = header_number(after, eol, "a derivation length (an integer >= 0)");
        if (!(v >= 0 && v <= kMaxDerivationLength)) {
          Cursor(src_, after, eol)
              .fail_at(after, "derivation length must be an integer in [0, " +
                                  std::to_string(kMaxDerivationLength) + "]");
        }
        sys_.derivation_length = static_cast<int>(v);
      } else if (match_header(b, eol, "maximum depth", after)) {
        const double v = header_number(after, eol, "a maximum depth (an integer >= 1)");
        const int depth = static_cast<int>(clamp_to_integer(v, 1, 10000));
        if (group == &sys_.productions) {
          sys_.maximum_depth = depth;
        } else {
          group->maximum_depth = depth;
        }
      } else if (match_header(b, eol, "ignore", after)) {
        read_symbol_list(after, eol, ignore_);
      } else if (match_header(b, eol, "consider", after)) {
        read_symbol_list(after, eol, consider_);
        has_consider_ = true;
      } else if (match_header(b, eol, "axiom", after)) {
        Cursor cur(src_, after, eol);
        LocalScope scope(sys_.globals, true);
        sys_.axiom = read_successor(cur, scope, false);
        axiom_seen = true;
      } else if (match_header(b, eol, "define", after)) {
        eol = read_block(after, sys_.define_block);
      } else if (match_header(b, eol, "starteach", after)) {
        eol = read_block(after, sys_.start_each_block);
      } else if (match_header(b, eol, "start", after)) {
        eol = read_block(after, sys_.start_block);
      } else if (match_header(b, eol, "endeach", after)) {
        eol = read_block(after, sys_.end_each_block);
      } else if (match_header(b, eol, "end", after)) {
        eol = read_block(after, sys_.end_block);
      } else if (match_header(b, eol, "view", after) || match_header(b, eol, "surface", after) ||
                 match_header(b, eol, "warnings", after)) {
        // Settings cpfg reads elsewhere; nothing to do here.
      } else {
        eol = production_end(b, eol);
        group->productions.push_back(read_production(b, eol));
      }
      pos = eol + 1;
    }
    if (!axiom_seen) {
      throw ParseError("expected an 'Axiom:' line in the L-system", sys_.file, 0, 0);
    }
    for (ProductionGroup* g : {&sys_.productions, &sys_.decomposition, &sys_.homomorphism}) {
      g->index(sys_.symbols.size());
    }
    sys_.ignored.assign(sys_.symbols.size(), 0);
    if (has_consider_) {
      std::fill(sys_.ignored.begin(), sys_.ignored.end(), 1);
      for (SymbolId s : consider_) sys_.ignored[s] = 0;
    }
    for (SymbolId s : ignore_) sys_.ignored[s] = 1;
    sys_.ignored[kOpenBranch] = 0;
    sys_.ignored[kCloseBranch] = 0;
    return std::move(sys_);
  }

 private:
  // GreenLab files name modules B0, M12 ...; cpfg files use one character per module (F1F1 is
  // F 1 F 1). Numbered names are on when some predecessor is written as a letter + digits.
  void detect_numbered_names() {
    std::size_t pos = 0;
    while (pos < text_.size()) {
      std::size_t eol = text_.find('\n', pos);
      if (eol == std::string::npos) eol = text_.size();
      std::size_t arrow = find_top(pos, eol, "->");
      if (arrow != std::string::npos) {
        std::size_t head_end = find_top(pos, arrow, ":");
        if (head_end == std::string::npos) head_end = arrow;
        if (head_end > pos && text_[head_end - 1] == '-') --head_end;
        std::size_t b = pos;
        const std::size_t lt = find_top(pos, head_end, "<");
        if (lt != std::string::npos) b = lt + 1;
        std::size_t e = head_end;
        const std::size_t gt = find_top(b, head_end, ">");
        if (gt != std::string::npos) e = gt;
        while (b < e && std::isspace(static_cast<unsigned char>(text_[b]))) ++b;
        std::size_t k = b;
        if (k < e && std::isalpha(static_cast<unsigned char>(text_[k]))) {
          ++k;
          const std::size_t digits = k;
          while (k < e && std::isdigit(static_cast<unsigned char>(text_[k]))) ++k;
          if (k > digits) {
            if (k < e && text_[k] == '(') {
              int depth = 0;
              for (; k < e; ++k) {
                if (text_[k] == '(') ++depth;
                if (text_[k] == ')' && --depth == 0) {
                  ++k;
                  break;
                }
              }
            }
            while (k < e && std::isspace(static_cast<unsigned char>(text_[k]))) ++k;
            if (k == e) numbered_ = true;
          }
        }
      }
      pos = eol + 1;
    }
  }

  std::string module_name(Cursor& cur) const { return read_module_name(cur, numbered_); }

  // Case-insensitive `word` (spaces inside the word may vary) followed by ':'.
  bool match_header(std::size_t b, std::size_t e, const char* word, std::size_t& after) const {
    std::size_t p = b;
    for (const char* w = word; *w; ++w) {
      if (*w == ' ') {
        while (p < e && text_[p] == ' ') ++p;
        continue;
      }
      if (p >= e || std::tolower(static_cast<unsigned char>(text_[p])) != *w) return false;
      ++p;
    }
    while (p < e && text_[p] == ' ') ++p;
    if (p >= e || text_[p] != ':') return false;
    after = p + 1;
    return true;
  }

  // Case-insensitive `word` as the first word on the line (a section keyword).
  bool match_word(std::size_t b, std::size_t e, const char* word, std::size_t& after) const {
    const std::size_t n = std::strlen(word);
    if (b + n > e) return false;
    for (std::size_t i = 0; i < n; ++i) {
      if (std::tolower(static_cast<unsigned char>(text_[b + i])) != word[i]) return false;
    }
    if (b + n < e && ident_char(text_[b + n])) return false;
    // A production such as `homomorphism --> x` cannot exist (multi-letter names are not
    // modules), so the keyword alone decides.
    after = b + n;
    return true;
  }

  double header_number(std::size_t b, std::size_t e, std::string_view what) {
    Cursor cur(src_, b, e);
    LocalScope scope(sys_.globals, false);
    ExpressionCompiler compiler(cur, scope);
    cur.skip_space();
    if (cur.at_end()) cur.fail(what);
    Expression ex = compiler.compile();
    cur.skip_space();
    if (!cur.at_end()) cur.fail("end of line after " + std::string(what));
    std::mt19937_64 rng(0);
    EvalState state{nullptr, sys_.globals.values.data(), &rng};
    return ex.evaluate(state);
  }

  void read_symbol_list(std::size_t b, std::size_t e, std::vector<SymbolId>& out) {
    Cursor cur(src_, b, e);
    for (;;) {
      cur.skip_space();
      if (cur.at_end()) break;
      out.push_back(sys_.symbols.intern(module_name(cur)));
    }
  }

  // `{ statements }` possibly over several lines; returns the end of the line holding '}'.
  std::size_t read_block(std::size_t after, std::vector<Expression>& out) {
    Cursor cur(src_, after, text_.size());
    cur.expect('{', "'{' opening the block");
    LocalScope scope(sys_.globals, false);
    ExpressionCompiler compiler(cur, scope);
    auto statements = compiler.compile_statements('}');
    cur.expect('}', "'}' closing the block");
    out.insert(out.end(), std::make_move_iterator(statements.begin()),
               std::make_move_iterator(statements.end()));
    std::size_t eol = text_.find('\n', cur.pos());
    if (eol == std::string::npos) eol = text_.size();
    Cursor tail(src_, cur.pos(), eol);
    tail.skip_space();
    if (!tail.at_end()) tail.fail("end of line after the block");
    return eol;
  }

  // A production whose {blocks} are not closed on its line continues on the next lines.
  std::size_t production_end(std::size_t b, std::size_t eol) const {
    int depth = 0;
    std::size_t p = b;
    for (;;) {
      for (; p < eol; ++p) {
        if (text_[p] == '{') ++depth;
        if (text_[p] == '}') --depth;
      }
      if (depth <= 0 || eol >= text_.size()) return eol;
      p = eol + 1;
      eol = text_.find('\n', p);
      if (eol == std::string::npos) eol = text_.size();
    }
  }

  // Position of `what` at paren/brace depth 0 in [b, e), or npos.
  std::size_t find_top(std::size_t b, std::size_t e, std::string_view what) const {
    int depth = 0;
    for (std::size_t p = b; p < e; ++p) {
      const char c = text_[p];
      if (c == '(' || c == '{') ++depth;
      if (c == ')' || c == '}') --depth;
      if (depth == 0 && text_.compare(p, what.size(), what) == 0 && p + what.size() <= e) {
        return p;
      }
    }
    return std::string::npos;
  }

  ModulePattern read_pattern(Cursor& cur, LocalScope& scope) {
    ModulePattern m;
    const std::size_t at = cur.pos();
    const std::string name = module_name(cur);
    if (name == "(" || name == ")" || name == "," || name == ":" || name == "<" || name == ">") {
      cur.fail_at(at, "expected a module name, found '" + name + "'");
    }
    m.symbol = sys_.symbols.intern(name);
    if (cur.peek() == '(') {
      cur.advance();
      for (;;) {
        cur.skip_space();
        if (!ident_start(cur.peek())) cur.fail("a formal parameter name");
        std::size_t n = 0;
        while (ident_char(cur.peek(n))) ++n;
        const std::string param(cur.rest().substr(0, n));
        if (scope.find_local(param) >= 0) {
          cur.fail_at(cur.pos(), "parameter '" + param + "' declared twice in the predecessor");
        }
        cur.advance(n);
        m.slots.push_back(scope.add_local(param));
        if (cur.accept(",")) continue;
        cur.expect(')', "',' or ')' in the formal parameter list");
        break;
      }
    }
    return m;
  }

  std::vector<ModulePattern> read_context(std::size_t b, std::size_t e, LocalScope& scope) {
    Cursor cur(src_, b, e);
    cur.skip_space();
    std::vector<ModulePattern> out;
    if (cur.peek() == '*') {
      cur.advance();
      cur.skip_space();
      if (!cur.at_end()) cur.fail("nothing after '*' (any context)");
      return out;
    }
    for (;;) {
      cur.skip_space();
      if (cur.at_end()) break;
      out.push_back(read_pattern(cur, scope));
    }
    return out;
  }

  std::vector<ModuleTemplate> read_successor(Cursor& cur, LocalScope& scope, bool stop_at_colon) {
    std::vector<ModuleTemplate> out;
    cur.skip_space();
    const std::size_t star = cur.pos();
    if (cur.peek() == '*') {
      Cursor probe = cur;
      probe.advance();
      probe.skip_space();
      if (probe.at_end() || (stop_at_colon && probe.peek() == ':')) {
        cur.set_pos(probe.pos());
        return out;  // `*`: the empty successor
      }
    }
    cur.set_pos(star);
    std::vector<std::size_t> open;  // positions of the '[' not closed yet
    for (;;) {
      cur.skip_space();
      if (cur.at_end() || (stop_at_colon && cur.peek() == ':')) break;
      const std::size_t at = cur.pos();
      const std::string name = module_name(cur);
      if (name == "(" || name == ")" || name == ",") {
        cur.fail_at(at, "expected a module, found '" + name + "'");
      }
      track_bracket(cur, name, at, open);
      ModuleTemplate m;
      m.symbol = sys_.symbols.intern(name);
      if (cur.peek() == '(') {
        cur.advance();
        ExpressionCompiler compiler(cur, scope);
        for (;;) {
          m.arguments.push_back(compiler.compile());
          if (cur.accept(",")) continue;
          cur.expect(')', "',' or ')' after a module parameter");
          break;
        }
      }
      out.push_back(std::move(m));
    }
    if (!open.empty()) cur.fail_at(open.back(), "this '[' is never closed by a ']'");
    return out;
  }

  // Branches of an axiom or successor must balance, and nest at most kMaxTreeDepth deep.
  static void track_bracket(const Cursor& cur, const std::string& name, std::size_t at,
                            std::vector<std::size_t>& open) {
    if (name == "[") {
      if (open.size() >= static_cast<std::size_t>(kMaxTreeDepth)) {
        cur.fail_at(at, nesting_too_deep(kMaxTreeDepth, "branches '['"));
      }
      open.push_back(at);
    } else if (name == "]") {
      if (open.empty()) cur.fail_at(at, "']' without a matching '['");
      open.pop_back();
    }
  }

  std::vector<Expression> read_inline_block(Cursor& cur, LocalScope& scope) {
    cur.expect('{', "'{'");
    ExpressionCompiler compiler(cur, scope);
    auto statements = compiler.compile_statements('}');
    cur.expect('}', "'}' closing the block");
    return statements;
  }

  Production read_production(std::size_t b, std::size_t e) {
    Production p;
    p.position = src_.position(b);
    std::size_t arrow = find_top(b, e, "-->");
    std::size_t arrow_len = 3;
    if (arrow == std::string::npos) {
      arrow = find_top(b, e, "->");
      arrow_len = 2;
    }
    if (arrow == std::string::npos) {
      Cursor(src_, b, e)
          .fail_at(b,
                   "expected a header (Axiom:, derivation length:, ...) or a production 'pred --> "
                   "succ'");
    }
    LocalScope scope(sys_.globals, true);
    const std::size_t colon = find_top(b, arrow, ":");
    const std::size_t head_end = colon == std::string::npos ? arrow : colon;
    // Head: [lc <] pred [> rc]
    const std::size_t lt = find_top(b, head_end, "<");
    const std::size_t gt = find_top(lt == std::string::npos ? b : lt + 1, head_end, ">");
    const std::size_t pred_b = lt == std::string::npos ? b : lt + 1;
    const std::size_t pred_e = gt == std::string::npos ? head_end : gt;
    if (lt != std::string::npos) p.left = read_context(b, lt, scope);
    {
      Cursor cur(src_, pred_b, pred_e);
      cur.skip_space();
      if (cur.at_end()) cur.fail("a predecessor module");
      p.predecessor = read_pattern(cur, scope);
      if (p.predecessor.symbol == kOpenBranch || p.predecessor.symbol == kCloseBranch) {
        cur.fail_at(pred_b, "expected a predecessor module other than '[' or ']'");
      }
      cur.skip_space();
      if (!cur.at_end()) cur.fail("'<', '>', ':' or '-->' after the predecessor (one module)");
    }
    if (gt != std::string::npos) p.right = read_context(gt + 1, head_end, scope);
    if (colon != std::string::npos) {
      Cursor cur(src_, colon + 1, arrow);
      cur.skip_space();
      if (cur.peek() == '{') p.pre_block = read_inline_block(cur, scope);
      cur.skip_space();
      if (cur.peek() == '*') {
        cur.advance();
      } else if (!cur.at_end() && cur.peek() != '{') {
        ExpressionCompiler compiler(cur, scope);
        p.condition = compiler.compile();
      }
      cur.skip_space();
      if (cur.peek() == '{') p.post_block = read_inline_block(cur, scope);
      cur.skip_space();
      if (!cur.at_end()) cur.fail("'-->' after the condition");
    }
    Cursor cur(src_, arrow + arrow_len, e);
    p.successor = read_successor(cur, scope, true);
    if (cur.accept(":")) {
      ExpressionCompiler compiler(cur, scope);
      cur.skip_space();
      if (cur.at_end()) cur.fail("a probability after ':'");
      p.probability = compiler.compile();
      cur.skip_space();
      if (!cur.at_end()) cur.fail("end of the production after the probability");
    }
    p.local_count = scope.size();
    return p;
  }

  const SourceText& src_;
  const std::string& text_;
  LSystem sys_;
  std::vector<SymbolId> ignore_, consider_;
  bool has_consider_ = false;
  bool numbered_ = false;
};

}  // namespace

std::string read_module_name(Cursor& cur, bool numbered_names) {
  const char c = cur.peek();
  if (cur.at_end()) cur.fail("a module name");
  std::string name(1, c);
  cur.advance();
  if (numbered_names && std::isalpha(static_cast<unsigned char>(c))) {
    while (std::isdigit(static_cast<unsigned char>(cur.peek()))) {
      name += cur.peek();
      cur.advance();
    }
  } else if (c == '?' && std::strchr("PHULE", cur.peek()) && cur.peek() != '\0') {
    name += cur.peek();
    cur.advance();
  } else if ((c == '@' || c == '~') && !cur.at_end() &&
             !std::isspace(static_cast<unsigned char>(cur.peek())) && cur.peek() != '(') {
    name += cur.peek();
    cur.advance();
    if (name == "@G" && std::isalpha(static_cast<unsigned char>(cur.peek()))) {
      name += cur.peek();
      cur.advance();
    }
  }
  return name;
}

LSystem parse_lsystem(const SourceText& source) { return Parser(source).run(); }

LSystem parse_lsystem(std::string_view text, const std::string& name,
                      const MacroOverrides& overrides, const std::string& include_dir) {
  const SourceText src = preprocess_text(text, name, overrides, include_dir);
  return parse_lsystem(src);
}

LSystem parse_lsystem_file(const std::string& path, const MacroOverrides& overrides) {
  const SourceText src = preprocess_file(path, overrides);
  LSystem sys = parse_lsystem(src);
  sys.file = path;
  return sys;
}

}  // namespace fspm::lsystem
