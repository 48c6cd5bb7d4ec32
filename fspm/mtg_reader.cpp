#include "fspm/mtg_reader.hpp"

#include <algorithm>
#include <optional>
#include <utility>

#include "fspm/error.hpp"
#include "fspm/input_file.hpp"
#include "fspm/mtg_code.hpp"
#include "fspm/trim.hpp"

namespace fspm {
namespace {

// Whitespace-separated words of a header row (after its comment is cut).
std::vector<std::string_view> words(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t p = 0;
  while (p < s.size()) {
    while (p < s.size() && (is_blank(s[p]) || s[p] == '\n')) ++p;
    const std::size_t from = p;
    while (p < s.size() && !is_blank(s[p])) ++p;
    if (p > from) out.push_back(s.substr(from, p - from));
  }
  return out;
}

std::string_view without_comment(std::string_view s) {
  const std::size_t hash = s.find('#');
  return hash == std::string_view::npos ? s : s.substr(0, hash);
}

// The section a header line opens ("CLASSES", "MTG" ...), if it is a keyword followed by spaces
// and a colon ("MTG :" as well as "MTG:").
std::string_view section_keyword(std::string_view line) {
  line = trim(without_comment(line));
  const std::size_t colon = line.find(':');
  if (colon == std::string_view::npos) return {};
  const std::string_view key = trim(line.substr(0, colon));
  for (std::string_view k : {"CODE", "CLASSES", "DESCRIPTION", "FEATURES", "MTG"}) {
    if (key == k) return k;
  }
  return {};
}

// The lines of the file with their numbers (from 1), '\r' removed.
std::vector<MtgLine> split_lines(std::string_view text) {
  std::vector<MtgLine> lines;
  int number = 0;
  for (std::size_t from = 0; from <= text.size();) {
    std::size_t end = text.find('\n', from);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(from, end - from);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.push_back({line, ++number});
    from = end + 1;
  }
  return lines;
}

// The header sections before "MTG:".
class HeaderReader {
 public:
  HeaderReader(const std::vector<MtgLine>& lines, const std::string& file, Mtg& mtg,
               std::vector<std::string>* warnings)
      : lines_(lines), file_(file), mtg_(mtg), warnings_(warnings) {}

  // Reads every section; returns the index of the "MTG:" line.
  std::size_t read() {
    std::string_view section;
    for (std::size_t k = 0; k < lines_.size(); ++k) {
      const std::string_view row = trim(without_comment(lines_[k].text));
      if (row.empty()) continue;
      if (const std::string_view key = section_keyword(row); !key.empty()) {
        section = key;
        if (key == "MTG") return finish(k);
        if (key == "CODE") read_code_form(row, lines_[k]);
        header_row_pending_ = key != "CODE";
        continue;
      }
      read_row(section, row, lines_[k]);
    }
    throw ParseError(
        "no 'MTG:' section: expected an MTG coding file (CODE:, CLASSES:, DESCRIPTION:, "
        "FEATURES: and MTG: sections)",
        file_, 1);
  }

 private:
  std::size_t finish(std::size_t k) {
    if (mtg_.classes.size() <= 1) {
      warn(lines_[k],
           "no CLASSES: section: each symbol's scale is taken from where it first "
           "appears in the code ('/' one scale finer)");
    }
    return k;
  }

  void read_code_form(std::string_view row, const MtgLine& line) {
    const std::string_view form = trim(row.substr(row.find(':') + 1));
    if (form != "FORM-A" && form != "FORM-B") {
      warn(line, "CODE: expected FORM-A or FORM-B, found '" + std::string(form) + "'");
    }
    mtg_.code_form = form.empty() ? "FORM-A" : std::string(form);
  }

  void read_row(std::string_view section, std::string_view row, const MtgLine& line) {
    const std::vector<std::string_view> w = words(row);
    if (header_row_pending_) {
      header_row_pending_ = false;  // SYMBOL SCALE ..., LEFT RIGHT ..., NAME TYPE
      if (w[0] == "SYMBOL" || w[0] == "LEFT" || w[0] == "NAME") return;
    }
    if (section == "CLASSES") {
      read_class(w, line);
    } else if (section == "DESCRIPTION") {
      read_rule(w, line);
    } else if (section == "FEATURES") {
      read_feature(w, line);
    } else {
      throw ParseError("unexpected text '" + std::string(row) +
                           "' before the first section: expected 'CODE:' or 'CLASSES:'",
                       file_, line.number, 1);
    }
  }

