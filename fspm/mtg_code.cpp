#include "fspm/mtg_code.hpp"

#include <algorithm>
#include <limits>
#include <optional>
#include <utility>

#include "fspm/error.hpp"
#include "fspm/number_text.hpp"
#include "fspm/trim.hpp"

namespace fspm {
namespace {

// Longest series a range (E1<<E35) may abbreviate: far beyond any plant, small enough that a
// typing slip (E1<<E1000000000) is an error rather than a billion entities.
constexpr long kMaxRange = 1'000'000;

bool is_letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool is_digit(char c) { return c >= '0' && c <= '9'; }

void split_tabs(std::string_view line, std::vector<std::string_view>& cells) {
  cells.clear();
  std::size_t from = 0;
  while (true) {
    const std::size_t tab = line.find('\t', from);
    cells.push_back(line.substr(from, tab == std::string_view::npos ? tab : tab - from));
    if (tab == std::string_view::npos) break;
    from = tab + 1;
  }
}

// One step of the code: a bracket (a branch opened or closed by the columns), an entity, or the
// dated repetition of the entity above ('*').
struct Token {
  char kind = 'e';      // '[', ']', 'e' (entity), '*' (repetition)
  char tag = 0;         // the relation of an entity: '/', '<', '+'
  bool range = false;   // '<<', '++', '<.<', '+.+'
  bool shared = false;  // '<.<', '+.+': the features go to every entity of the series
  std::string_view symbol;
  long index = -1;
  int line = 0;
  int column = 0;                            // byte column of the entity in its line, from 1
  std::string_view code;                     // the line's code cell (for messages)
  std::size_t row = std::string_view::npos;  // the line's feature cells (last entity only)
};

class CodeReader {
 public:
  CodeReader(const std::vector<MtgLine>& lines, std::size_t first, const std::string& file,
             Mtg& mtg, std::vector<std::string>* warnings)
      : lines_(lines),
        first_(first),
        file_(file),
        mtg_(mtg),
        warnings_(warnings),
        infer_classes_(mtg.classes.size() <= 1) {}

  void read() {
    const std::size_t k = read_column_header();
    for (std::size_t i = k + 1; i < lines_.size(); ++i) read_line(lines_[i]);
    if (tokens_.empty()) {
      split_tabs(lines_[k].text, cells_);
      fail("the MTG: table has no entity after its " + std::string(trim(cells_[0])) +
               " header (is the file truncated?)",
           lines_[k].number);
    }
    close_open_branches();
    for (const Token& t : tokens_) edit(t);
    type_undeclared_features();
    complete_relations();
  }

 private:
  [[noreturn]] void fail(const std::string& what, int line, int column = 0) const {
    throw ParseError(what, file_, line, column);
  }
  [[noreturn]] void fail(const std::string& what, const Token& t) const {
    fail("entity code '" + std::string(t.code) + "': " + what, t.line, t.column);
  }
  void warn(const std::string& what, int line) const {
    if (warnings_) warnings_->push_back(file_ + ":" + std::to_string(line) + ": " + what);
  }

  // --- The column header: ENTITY-CODE or TOPO, then the feature names, each in its column. ---
  std::size_t read_column_header() {
    std::size_t k = first_;
    while (k < lines_.size() && trim(lines_[k].text).empty()) ++k;
    if (k == lines_.size()) {
      fail("expected the header line 'ENTITY-CODE' (or 'TOPO') after 'MTG:'",
           lines_.empty() ? 0 : lines_.back().number);
    }
    const MtgLine& line = lines_[k];
    std::vector<std::string_view> cells;
    split_tabs(line.text, cells);
    const std::string_view head = trim(cells[0]);
    if (head != "ENTITY-CODE" && head != "TOPO") {
      fail("expected the header line 'ENTITY-CODE' (or 'TOPO') after 'MTG:', found '" +
               std::string(head.substr(0, 40)) + "' (feature columns are separated by tabs)",
           line.number, 1);
    }
    first_feature_cell_ = std::numeric_limits<std::size_t>::max();  // no feature: code anywhere
    for (std::size_t c = 1; c < cells.size(); ++c) {
      const std::string_view name = trim(cells[c]);
      if (name.empty()) continue;
      first_feature_cell_ = std::min(first_feature_cell_, c);
      add_feature_column(name, c, line.number);
    }
    return k;
  }

