#pragma once
// The notes of a report (fewer pairs than asked for, a tree that could not be drawn, ...) as a
// reader wants them: a note repeated for many groups once, with a count, instead of a wall of
// near-identical lines.
#include <string>
#include <vector>

namespace fspm::experiments {

// Notes in order of first appearance, each once: identical notes as "NOTE (3 times)"; notes that
// differ only in their first parenthesized label, e.g. the group in "comparison T-G (preset=A):
// only 6 of 50 pairs", as "comparison T-G: only 6 of 50 pairs (3 times: preset=A; preset=B;
// preset=C)", the first four distinct labels listed, then "...".
std::vector<std::string> collapse_notes(const std::vector<std::string>& notes);

// "\nNote: ...\n" for each collapsed note (the report's way of printing them).
std::string notes_markdown(const std::vector<std::string>& notes);

}  // namespace fspm::experiments
