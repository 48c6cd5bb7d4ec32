#include "cli/html_report_data.hpp"

#include <cmath>
#include <string>
#include <variant>

#include "experiments/report.hpp"
#include "experiments/sweep_summary.hpp"

namespace fspm::cli {
namespace {

namespace ex = fspm::experiments;
using nlohmann::json;

json number_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json parameter_json(const ex::ParameterValue& v) {
  if (const auto* i = std::get_if<std::int64_t>(&v)) return *i;
  if (const auto* d = std::get_if<double>(&v)) return number_or_null(*d);
  return std::get<std::string>(v);
}

}  // namespace

json html_runs_json(const ex::ExperimentInfo& info, const std::vector<ex::RunRecord>& runs) {
  json out = {{"run", json::array()},         {"point", json::array()},
              {"seed", json::array()},        {"status", json::array()},
              {"parameters", json::object()}, {"metrics", json::object()}};
  for (const std::string& name : info.swept) out["parameters"][name] = json::array();
  for (const std::string& name : info.metrics) out["metrics"][name] = json::array();
  for (const ex::RunRecord& r : runs) {
    out["run"].push_back(r.run);
    out["point"].push_back(r.point);
    out["seed"].push_back(std::to_string(r.seed));
    out["status"].push_back(std::string(ex::run_status_name(r.status)));
    for (const std::string& name : info.swept) {
      const auto it = r.parameters.find(name);
      out["parameters"][name].push_back(it == r.parameters.end() ? json(nullptr)
                                                                 : parameter_json(it->second));
    }
    for (const std::string& name : info.metrics) {
      const auto it = r.metrics.find(name);
      const bool ok = r.status == ex::RunStatus::kOk && it != r.metrics.end();
      out["metrics"][name].push_back(ok ? number_or_null(it->second) : json(nullptr));
    }
  }
  return out;
}

json html_metrics_json(const ex::ExperimentInfo& info, std::optional<ex::ModelKind> model_kind) {
  json out = json::array();
  for (const std::string& name : info.metrics) {
    out.push_back({{"name", name},
                   {"unit", ex::metric_unit(name, model_kind)},
                   {"timing", ex::is_timing_metric(name)}});
  }
  return out;
}

json html_pairs_json(const ex::ComparisonResults& results, ex::DistanceScale scale) {
  json out = {{"scale", std::string(ex::distance_scale_name(scale))},
              {"raw_distance", json::array()},
              {"comparison", json::array()},
              {"group", json::array()},
              {"run_a", json::array()},
              {"run_b", json::array()},
              {"distance", json::array()}};
  for (const ex::PairDistance& p : results.pairs) {
    out["comparison"].push_back(p.comparison);
    out["group"].push_back(p.group);
    out["run_a"].push_back(p.run_a);
    out["run_b"].push_back(p.run_b);
    out["distance"].push_back(number_or_null(p.value(scale)));
    out["raw_distance"].push_back(number_or_null(p.distance));
  }
  return out;
}

json html_light_profiles_json(const LightProfiles& profiles) {
  json out = json::array();
  for (const TreeLightProfile& t : profiles.trees) {
    json tree = {{"run", t.run},
                 {"group", t.group},
                 {"height_m", json::array()},
                 {"mean_light", json::array()},
                 {"clusters", json::array()}};
    for (const environment::LightLayer& layer : t.layers) {
      tree["height_m"].push_back(number_or_null(layer.height_m));
      tree["mean_light"].push_back(number_or_null(layer.mean_light));
      tree["clusters"].push_back(layer.clusters);
    }
    out.push_back(std::move(tree));
  }
  return out;
}

}  // namespace fspm::cli