  // A column not declared in FEATURES is REAL if all its values are numbers, else ALPHA (decided
  // when the table is read: type_undeclared_features).
  void add_feature_column(std::string_view name, std::size_t cell, int line) {
    std::optional<std::size_t> f = mtg_.feature_index(name);
    if (!f) {
      undeclared_names_ += (undeclared_names_.empty() ? "" : ", ") + std::string(name);
      undeclared_line_ = line;
      f = mtg_.add_feature({std::string(name), MtgFeatureType::kReal, ""});
      undeclared_.push_back(*f);
    }
    columns_.emplace_back(*f, cell);
  }

  void type_undeclared_features() {
    if (undeclared_.empty()) return;
    warn("features not declared in FEATURES (" + undeclared_names_ +
             "): typed REAL where every value is a number, ALPHA otherwise",
         undeclared_line_);
    for (std::size_t f : undeclared_) {
      for (MtgVertex v = 1; v < mtg_.size(); ++v) {
        if (!mtg_.feature_text(v, f).empty() && !mtg_.feature_number(v, f)) {
          mtg_.set_feature_type(f, MtgFeatureType::kAlpha);
          break;
        }
      }
    }
  }

  // --- Lines into tokens, with the brackets the columns imply (OpenAlea's preprocess_line). ---
  void read_line(const MtgLine& line) {
    const std::string_view text = line.text;
    const std::string_view stripped = trim(text);
    if (stripped.empty() || stripped.front() == '#') return;
    split_tabs(text, cells_);
    std::size_t cell = 0;
    while (cell < cells_.size() && trim(cells_[cell]).empty()) ++cell;
    if (cell >= first_feature_cell_) {
      fail("expected an entity code in the columns before the first feature column (column " +
               std::to_string(first_feature_cell_ + 1) + ")",
           line.number, 1);
    }
    std::string_view code = trim(cells_[cell]);
    std::size_t end = 0;
    while (end < code.size() && !is_blank(code[end])) ++end;
    code = code.substr(0, end);
    const int indent = static_cast<int>(cell);
    const std::size_t row = store_row(line);
    place_in_columns(code, indent, line, static_cast<int>(code.data() - text.data()) + 1);
    const int column = static_cast<int>(code.data() - text.data()) + 1;  // after a '^
    if (code.front() == '*') {
      if (code.size() > 1) {
        fail("entity code '" + std::string(code) +
                 "': '*' repeats the entity above at another date and stands alone",
             line.number, column);
      }
      tokens_.push_back({'*', 0, false, false, {}, -1, line.number, column, code, row});
      return;
    }
    parse_code(code, line.number, column, row);
  }

  // The feature cells of the current line; returns their row.
  std::size_t store_row(const MtgLine& line) {
    const std::size_t row = rows_.size() / std::max<std::size_t>(columns_.size(), 1);
    for (const auto& [f, c] : columns_) {
      std::string_view v = c < cells_.size() ? trim(cells_[c]) : std::string_view{};
      if (!v.empty() && v.front() == '#') v = {};  // a comment up to the next tab
      rows_.push_back(v);
    }
    if (columns_.empty()) rows_.emplace_back();
    for (std::size_t c = cells_.size(); !extra_reported_ && c-- > columns_end();) {
      if (!trim(cells_[c]).empty() && trim(cells_[c]).front() != '#') {
        extra_reported_ = true;
        warn(
            "a value beyond the last feature column is ignored (later such values are not "
            "reported)",
            line.number);
      }
    }
    return row;
  }
  std::size_t columns_end() const {
    std::size_t end = first_feature_cell_;
    for (const auto& fc : columns_) end = std::max(end, fc.second + 1);
    return end;
  }

