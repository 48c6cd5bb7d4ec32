#include "experiments/run_record.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <variant>

namespace fspm::experiments {

using nlohmann::json;

json run_record_json(const RunRecord& r) {
  json params = json::object();
  for (const auto& [name, value] : r.parameters) {
    std::visit([&](const auto& v) { params[name] = v; }, value);
  }
  json metrics = json::object();
  for (const auto& [name, v] : r.metrics) metrics[name] = std::isfinite(v) ? json(v) : json();
  return {{"run", r.run},
          {"point", r.point},
          {"replicate", r.replicate},
          {"seed", r.seed},
          {"status", run_status_name(r.status)},
          {"seconds", r.seconds},
          {"parameters", params},
          {"metrics", metrics},
          {"error", r.error.empty() ? json() : json(r.error)},
          {"files", r.files},
          {"finished_at", r.finished_at}};
}

RunRecord run_record_from_json(const json& j) {
  RunRecord r;
  r.run = j.at("run").get<std::size_t>();
  r.point = j.at("point").get<std::size_t>();
  r.replicate = j.at("replicate").get<std::size_t>();
  r.seed = j.at("seed").get<std::uint64_t>();
  r.status = run_status_from_name(j.at("status").get<std::string>());
  r.seconds = j.at("seconds").get<double>();
  const json& params = j.at("parameters");
  for (auto it = params.begin(); it != params.end(); ++it) {
    if (it->is_number_integer()) {
      r.parameters[it.key()] = it->get<std::int64_t>();
    } else if (it->is_number()) {
      r.parameters[it.key()] = it->get<double>();
    } else {
      r.parameters[it.key()] = it->get<std::string>();
    }
  }
  const json& metrics = j.at("metrics");
  for (auto it = metrics.begin(); it != metrics.end(); ++it) {
    r.metrics[it.key()] = it->is_number() ? it->get<double>() : std::nan("");
  }
  const json& error = j.at("error");
  r.error = error.is_null() ? std::string() : error.get<std::string>();
  r.files = j.at("files").get<std::vector<std::string>>();
  r.finished_at = j.at("finished_at").get<std::string>();
  return r;
}

}  // namespace fspm::experiments
