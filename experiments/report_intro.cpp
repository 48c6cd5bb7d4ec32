#include "experiments/report_intro.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "experiments/metrics.hpp"
#include "experiments/scene_words.hpp"

namespace fspm::experiments {
namespace {

// A model or scene file as the experiment file names it: relative to the file's folder.
std::string shown_path(const Experiment& x, const std::string& file) {
  if (x.path == "<string>") return file;
  const std::filesystem::path relative =
      std::filesystem::path(file).lexically_relative(std::filesystem::path(x.path).parent_path());
  return relative.empty() ? file : relative.string();
}

// The model kinds in words, with the literature they follow (docs/references.md).
std::string model_words(const Experiment& x) {
  if (x.model_kind == ModelKind::kLSystem) {
    return "the L-system `" + shown_path(x, x.model_file) +
           "` (Prusinkiewicz and Lindenmayer 1990), lengths in "
           "the L-system's own units";
  }
  if (x.model_kind == ModelKind::kGreenLab) return "the GreenLab model (de Reffye et al. 2003)";
  if (x.model_kind == ModelKind::kGrow) {
    return "the self-organizing growth model (Palubicki et al. 2009), trees grown from a seed "
           "under the sky's light";
  }
  if (x.model_kind == ModelKind::kAdapt) {
    return "plastic adaptation (Pirk 2013, chapter 4) of the tree `" + shown_path(x, x.model_file) +
           "`";
  }
  if (x.model_kind == ModelKind::kStages) {
    return "the developmental stages (Pirk 2013, chapter 5) of the tree `" +
           shown_path(x, x.model_file) + "`";
  }
  return "the " + std::string(model_kind_name(x.model_kind)) + " model";
}

std::string values_text(const std::vector<ParameterValue>& values) {
  std::string out;
  for (std::size_t i = 0; i < values.size(); ++i) {
    out += (i == 0 ? "" : ", ") + parameter_text(values[i]);
  }
  return out;
}

std::string filter_text(const RunFilter& filter) {
  std::string out;
  for (const auto& [name, value] : filter) {
    out += (out.empty() ? "" : " and ") + name + " = " + parameter_text(value);
  }
  return out.empty() ? "any run" : out;
}

std::string names_text(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    out += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
  }
  return out;
}

void what_was_run(std::ostream& md, const Experiment& x) {
  md << "**What was run.** " << x.runs() << " runs of " << model_words(x);
  if (!x.model_scene.empty()) {
    md << ", in the scene `" << shown_path(x, x.model_scene) << "`";
    const std::string words = scene_in_words(x.model_scene);
    if (!words.empty()) md << " (" << words << ")";
  }
  md << ": ";
  if (x.sweep.empty() && !x.sampling) {
    md << "one parameter point";
  } else {
    md << x.points() << " parameter points (";
    for (std::size_t i = 0; i < x.sweep.size(); ++i) {
      md << (i == 0 ? "" : " × ") << x.sweep[i].name << " " << values_text(x.sweep[i].values);
    }
    if (x.sampling) {
      md << (x.sweep.empty() ? "" : ", crossed with ") << x.sampling->samples
         << (x.sampling->method == SamplingMethod::kLatinHypercube ? " Latin-hypercube" : " random")
         << " samples of ";
      std::vector<std::string> ranges;
      for (const SampledParameter& p : x.sampling->parameters) {
        std::ostringstream range;
        range << p.name << (p.integer ? " among the integers " : " in ") << "[" << p.low << ", "
              << p.high << "]" << (p.log_scale ? " (log-uniform)" : "");
        ranges.push_back(range.str());
      }
      md << names_text(ranges);
    }
    md << ")";
  }
  md << ", " << x.replicates << (x.replicates == 1 ? " run" : " runs") << " per point";
  if (x.model_kind == ModelKind::kAdapt || x.model_kind == ModelKind::kStages) {
    md << " (the model is deterministic: it uses no random numbers).";
  } else {
    md << ", each with its own random seed derived from the experiment seed " << x.seed << ".";
  }
  if (!x.fixed.empty()) {
    md << " Fixed:";
    std::string sep = " ";
    for (const auto& [name, value] : x.fixed) {
      md << sep << name << " = " << parameter_text(value);
      sep = ", ";
    }
    md << ".";
  }
  md << " Recorded per run: " << names_text(x.metrics) << ".\n\n";
}

// The tree types and the values of `set` (grow model) that the experiment uses, in words.
void set_meanings(std::ostream& md, const Experiment& x) {
  if (x.model_kind != ModelKind::kGrow) return;
  std::vector<ParameterValue> sets;
  for (const SweepAxis& a : x.sweep) {
    if (a.name == "set") sets = a.values;
  }
  if (const auto it = x.fixed.find("set"); it != x.fixed.end()) sets = {it->second};
  const bool presets = std::any_of(x.sweep.begin(), x.sweep.end(),
                                   [](const SweepAxis& a) { return a.name == "preset"; });
  if (presets) {
    md << "**The tree types** (preset): Pirk's types A, B and C (2013, 4.5.4), parameter sets of "
          "the growth model that differ mainly in phototropism, gravitropism and apical control "
          "(docs/environment.md).\n\n";
  }
  if (sets.empty()) return;
  md << "**The sets.**";
  for (const ParameterValue& v : sets) {
    const std::string name = parameter_text(v);
    if (const std::optional<GrowSet> set = find_grow_set(name)) {
      md << " **" << name << "**: " << grow_set_meaning(*set) << ".";
    }
  }
  md << "\n\n";
}

void comparison_meanings(std::ostream& md, const Experiment& x) {
  if (x.comparisons.empty()) return;
  md << "**The comparisons.** Each compares pairs of trees by the constrained edit distance "
        "(Zhang 1996; Ferraro and Godin 2000): the cost of turning one tree's branching "
        "structure into the other's, 0 for identical trees, larger for less alike ones. No tree "
        "is used twice within a comparison.";
  for (const ComparisonSpec& c : x.comparisons) {
    md << " **" << c.name << "**: ";
    if (c.a == c.b) {
      md << "two different runs with " << filter_text(c.a);
    } else {
      md << "a run with " << filter_text(c.a) << " against one with " << filter_text(c.b);
    }
    if (!c.within.empty()) md << ", both with the same " << names_text(c.within);
    if (!c.where.empty()) md << ", among the runs with " << filter_text(c.where);
    if (c.pairs > 0) md << " (up to " << c.pairs << " pairs per group)";
    md << ".";
  }
  md << "\n\n";
  if (x.ttests.empty()) return;
  md << "**The tests.**";
  for (const TTestSpec& t : x.ttests) {
    md << " Are the " << t.a << " distances "
       << (t.alternative == Alternative::kLess      ? "smaller than"
           : t.alternative == Alternative::kGreater ? "larger than"
                                                    : "different from")
       << " the " << t.b << " distances? (" << (t.welch ? "Welch's" : "Student's")
       << " t-test, significant when p < " << t.alpha << ".)";
  }
  md << "\n\n";
}

}  // namespace

std::string report_introduction(const Experiment& x) {
  std::ostringstream md;
  if (!x.description.empty()) md << x.description << "\n\n";
  what_was_run(md, x);
  set_meanings(md, x);
  comparison_meanings(md, x);
  if (!x.about.empty()) md << x.about << (x.about.ends_with('\n') ? "\n" : "\n\n");
  return md.str();
}

}  // namespace fspm::experiments