  // The brackets of the columns: a line further right opens a branch ('+' or '/') or continues
  // ('<'); a '+' or '/' in the same column closes the branch above and opens the next; a line
  // back to the left closes what was opened to its right. '^' continues the column's last entity.
  void place_in_columns(std::string_view& code, int indent, const MtgLine& line, int column) {
    const int diff = indent - indents_.back();
    if (diff > 0) {
      if (code.front() == '^') {
        fail("entity code '" + std::string(code) +
                 "': '^' continues an entity of its own column, but this line opens a new column "
                 "(no entity above it there)",
             line.number, column);
      }
      indents_.push_back(indent);
      edges_.push_back(code.front());
      if (code.front() == '+' || code.front() == '/') push_bracket('[', line.number);
      return;
    }
    if (diff < 0) {
      while (indent < indents_.back()) {
        indents_.pop_back();
        if (!edges_.empty()) {
          const char e = edges_.back();
          edges_.pop_back();
          if (e == '+' || e == '/') push_bracket(']', line.number);
        }
      }
      if (indent != indents_.back()) {
        fail("entity code '" + std::string(code) + "' is in column " + std::to_string(indent + 1) +
                 ", which matches no column of the lines above it",
             line.number, column);
      }
    }
    if (code.front() == '^') {
      code.remove_prefix(1);
      if (code.empty()) fail("expected an entity after '^'", line.number, column);
    } else if (code.front() == '*') {
      return;
    } else if (!edges_.empty()) {
      if (code.front() == '+' || code.front() == '/') {
        if (edges_.back() == '+' || edges_.back() == '/') {
          edges_.pop_back();
          push_bracket(']', line.number);
        }
        edges_.push_back(code.front());
        push_bracket('[', line.number);
      }
    } else if (diff == 0 && code.front() == '+') {
      edges_.push_back('+');
    }
  }

  void push_bracket(char kind, int line) {
    Token t;
    t.kind = kind;
    t.line = line;
    tokens_.push_back(t);
  }

  void close_open_branches() {
    while (!edges_.empty()) {
      if (edges_.back() == '+' || edges_.back() == '/') push_bracket(']', 0);
      edges_.pop_back();
    }
  }

  // "/P1/A1/U1<<U5+E2": relation, symbol (letters), index (digits), for each entity.
  void parse_code(std::string_view code, int line, int column, std::size_t row) {
    std::size_t p = skip_to_relation(code, line, column);
    if (p == code.size()) return;
    const std::size_t first = tokens_.size();
    while (p < code.size()) {
      Token t;
      t.line = line;
      t.column = column + static_cast<int>(p);
      t.code = code;
      p = parse_relation(code, p, t);
      const std::size_t s = p;
      while (p < code.size() && is_letter(code[p])) ++p;
      if (p == s) {
        fail("expected a class symbol (letters) at column " + std::to_string(column + p), t);
      }
      t.symbol = code.substr(s, p - s);
      const std::size_t d = p;
      while (p < code.size() && is_digit(code[p]) && p - d < 15) ++p;
      if (p > d) t.index = std::stol(std::string(code.substr(d, p - d)));
      while (p < code.size() && is_digit(code[p])) ++p;
      tokens_.push_back(t);
    }
    if (tokens_.size() == first) fail("empty entity code", line, column);
    tokens_.back().row = row;
  }

