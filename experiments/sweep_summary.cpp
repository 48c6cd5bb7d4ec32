#include "experiments/sweep_summary.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

#include "experiments/metrics.hpp"

namespace fspm::experiments {

void Moments::add(double x) {
  ++n;
  const double d = x - mean;
  mean += d / static_cast<double>(n);
  m2 += d * (x - mean);
  min = std::min(min, x);
  max = std::max(max, x);
}

double Moments::sd() const { return n > 1 ? std::sqrt(m2 / static_cast<double>(n - 1)) : 0.0; }

bool SweptParameter::numeric() const {
  return std::all_of(values.begin(), values.end(),
                     [](const SweptValue& v) { return !std::isnan(v.number); });
}

std::vector<SweptParameter> sweep_summary(const ExperimentInfo& info,
                                          const std::vector<RunRecord>& runs) {
  std::vector<SweptParameter> out;
  for (const std::string& name : info.swept) {
    SweptParameter p;
    p.name = name;
    std::map<std::string, std::size_t> index;  // value text -> position in p.values
    for (const RunRecord& r : runs) {
      const auto it = r.parameters.find(name);
      if (it == r.parameters.end()) continue;
      const std::string text = parameter_text(it->second);
      auto [pos, inserted] = index.try_emplace(text, p.values.size());
      if (inserted) {
        const double number = std::holds_alternative<std::string>(it->second) ? std::nan("")
                              : std::holds_alternative<double>(it->second)
                                  ? std::get<double>(it->second)
                                  : static_cast<double>(std::get<std::int64_t>(it->second));
        p.values.push_back({text, number, {}});
      }
      if (r.status != RunStatus::kOk) continue;
      SweptValue& v = p.values[pos->second];
      for (const std::string& metric : info.metrics) {
        const auto m = r.metrics.find(metric);
        if (m != r.metrics.end() && std::isfinite(m->second)) v.metrics[metric].add(m->second);
      }
    }
    if (p.numeric()) {
      std::stable_sort(
          p.values.begin(), p.values.end(),
          [](const SweptValue& a, const SweptValue& b) { return a.number < b.number; });
    }
    out.push_back(std::move(p));
  }
  return out;
}

const SweptParameter* age_parameter(const std::vector<SweptParameter>& summary) {
  for (const SweptParameter& p : summary) {
    if ((p.name == "years" || p.name == "age") && p.values.size() >= 2) return &p;
  }
  return nullptr;
}

std::vector<RunRecord> runs_with(const std::vector<RunRecord>& runs, const std::string& parameter,
                                 const std::string& value) {
  std::vector<RunRecord> out;
  for (const RunRecord& r : runs) {
    const auto it = r.parameters.find(parameter);
    if (it != r.parameters.end() && parameter_text(it->second) == value) out.push_back(r);
  }
  return out;
}

bool is_timing_metric(const std::string& metric) {
  const MetricInfo* info = find_metric(metric);
  return info != nullptr && info->unit == "s";
}

}  // namespace fspm::experiments
