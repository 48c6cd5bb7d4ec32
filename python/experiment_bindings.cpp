// Python bindings: running experiment files and recomputing their comparisons.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "experiments/comparisons.hpp"
#include "experiments/experiment.hpp"
#include "experiments/model_factory.hpp"
#include "experiments/run_plan.hpp"
#include "experiments/runner.hpp"
#include "python/bindings.hpp"

namespace fspm::python {

void bind_experiments(py::module_& m) {
  m.def(
      "run_experiment",
      [](const std::string& path, const std::string& out, std::size_t jobs, bool resume,
         std::size_t replicates) {
        namespace ex = fspm::experiments;
        ex::RunnerSummary s;
        {
          py::gil_scoped_release release;
          ex::Experiment x = ex::read_experiment(path);
          if (replicates > 0) ex::override_replicates(x, replicates);
          const std::unique_ptr<ex::Model> model = ex::make_model(x);
          const ex::RunPlan plan(x);
          ex::check_experiment(x, *model, plan);
          ex::RunnerOptions r;
          r.out_dir = out;
          r.jobs = jobs;
          r.resume = resume;
          s = ex::run_experiment(x, *model, r);
          // As fspm run: a complete sweep with [[comparison]]s gets its distances and t-tests.
          if (!x.comparisons.empty()) ex::compare_results(out, jobs);
        }
        py::dict d;
        d["database"] = s.database;
        d["total_runs"] = s.total_runs;
        d["ran"] = s.ran;
        d["ok"] = s.ok;
        d["error"] = s.failed;
        d["timeout"] = s.timed_out;
        d["seconds"] = s.seconds;
        return d;
      },
      py::arg("experiment"), py::arg("out"), py::arg("jobs") = 0, py::arg("resume") = false,
      py::arg("replicates") = 0,
      "Run an experiment file (TOML) into the directory `out` (replicates > 0 overrides the "
      "file's); read it with read_results, its comparisons (pairs.csv, ttests.csv) with pandas");

  m.def(
      "compare_results",
      [](const std::string& out, std::size_t jobs) {
        namespace ex = fspm::experiments;
        ex::ComparisonResults c;
        {
          py::gil_scoped_release release;
          c = ex::compare_results(out, jobs);
        }
        py::dict d;
        d["pairs"] = c.pairs.size();
        d["notes"] = c.notes;
        d["seconds"] = c.seconds;
        return d;
      },
      py::arg("out"), py::arg("jobs") = 0,
      "Recompute the [[comparison]] distances and t-tests of a result directory (pairs.csv, "
      "ttests.csv)");
}

}  // namespace fspm::python