  // Text before a code's first relation ("f", "j^<HT", "^^/T" in real files) is not an entity:
  // OpenAlea's reader appends it to the entity before, and so ignores it; so does this reader,
  // with a warning. Returns where the first entity starts (code.size(): none on this line).
  std::size_t skip_to_relation(std::string_view code, int line, int column) {
    if (code.front() == '/' || code.front() == '<' || code.front() == '+') return 0;
    if (code.front() == '(') {
      fail("entity code '" + std::string(code) +
               "': aliases ('(name)' prefixes) are not supported: write the entity's code",
           line, column);
    }
    const std::size_t p = std::min(code.find_first_of("/<+"), code.size());
    if (!junk_reported_) {
      junk_reported_ = true;
      warn("entity code '" + std::string(code) + "': '" + std::string(code.substr(0, p)) +
               "' is not a relation and label" +
               (p == code.size() ? ": the line is ignored" : ": ignored") +
               ", as OpenAlea's reader ignores it (later such codes are not reported)",
           line);
    }
    return p;
  }

  std::size_t parse_relation(std::string_view code, std::size_t p, Token& t) const {
    const std::string_view rest = code.substr(p);
    for (std::string_view form : {"<.<", "+.+"}) {
      if (rest.starts_with(form)) {
        t.tag = form[0];
        t.range = t.shared = true;
        return p + 3;
      }
    }
    if (rest.starts_with("<<") || rest.starts_with("++")) {
      t.tag = rest[0];
      t.range = true;
      return p + 2;
    }
    if (rest.front() == '/' || rest.front() == '<' || rest.front() == '+') {
      t.tag = rest.front();
      return p + 1;
    }
    if (rest.front() == '(') {
      fail("aliases ('(name)' prefixes) are not supported: write the entity's code", t);
    }
    fail("expected a relation '/', '<', '+' (or '<<', '++') at column " + std::to_string(t.column),
         t);
  }

  // --- The multiscale edit (OpenAlea's multiscale_edit): `vid_` is the last entity at the
  // finest scale reached, `current_` the one at the scale being written. ---
  void edit(const Token& t) {
    if (t.kind == '[') {
      stack_.push_back(vid_);
    } else if (t.kind == ']') {
      vid_ = stack_.back();
      stack_.pop_back();
      current_ = vid_;
      scale_ = mtg_.scale(vid_);
    } else if (t.kind == '*') {
      repeat(t);
    } else {
      entity(t);
    }
  }

  // The scale of a token's class. Without a CLASSES section, a symbol takes the scale where it
  // first appears (one finer after '/').
  // A symbol missing from a CLASSES section that has others takes the scale of the entity
  // before it, as in OpenAlea's reader, with a warning.
  int symbol_scale(const Token& t, std::size_t& class_id) {
    auto c = mtg_.class_index(t.symbol);
    if (!c && infer_classes_) {
      mtg_.classes.push_back({std::string(t.symbol), t.tag == '/' ? scale_ + 1 : scale_});
      c = mtg_.classes.size() - 1;
    } else if (!c) {
      if (last_scale_ < 0)
        fail("symbol '" + std::string(t.symbol) + "' is not declared in CLASSES", t);
      warn("symbol '" + std::string(t.symbol) + "' is not declared in CLASSES: read at scale " +
               std::to_string(last_scale_) + ", that of the entity before it",
           t.line);
      mtg_.classes.push_back({std::string(t.symbol), last_scale_});
      c = mtg_.classes.size() - 1;
    }
    class_id = *c;
    return mtg_.classes[*c].scale;
  }

  void entity(const Token& t) {
    std::size_t class_id = 0;
    const int class_scale = symbol_scale(t, class_id);
    int new_scale = class_scale;
    if (t.tag == '/' && new_scale <= scale_) {
      --new_scale;  // a new complex: climb to the scale it decomposes
      pending_ = '/';
    }
    last_scale_ = new_scale;
    while (new_scale < scale_) {
      --scale_;
      current_ = mtg_.complex(current_);
    }
    if (t.range) {
      range(t, class_id, new_scale);
    } else if (t.tag == '/') {
      decompose(t, class_id, class_scale);
    } else {
      relate(t, class_id, new_scale);
    }
  }

