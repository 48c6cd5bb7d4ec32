#include "experiments/render_selection.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

#include "environment/scene_file.hpp"
#include "experiments/grow_set.hpp"
#include "experiments/metrics.hpp"
#include "experiments/model_factory.hpp"
#include "fspm/file_kind.hpp"
#include "fspm/number_text.hpp"
#include "fspm/tree_file.hpp"

namespace fspm::experiments {
namespace {

std::string number(double v) { return format_significant(v); }

bool matches(const RunRecord& r, const RunFilter& where) {
  for (const auto& [name, value] : where) {
    const auto it = r.parameters.find(name);
    if (it == r.parameters.end() || parameter_text(it->second) != parameter_text(value))
      return false;
  }
  return true;
}

double metric_of(const RunRecord& r, const std::string& metric) {
  const auto it = r.metrics.find(metric);
  return it == r.metrics.end() ? std::nan("") : it->second;
}

}  // namespace

std::vector<RenderChoice> select_renders(const Experiment& x, const std::vector<RunRecord>& runs) {
  const RenderSpec& spec = x.render;
  if (spec.renders == 0) return {};
  const std::vector<std::string> by = spec.by_given ? spec.by : x.swept_names();
  const std::string metric =
      !spec.metric.empty() ? spec.metric : (x.metrics.empty() ? std::string() : x.metrics[0]);

  std::vector<std::string> order;  // group keys in order of first appearance
  std::map<std::string, std::vector<const RunRecord*>> groups;
  std::vector<const RunRecord*> sorted;
  for (const RunRecord& r : runs) sorted.push_back(&r);
  std::sort(sorted.begin(), sorted.end(),
            [](const RunRecord* a, const RunRecord* b) { return a->run < b->run; });
  for (const RunRecord* r : sorted) {
    if (r->status != RunStatus::kOk || !matches(*r, spec.where)) continue;
    std::string key;
    for (const std::string& name : by) {
      const auto it = r->parameters.find(name);
      key += (key.empty() ? "" : ", ") + name + " = " +
             (it == r->parameters.end() ? std::string("-") : parameter_text(it->second));
    }
    if (key.empty()) key = "all runs";
    auto [it, inserted] = groups.try_emplace(key);
    if (inserted) order.push_back(key);
    it->second.push_back(r);
  }

  // Spread evenly from the first group to the last (the largest trees of a sweep are often at
  // its end): round(i (G - 1) / (N - 1)).
  std::vector<std::size_t> picked;
  const std::size_t count = std::min(spec.renders, order.size());
  const std::size_t last = order.size() - 1;
  for (std::size_t i = 0; i < count; ++i) {
    picked.push_back(count == 1 ? 0 : (2 * i * last + count - 1) / (2 * (count - 1)));
  }

  std::vector<RenderChoice> choices;
  for (const std::size_t g : picked) {
    std::vector<const RunRecord*> members = groups.at(order[g]);
    // Finite values first, ascending, ties by run index (stable: members are in run order).
    std::stable_sort(members.begin(), members.end(), [&](const RunRecord* a, const RunRecord* b) {
      const double va = metric_of(*a, metric);
      const double vb = metric_of(*b, metric);
      if (std::isnan(va) || std::isnan(vb)) return !std::isnan(va) && std::isnan(vb);
      return va < vb;
    });
    std::size_t finite = 0;
    while (finite < members.size() && !std::isnan(metric_of(*members[finite], metric))) ++finite;
    const RunRecord& r = *members[finite > 0 ? (finite - 1) / 2 : 0];
    RenderChoice c;
    c.run = r.run;
    c.group = order[g];
    std::ostringstream caption;
    caption << "Run " << r.run << " (seed " << r.seed << ")";
    std::string values;
    for (const std::string& name : x.swept_names()) {
      const auto it = r.parameters.find(name);
      if (it == r.parameters.end()) continue;
      values += (values.empty() ? "" : ", ") + name + " = " + parameter_text(it->second);
    }
    if (!values.empty()) caption << ": " << values;
    if (finite > 0) {
      caption << "; " << metric << " = " << number(metric_of(r, metric)) << ", the median of "
              << finite << (finite == 1 ? " run" : " runs");
      // The default groups are the points, whose values the caption has just listed.
      if (spec.by_given && !by.empty()) caption << " with " << order[g];
    }
    c.caption = caption.str();
    choices.push_back(std::move(c));
  }
  return choices;
}

TreeGraph recorded_run_tree(const Experiment& x, const RunRecord& record, const std::string& dir) {
  for (const std::string& file : record.files) {
    if (file_kind_by_extension(file) == FileKind::kTreeText)
      return read_tree_file((std::filesystem::path(dir) / file).string());
  }
  // The recorded parameters and seed, not the plan's: they are what the run was given.
  const std::unique_ptr<Model> model = make_model(x);
  RunResult result = model->run(record.parameters, record.seed, RunContext());
  if (!result.tree) {
    throw ValueError("run " + std::to_string(record.run) + ": the " +
                     std::string(model_kind_name(x.model_kind)) + " model gives no tree to render");
  }
  return std::move(*result.tree);
}

std::optional<environment::Scene> recorded_run_scene(const Experiment& x, const RunRecord& record) {
  if (x.model_kind != ModelKind::kGrow && x.model_kind != ModelKind::kAdapt) return std::nullopt;
  const auto text = [&](const char* name) -> std::optional<std::string> {
    const auto it = record.parameters.find(name);
    if (it == record.parameters.end()) return std::nullopt;
    return parameter_text(it->second);
  };
  if (x.model_kind == ModelKind::kGrow &&
      find_grow_set(text("set").value_or("G")) == GrowSet::kOpen) {
    return std::nullopt;
  }
  std::string path = x.model_scene;
  if (const auto scene = text("scene")) {
    if (*scene == "open") return std::nullopt;
    // As the models resolve it: against the experiment file's folder.
    const std::filesystem::path p(*scene);
    path = p.is_absolute() || x.path == "<string>"
               ? p.string()
               : (std::filesystem::path(x.path).parent_path() / p).string();
  }
  if (path.empty()) return std::nullopt;
  environment::Scene scene = environment::read_scene_file(path);
  if (x.model_kind == ModelKind::kAdapt) {
    // The adapt model keeps the tree where it is and moves the scene the other way.
    Eigen::Vector3d at = Eigen::Vector3d::Zero();
    if (const auto it = record.parameters.find("tree_x_m"); it != record.parameters.end())
      at.x() = parameter_number(it->second, "tree_x_m");
    if (const auto it = record.parameters.find("tree_y_m"); it != record.parameters.end())
      at.y() = parameter_number(it->second, "tree_y_m");
    scene = environment::translated(scene, -at);
  }
  return scene;
}

}  // namespace fspm::experiments
