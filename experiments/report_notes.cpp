#include "experiments/report_notes.hpp"

#include <set>

namespace fspm::experiments {
namespace {

// The note without its first " (label)", and the label; the note itself and "" without one.
std::pair<std::string, std::string> split_label(const std::string& note) {
  const auto open = note.find(" (");
  if (open == std::string::npos) return {note, {}};
  const auto close = note.find(')', open);
  if (close == std::string::npos) return {note, {}};
  return {note.substr(0, open) + note.substr(close + 1), note.substr(open + 2, close - open - 2)};
}

constexpr std::size_t kLabelsListed = 4;

std::string times(std::size_t count) {
  return count > 1 ? " (" + std::to_string(count) + " times)" : std::string();
}

}  // namespace

std::vector<std::string> collapse_notes(const std::vector<std::string>& notes) {
  struct Entry {
    std::string first;                // the first note with this text, as it was
    std::size_t count = 0;            // notes with this text
    std::vector<std::string> labels;  // distinct labels, first seen first
    std::set<std::string> seen;
  };
  std::vector<Entry> entries;
  for (const std::string& note : notes) {
    const auto [text, label] = split_label(note);
    auto it = entries.begin();
    while (it != entries.end() && split_label(it->first).first != text) ++it;
    if (it == entries.end()) {
      entries.push_back({note, 0, {}, {}});
      it = entries.end() - 1;
    }
    ++it->count;
    if (it->seen.insert(label).second) it->labels.push_back(label);
  }
  std::vector<std::string> out;
  for (const Entry& e : entries) {
    if (e.labels.size() == 1) {
      out.push_back(e.first + times(e.count));
      continue;
    }
    std::string line = split_label(e.first).first + " (" + std::to_string(e.count) + " times: ";
    for (std::size_t i = 0; i < e.labels.size() && i < kLabelsListed; ++i) {
      line += (i == 0 ? "" : "; ") + e.labels[i];
    }
    if (e.labels.size() > kLabelsListed) line += "; ...";
    line += ')';
    out.push_back(line);
  }
  return out;
}

std::string notes_markdown(const std::vector<std::string>& notes) {
  std::string md;
  for (const std::string& note : collapse_notes(notes)) md += "\nNote: " + note + '\n';
  return md;
}

}  // namespace fspm::experiments
