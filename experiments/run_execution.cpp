#include "experiments/run_execution.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "experiments/comparisons.hpp"
#include "experiments/metrics.hpp"
#include "fspm/tree_file.hpp"

namespace fspm::experiments {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using nlohmann::json;

std::string utc_now() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

}  // namespace

ExecutionSettings execution_settings(const Experiment& experiment, const std::string& out_dir,
                                     std::optional<double> time_limit_override,
                                     const std::atomic<bool>* interrupt,
                                     const RunFileWriters& writers) {
  check_run_file_writers(experiment, writers);
  ExecutionSettings s;
  s.experiment = &experiment;
  s.out_dir = out_dir;
  s.time_limit_s = time_limit_override ? time_limit_override : experiment.time_limit_s;
  s.keep_tree = std::find(experiment.keep.begin(), experiment.keep.end(), KeptFile::kTree) !=
                experiment.keep.end();
  s.interrupt = interrupt;
  for (const KeptFile kind : experiment.keep) {
    if (kind != KeptFile::kTree) s.file_writers.emplace_back(kind, writers.find(kind)->second);
  }
  if (!experiment.keep.empty()) fs::create_directories(fs::path(out_dir) / "runs");
  const bool wants_distance = std::find(experiment.metrics.begin(), experiment.metrics.end(),
                                        "distance_to_reference") != experiment.metrics.end();
  if (wants_distance && !experiment.reference_file.empty()) {
    s.reference = std::make_shared<const TreeGraph>(read_tree_file(experiment.reference_file));
  }
  return s;
}

std::optional<RunRecord> execute_run(const Model& model, const RunSpec& spec,
                                     const ExecutionSettings& settings) {
  const Experiment& experiment = *settings.experiment;
  RunRecord record;
  record.run = spec.index;
  record.point = spec.point;
  record.replicate = spec.replicate;
  record.seed = spec.seed;
  record.parameters = spec.parameters;
  const std::optional<double> limit_s = settings.time_limit_s;
  const std::string limit_text =
      limit_s ? "time limit of " + std::to_string(*limit_s) + " s exceeded" : std::string();
  const Clock::time_point t0 = Clock::now();
  std::optional<Clock::time_point> deadline;
  if (limit_s) {
    deadline =
        t0 + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(*limit_s));
  }
  const RunContext context(deadline, settings.interrupt);
  try {
    RunResult result = model.run(spec.parameters, spec.seed, context);
    record.seconds = seconds_since(t0);
    if (settings.reference && result.tree) {
      // Not part of the run's time: it measures the model, not the comparison.
      result.metrics["distance_to_reference"] =
          constrained_edit_distance(*result.tree, *settings.reference,
                                    distance_options(experiment.distance))
              .distance;
    }
    for (const std::string& name : experiment.metrics) {
      const auto it = result.metrics.find(name);
      record.metrics[name] = it != result.metrics.end() ? it->second : std::nan("");
    }
    if (limit_s && record.seconds > *limit_s) {
      // A model that does not check its context still gets the status it earned.
      record.status = RunStatus::kTimeout;
      record.error = limit_text;
    } else if (result.tree) {
      if (settings.keep_tree) {
        const std::string rel = run_file_path(spec.index, "tree");
        write_tree_file(*result.tree, (fs::path(settings.out_dir) / rel).string());
        record.files.push_back(rel);
      }
      for (const auto& [kind, writer] : settings.file_writers) {
        try {
          record.files.push_back(writer(*result.tree, spec.index, settings.out_dir));
        } catch (const std::exception& e) {
          throw IoError("keeping the run's " + std::string(kept_file_name(kind)) + ": " + e.what());
        }
      }
    }
  } catch (const RunStopped& e) {
    record.seconds = seconds_since(t0);
    if (!e.timed_out()) return std::nullopt;  // interrupted: no row, --resume runs it again
    record.status = RunStatus::kTimeout;
    record.error = limit_text;
  } catch (const std::exception& e) {
    record.seconds = seconds_since(t0);
    record.status = RunStatus::kError;
    record.error = e.what();
  } catch (...) {
    record.seconds = seconds_since(t0);
    record.status = RunStatus::kError;
    record.error = "unknown exception";
  }
  if (record.status != RunStatus::kOk) {
    for (const std::string& name : experiment.metrics) record.metrics[name] = std::nan("");
  }
  if (record.metrics.contains(std::string(kRunTimeMetric))) {
    record.metrics[std::string(kRunTimeMetric)] = record.seconds;
  }
  record.finished_at = utc_now();
  return record;
}

std::string record_to_json(const RunRecord& r) { return run_record_json(r).dump(); }

RunRecord record_from_json(const std::string& text) {
  return run_record_from_json(nlohmann::json::parse(text));
}

}  // namespace fspm::experiments