  // '<' or '+': a child of the last finest entity, or, at a coarser scale, a new complex whose
  // relation follows from its components (or from this code, if it has none).
  void relate(const Token& t, std::size_t class_id, int new_scale) {
    if (new_scale != scale_ || current_ == Mtg::root()) {
      fail("'" + std::string(1, t.tag) + "' relates entities of one scale, but " +
               std::string(t.symbol) + " (scale " + std::to_string(new_scale) +
               ") follows an entity of scale " + std::to_string(scale_),
           t);
    }
    const MtgEdge edge = t.tag == '<' ? MtgEdge::kSuccessor : MtgEdge::kBranch;
    if (mtg_.scale(vid_) == scale_) {
      vid_ = add(mtg_.complex(vid_), class_id, t);
      mtg_.set_parent(vid_, vid_before_, edge);
      current_ = vid_;
      pending_ = 0;
    } else {
      const MtgVertex before = current_;
      current_ = add(mtg_.complex(current_), class_id, t);
      fallback_.push_back({current_, before, edge});
      pending_ = t.tag;
    }
  }

  // '/': the first component of the entity being written.
  void decompose(const Token& t, std::size_t class_id, int class_scale) {
    if (class_scale != scale_ + 1 && !scale_mismatch_reported_) {
      // OpenAlea's reader places the component one scale below its complex whatever CLASSES
      // says; so does this one, and says so.
      scale_mismatch_reported_ = true;
      warn("entity code '" + std::string(t.code) + "': " + std::string(t.symbol) + " is of scale " +
               std::to_string(class_scale) +
               " in CLASSES but decomposes an "
               "entity of scale " +
               std::to_string(scale_) + ": read at scale " + std::to_string(scale_ + 1) +
               " (later such entities are not reported)",
           t.line);
    }
    const int vid_scale = mtg_.scale(vid_);
    if (vid_scale == scale_) {
      vid_ = add(vid_, class_id, t);
      current_ = vid_;
      ++scale_;
      return;
    }
    ++scale_;
    const MtgVertex component = add(current_, class_id, t);
    if (vid_scale == scale_ && pending_ != '/') {
      mtg_.set_parent(component, vid_, pending_ == '+' ? MtgEdge::kBranch : MtgEdge::kSuccessor);
      vid_ = component;
      current_ = component;
    } else {
      current_ = component;
      if (pending_ == '/') {
        vid_ = current_;
        scale_ = mtg_.scale(vid_);
      }
    }
  }

  // E1<<E35: the successors (branches) numbered from the entity written last up to 35; the
  // line's features go to the last one (to all of them for '<.<' and '+.+').
  void range(const Token& t, std::size_t class_id, int new_scale) {
    const long from = mtg_.index(current_);
    if (new_scale != scale_ || current_ == Mtg::root() || from < 0 || t.index < 0) {
      fail("a range '" + std::string(t.tag == '<' ? "<<" : "++") +
               "' continues a numbered entity of its own scale up to a numbered one",
           t);
    }
    if (t.index <= from || t.index - from > kMaxRange) {
      fail("a range from " + mtg_.label(current_) + " to " + std::string(t.symbol) +
               std::to_string(t.index) + " must count up, by at most " + std::to_string(kMaxRange) +
               " entities",
           t);
    }
    const MtgEdge edge = t.tag == '<' ? MtgEdge::kSuccessor : MtgEdge::kBranch;
    const bool at_finest = mtg_.scale(vid_) == new_scale;
    MtgVertex previous = at_finest ? vid_ : current_;
    for (long i = from + 1; i <= t.index; ++i) {
      Token step = t;
      step.index = i;
      step.row = (i == t.index || t.shared) ? t.row : std::string_view::npos;
      const MtgVertex v = add(mtg_.complex(previous), class_id, step);
      mtg_.set_parent(v, previous, edge);
      previous = v;
    }
    current_ = previous;
    if (at_finest) vid_ = previous;
    pending_ = 0;
  }

  // A new vertex; vid_before_ keeps the vertex that was the finest before it (its parent).
  MtgVertex add(MtgVertex complex, std::size_t class_id, const Token& t) {
    vid_before_ = vid_;
    const MtgVertex v = mtg_.add_component(complex, class_id, t.index, t.line);
    if (t.row != std::string_view::npos) set_features(v, t.row, t.line);
    last_ = v;
    return v;
  }

