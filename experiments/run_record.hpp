#pragma once
// One row of the result database: what a run was given and what came out.
#include <cstddef>
#include <cstdint>
#include <map>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "experiments/parameter_set.hpp"

namespace fspm::experiments {

enum class RunStatus { kOk, kError, kTimeout };

// "ok", "error", "timeout".
std::string_view run_status_name(RunStatus status);
// Throws ValueError for another name.
RunStatus run_status_from_name(std::string_view name);

struct RunRecord {
  std::size_t run = 0;
  std::size_t point = 0;
  std::size_t replicate = 0;
  std::uint64_t seed = 0;
  RunStatus status = RunStatus::kOk;
  double seconds = 0.0;  // wall-clock time of the model run
  ParameterSet parameters;
  std::map<std::string, double> metrics;  // NaN: the model did not give this metric
  std::string error;                      // empty when the run succeeded
  std::vector<std::string> files;         // kept files, relative to the output directory
  std::string finished_at;                // UTC, ISO 8601
};

// The record as one JSON object, the one form of a row outside the database (the export's rows
// and the rows the MPI ranks send): NaN metrics and an empty error are null. And back; throws
// nlohmann::json's errors for a malformed object.
nlohmann::json run_record_json(const RunRecord& record);
RunRecord run_record_from_json(const nlohmann::json& j);

}  // namespace fspm::experiments
