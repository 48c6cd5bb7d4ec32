#include "experiments/report_findings.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "fspm/number_text.hpp"
#include "fspm/p_value_text.hpp"

namespace fspm::experiments {
namespace {

std::string number(double v) { return std::isfinite(v) ? format_significant(v) : "-"; }

// "T-G is like G-G" or "T-G is unlike G-G (smaller)", then the numbers behind it.
void test_sentence(std::ostream& md, const TTestRow& t) {
  md << t.a << " is ";
  if (std::isnan(t.p)) {
    md << "not testable against " << t.b << " (both groups constant)";
  } else if (t.significant_holm()) {
    md << "**unlike** " << t.b << " (" << (t.mean_a > t.mean_b ? "larger" : "smaller") << ")";
  } else {
    md << "**like** " << t.b;
  }
  md << ": mean " << number(t.mean_a) << " against " << number(t.mean_b) << ", difference "
     << number(t.mean_a - t.mean_b) << " [95 % CI " << number(t.difference_low) << ", "
     << number(t.difference_high) << "], Cohen's d " << number(t.cohens_d) << ", "
     << format_p_value(t.p) << ", Holm " << format_p_value(t.p_holm) << " (" << t.n_a << " and "
     << t.n_b << " pairs)";
}

}  // namespace

std::string findings_markdown(const Experiment& x, const std::vector<TTestRow>& tests) {
  if (tests.empty()) return {};
  std::ostringstream md;
  md << "## Findings\n\n";
  const std::string measure = tests.front().scale == DistanceScale::kRaw
                                  ? "constrained edit distance"
                                  : "normalized constrained edit distance (0 identical, 1 "
                                    "nothing in common)";
  md << "Compared by the " << measure << ", with Holm's correction over all " << tests.size()
     << " t-tests (Holm 1979): \"like\" means no difference was found at alpha after the "
        "correction, \"unlike\" that one was.\n\n";
  std::size_t smallest = tests.front().n_a;
  for (const TTestRow& t : tests) smallest = std::min({smallest, t.n_a, t.n_b});
  if (smallest < kFewPairs) {
    md << "**Warning: some groups hold fewer than " << kFewPairs << " pairs (the smallest "
       << smallest
       << ").** A t-test on so few pairs finds only large differences, so \"like\" "
          "there says little; run more replicates (`--replicates`) for a conclusion.\n\n";
  }
  // One bullet per group, in the order the tests first name it.
  std::vector<std::string> groups;
  for (const TTestRow& t : tests) {
    if (std::find(groups.begin(), groups.end(), t.group) == groups.end()) groups.push_back(t.group);
  }
  for (const std::string& g : groups) {
    md << "- **" << g << "**: ";
    bool first = true;
    for (const TTestRow& t : tests) {
      if (t.group != g) continue;
      md << (first ? "" : "; ");
      test_sentence(md, t);
      first = false;
    }
    md << ".\n";
  }
  md << '\n';
  for (const TTestSpec& spec : x.ttests) {
    std::size_t groups_tested = 0, unlike = 0, larger = 0, undefined = 0;
    for (const TTestRow& t : tests) {
      if (t.a != spec.a || t.b != spec.b) continue;
      ++groups_tested;
      undefined += std::isnan(t.p);
      if (!t.significant_holm()) continue;
      ++unlike;
      larger += t.mean_a > t.mean_b;
    }
    if (groups_tested == 0) continue;
    md << "In all, " << spec.a << " is unlike " << spec.b << " in " << unlike << " of "
       << groups_tested << (groups_tested == 1 ? " group" : " groups");
    if (unlike > 0) md << " (larger in " << larger << ", smaller in " << unlike - larger << ")";
    md << " and like it in " << groups_tested - unlike - undefined;
    if (undefined > 0) md << "; not testable in " << undefined;
    md << ".\n";
  }
  return md.str() + "\n";
}

}  // namespace fspm::experiments