  void set_features(MtgVertex v, std::size_t row, int line) {
    for (std::size_t k = 0; k < columns_.size(); ++k) {
      const std::string_view text = rows_[row * columns_.size() + k];
      if (text.empty()) continue;
      const std::size_t f = columns_[k].first;
      mtg_.set_feature_text(v, f, text);
      check_type(v, f, line);
    }
  }

  // A value that is not of its feature's type is kept as text and reported once per feature.
  void check_type(MtgVertex v, std::size_t f, int line) {
    if (std::find(undeclared_.begin(), undeclared_.end(), f) != undeclared_.end()) return;
    const MtgFeatureType type = mtg_.features()[f].type;
    if (!mtg_feature_is_number(type) && !mtg_feature_is_date(type)) return;
    if (mtg_.feature_number(v, f)) return;
    if (reported_.size() <= f) reported_.resize(f + 1, false);
    if (reported_[f]) return;
    reported_[f] = true;
    warn("feature " + mtg_.features()[f].name + ": '" + std::string(mtg_.feature_text(v, f)) +
             "' is not a value of type " + std::string(mtg_feature_type_name(type)) +
             " (kept as text; later such values are not reported)",
         line);
  }

  // '*': the line's features at another date, for the entity written last.
  void repeat(const Token& t) {
    if (last_ == kNoMtgVertex) fail("'*' repeats the entity above, but there is none", t);
    MtgObservation o{last_, {}, t.line};
    o.values.resize(mtg_.features().size());
    for (std::size_t k = 0; k < columns_.size(); ++k) {
      o.values[columns_[k].first] = std::string(rows_[t.row * columns_.size() + k]);
    }
    mtg_.observations.push_back(std::move(o));
  }

  // Edges of coarser scales from their components; a coarse entity without components keeps
  // the relation its code gave (which OpenAlea's reader drops).
  void complete_relations() {
    mtg_.complete_topology();
    for (const Fallback& f : fallback_) {
      if (mtg_.parent(f.child) == kNoMtgVertex && mtg_.components(f.child).empty()) {
        mtg_.set_parent(f.child, f.parent, f.edge);
      }
    }
  }

  struct Fallback {
    MtgVertex child, parent;
    MtgEdge edge;
  };

  const std::vector<MtgLine>& lines_;
  std::size_t first_;
  const std::string& file_;
  Mtg& mtg_;
  std::vector<std::string>* warnings_;
  bool infer_classes_;
  std::size_t first_feature_cell_ = 0;
  std::vector<std::pair<std::size_t, std::size_t>> columns_;  // (feature, cell)
  std::vector<std::string_view> cells_;
  std::vector<std::string_view> rows_;  // feature cells, columns_.size() per line
  std::vector<Token> tokens_;
  std::vector<int> indents_{0};
  std::vector<char> edges_;
  // Edit state.
  MtgVertex vid_ = Mtg::root(), current_ = Mtg::root(), vid_before_ = Mtg::root();
  MtgVertex last_ = kNoMtgVertex;
  int scale_ = 0;
  char pending_ = 0;
  std::vector<MtgVertex> stack_;
  std::vector<Fallback> fallback_;
  std::vector<bool> reported_;
  bool scale_mismatch_reported_ = false;
  bool junk_reported_ = false;
  bool extra_reported_ = false;
  int last_scale_ = -1;  // the scale of the entity before (after a '/' climb: the complex's)
  std::vector<std::size_t> undeclared_;
  std::string undeclared_names_;
  int undeclared_line_ = 0;
};

}  // namespace

void read_mtg_code(const std::vector<MtgLine>& lines, std::size_t first, const std::string& file,
                   Mtg& mtg, std::vector<std::string>* warnings) {
  CodeReader(lines, first, file, mtg, warnings).read();
}

}  // namespace fspm
