#include "experiments/results_export.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>

#include "fspm/error.hpp"
#include "fspm/number_text.hpp"

namespace fspm::experiments {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string number_cell(double v) {
  if (!std::isfinite(v)) return {};
  std::string out;
  append_number(out, v);
  return out;
}

// A number in text for people: four significant digits (export and --json keep every digit).
std::string human(double v) { return std::isfinite(v) ? format_significant(v) : "-"; }

struct Stats {
  std::size_t count = 0;
  double sum = 0.0;
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
};

json summary(const ExperimentInfo& info, const std::vector<RunRecord>& runs) {
  std::map<std::string, std::size_t> by_status = {{"ok", 0}, {"error", 0}, {"timeout", 0}};
  double seconds = 0.0;
  std::map<std::string, Stats> stats;
  json errors = json::array();
  for (const RunRecord& r : runs) {
    ++by_status[std::string(run_status_name(r.status))];
    seconds += r.seconds;
    if (r.status != RunStatus::kOk) {
      if (errors.size() < 5) errors.push_back({{"run", r.run}, {"error", r.error}});
      continue;
    }
    for (const auto& [name, v] : r.metrics) {
      if (!std::isfinite(v)) continue;
      Stats& s = stats[name];
      ++s.count;
      s.sum += v;
      s.min = std::min(s.min, v);
      s.max = std::max(s.max, v);
    }
  }
  json metrics = json::object();
  for (const std::string& name : info.metrics) {
    const Stats& s = stats[name];
    metrics[name] = s.count == 0 ? json{{"count", 0}}
                                 : json{{"count", s.count},
                                        {"mean", s.sum / static_cast<double>(s.count)},
                                        {"min", s.min},
                                        {"max", s.max}};
  }
  return {{"experiment", info.name},
          {"experiment_file", info.experiment_path},
          {"total_runs", info.total_runs},
          {"recorded", runs.size()},
          {"missing", info.total_runs - std::min(info.total_runs, runs.size())},
          {"status", by_status},
          {"run_seconds", seconds},
          {"swept", info.swept},
          {"metrics", metrics},
          {"first_errors", errors}};
}

}  // namespace

void write_results_csv(const ExperimentInfo& info, const std::vector<RunRecord>& runs,
                       std::ostream& out) {
  out << "run,seed,status,seconds";
  for (const std::string& name : info.swept) out << ',' << csv_cell(name);
  for (const std::string& name : info.metrics) out << ',' << csv_cell(name);
  out << '\n';
  for (const RunRecord& r : runs) {
    out << r.run << ',' << r.seed << ',' << run_status_name(r.status) << ','
        << number_cell(r.seconds);
    for (const std::string& name : info.swept) {
      const auto it = r.parameters.find(name);
      out << ','
          << (it == r.parameters.end() ? std::string() : csv_cell(parameter_text(it->second)));
    }
    for (const std::string& name : info.metrics) {
      const auto it = r.metrics.find(name);
      out << ',' << (it == r.metrics.end() ? std::string() : number_cell(it->second));
    }
    out << '\n';
  }
}

std::string results_json(const ExperimentInfo& info, const std::vector<RunRecord>& runs) {
  json doc = {{"experiment", info.name},
              {"experiment_file", info.experiment_path},
              {"total_runs", info.total_runs},
              {"swept", info.swept},
              {"metrics", info.metrics}};
  json rows = json::array();
  for (const RunRecord& r : runs) rows.push_back(run_record_json(r));
  doc["runs"] = std::move(rows);
  return doc.dump(2) + "\n";
}

std::string results_summary_json(const ExperimentInfo& info, const std::vector<RunRecord>& runs) {
  return summary(info, runs).dump(2) + "\n";
}

std::string results_summary_text(const ExperimentInfo& info, const std::vector<RunRecord>& runs) {
  const json s = summary(info, runs);
  std::ostringstream out;
  out << "experiment: " << info.name << " (" << info.experiment_path << ")\n";
  out << "runs: " << runs.size() << " of " << info.total_runs << " recorded, "
      << s["missing"].get<std::size_t>() << " missing\n";
  out << "status: " << s["status"]["ok"].get<std::size_t>() << " ok, "
      << s["status"]["error"].get<std::size_t>() << " error, "
      << s["status"]["timeout"].get<std::size_t>() << " timeout\n";
  out << "model run time: " << human(s["run_seconds"].get<double>()) << " s in total\n";
  if (!info.swept.empty()) {
    out << "swept:";
    for (const std::string& name : info.swept) out << ' ' << name;
    out << '\n';
  }
  out << "metrics over successful runs (mean [min, max]):\n";
  for (const std::string& name : info.metrics) {
    const json& m = s["metrics"][name];
    out << "  " << name << ": ";
    if (m["count"].get<std::size_t>() == 0) {
      out << "-\n";
    } else {
      out << human(m["mean"].get<double>()) << " [" << human(m["min"].get<double>()) << ", "
          << human(m["max"].get<double>()) << "]\n";
    }
  }
  for (const json& e : s["first_errors"]) {
    out << "error in run " << e["run"].get<std::size_t>() << ": " << e["error"].get<std::string>()
        << '\n';
  }
  return out.str();
}

MergeSummary merge_results(const std::string& out_dir, const std::vector<std::string>& inputs) {
  if (inputs.empty()) throw ValueError("results merge needs at least one input directory");
  MergeSummary summary;
  std::vector<std::unique_ptr<ResultsDb>> dbs;
  for (const std::string& dir : inputs) {
    dbs.push_back(std::make_unique<ResultsDb>(dir, ResultsDb::Mode::kRead));
    if (dbs.back()->info().experiment_text != dbs.front()->info().experiment_text) {
      throw IoError("belongs to another experiment than " + dbs.front()->path() +
                        "; only shards of one experiment can be merged",
                    dbs.back()->path());
    }
  }
  ResultsDb out(out_dir, ResultsDb::Mode::kCreate, dbs.front()->info());
  std::vector<char> taken(out.info().total_runs, 0);
  for (std::size_t k = 0; k < dbs.size(); ++k) {
    std::vector<RunRecord> rows = dbs[k]->read_all();
    std::vector<RunRecord> fresh;
    for (RunRecord& r : rows) {
      if (r.run >= taken.size() || taken[r.run] != 0) {
        ++summary.duplicates;
        continue;
      }
      taken[r.run] = 1;
      for (const std::string& file : r.files) {
        const fs::path target = fs::path(out_dir) / file;
        fs::create_directories(target.parent_path());
        std::error_code ec;
        fs::copy_file(fs::path(inputs[k]) / file, target, fs::copy_options::overwrite_existing, ec);
        if (ec)
          throw IoError("cannot copy a kept file: " + ec.message(),
                        (fs::path(inputs[k]) / file).string());
      }
      fresh.push_back(std::move(r));
    }
    out.insert(fresh);
    summary.rows += fresh.size();
  }
  summary.inputs = dbs.size();
  summary.missing = out.info().total_runs - summary.rows;
  return summary;
}

}  // namespace fspm::experiments