  void read_class(const std::vector<std::string_view>& w, const MtgLine& line) {
    const std::string_view symbol = w[0];
    const bool letters = std::all_of(symbol.begin(), symbol.end(), [](char c) {
      return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
    });
    int scale = -1;
    if (w.size() >= 2 &&
        std::all_of(w[1].begin(), w[1].end(), [](char c) { return c >= '0' && c <= '9'; }) &&
        w[1].size() < 6) {
      scale = std::stoi(std::string(w[1]));
    }
    if ((!letters && symbol != "$") || scale < 0) {
      throw ParseError(
          "CLASSES: expected a symbol of letters (or $) and its scale (a whole "
          "number), found '" +
              std::string(trim(line.text)) + "'",
          file_, line.number, 1);
    }
    if (symbol == "$") return;  // the scale-0 class every MTG has
    if (mtg_.class_index(symbol)) {
      throw ParseError("CLASSES: symbol '" + std::string(symbol) + "' declared twice", file_,
                       line.number, 1);
    }
    MtgClass c{std::string(symbol), scale};
    if (w.size() >= 5) {
      c.decomposition = w[2];
      c.indexation = w[3];
      c.definition = w[4];
    }
    mtg_.classes.push_back(std::move(c));
  }

  void read_rule(const std::vector<std::string_view>& w, const MtgLine& line) {
    if (w.size() < 4 || (w[w.size() - 2] != "<" && w[w.size() - 2] != "+")) {
      warn(line, "DESCRIPTION: expected 'LEFT RIGHT RELTYPE MAX' with RELTYPE < or +; row ignored");
      return;
    }
    MtgRelationRule rule{std::string(w[0]), {}, w[w.size() - 2][0], std::string(w.back())};
    std::string right;
    for (std::size_t i = 1; i + 2 < w.size(); ++i) right += w[i];
    for (std::size_t from = 0; from <= right.size();) {
      std::size_t comma = right.find(',', from);
      if (comma == std::string::npos) comma = right.size();
      if (comma > from) rule.right.push_back(right.substr(from, comma - from));
      from = comma + 1;
    }
    mtg_.description.push_back(std::move(rule));
  }

  void read_feature(const std::vector<std::string_view>& w, const MtgLine& line) {
    const auto type = w.size() >= 2 ? mtg_feature_type_from_name(w[1]) : std::nullopt;
    if (!type) {
      throw ParseError(
          "FEATURES: expected 'NAME TYPE' with TYPE one of INT, REAL, ALPHA, "
          "STRING, DD/MM/YY, DD/MM/YYYY, MM/YY, DD/MM, GEOMETRY, APPEARANCE, "
          "OBJECT; found '" +
              std::string(trim(line.text)) + "'",
          file_, line.number, 1);
    }
    if (mtg_.feature_index(w[0])) {
      throw ParseError("FEATURES: feature '" + std::string(w[0]) + "' declared twice", file_,
                       line.number, 1);
    }
    mtg_.add_feature({std::string(w[0]), *type, w.size() >= 3 ? std::string(w[2]) : ""});
  }

  void warn(const MtgLine& line, const std::string& what) const {
    if (warnings_) warnings_->push_back(file_ + ":" + std::to_string(line.number) + ": " + what);
  }

  const std::vector<MtgLine>& lines_;
  const std::string& file_;
  Mtg& mtg_;
  std::vector<std::string>* warnings_;
  bool header_row_pending_ = false;
};

}  // namespace

Mtg read_mtg(std::string_view text, const std::string& file, std::vector<std::string>* warnings) {
  const std::vector<MtgLine> lines = split_lines(text);
  Mtg mtg;
  const std::size_t mtg_line = HeaderReader(lines, file, mtg, warnings).read();
  read_mtg_code(lines, mtg_line + 1, file, mtg, warnings);
  return mtg;
}

Mtg read_mtg_file(const std::string& path, std::vector<std::string>* warnings) {
  return read_mtg(read_text_input_file(path), path, warnings);
}

}  // namespace fspm
