// fspm run | results export | show | merge: parameter sweeps and their result databases.
#include <unistd.h>

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "cli/commands.hpp"
#include "cli/full_command_list.hpp"
#include "cli/html_report.hpp"
#include "cli/html_single_file.hpp"
#include "cli/output.hpp"
#include "cli/report_figures.hpp"
#include "cli/report_light_profile.hpp"
#include "cli/run_file_writers.hpp"
#include "cli/xvfb.hpp"
#include "experiments/comparisons.hpp"
#include "experiments/experiment.hpp"
#include "experiments/model_factory.hpp"
#include "experiments/mpi_runner.hpp"
#include "experiments/report.hpp"
#include "experiments/report_findings.hpp"
#include "experiments/report_intro.hpp"
#include "experiments/results_export.hpp"
#include "experiments/run_plan.hpp"
#include "experiments/runner.hpp"
#include "experiments/shell_text.hpp"
#include "experiments/slurm_script.hpp"
#include "fspm/atomic_file.hpp"
#include "fspm/error.hpp"
#include "fspm/number_text.hpp"
#include "fspm/p_value_text.hpp"
#include "fspm/signal_cleanup.hpp"
#include "graphics/render.hpp"

namespace fspm::cli {
namespace {

namespace fs = std::filesystem;
namespace ex = fspm::experiments;
// Far above any machine; -j 0 is one thread per hardware thread.
constexpr double kMaxJobs = 4096;

std::atomic<bool> g_interrupted{false};
// The signal that stopped the runs: the exit code is 128 + its number, as a shell reports a
// process the signal killed (130 for SIGINT, 143 for SIGTERM).
std::atomic<int> g_interrupt_signal{SIGINT};

extern "C" void on_interrupt(int signal) {
  g_interrupt_signal.store(signal);
  g_interrupted.store(true);
  // A second Ctrl-C ends the process at once, removing the temporaries of unfinished outputs.
  std::signal(signal, fspm_signal_cleanup_handler);
}

struct RunOptions {
  std::string experiment;
  std::string out;
  std::size_t jobs = 0;
  bool resume = false;
  std::string shard;
  double time_limit_s = 0.0;
  bool json = false;
  bool emit_slurm = false;
  bool mpi = false;
  // --shards and --slurm-time bound straight into the script's options, whose defaults are theirs.
  ex::SlurmOptions slurm;
  std::string slurm_file;
  std::size_t replicates = 0;  // 0: the file's
  bool grid_order = false;
};

struct ExportOptions {
  std::string dir;
  bool csv = false;
  bool json = false;
  std::string output;
};

struct ShowOptions {
  std::string dir;
  bool json = false;
};

struct ReportOptions {
  std::string dir;
  std::string output;
  bool no_figures = false;
  bool html = false;
  bool single_file = false;
  bool json = false;
};

struct CompareOptions {
  std::string dir;
  std::size_t jobs = 0;
  bool json = false;
};

struct MergeOptions {
  std::string out;
  std::vector<std::string> inputs;
  bool json = false;
};

std::pair<std::size_t, std::size_t> parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  try {
    if (slash != std::string::npos) {
      std::size_t used = 0;
      const std::size_t i = std::stoul(text.substr(0, slash), &used);
      if (used == slash) {
        const std::string rest = text.substr(slash + 1);
        const std::size_t n = std::stoul(rest, &used);
        if (used == rest.size() && n > 0 && i < n) return {i, n};
      }
    }
  } catch (const std::exception&) {
  }
  throw ValueError("--shard: expected I/N with 0 <= I < N (e.g. 0/4), not '" + text + "'");
}

// Named after the experiment, in the current folder whatever the name holds ("../x" too).
std::string default_out(const ex::Experiment& x) {
  return ex::file_stem_from_name(x.name) + "-results";
}

void emit_slurm(const RunOptions& o, const ex::Experiment& x) {
  ex::SlurmOptions s = o.slurm;
  s.fspm_executable = fs::read_symlink("/proc/self/exe").string();
  s.experiment_file = fs::absolute(o.experiment).lexically_normal().string();
  s.out_dir = fs::absolute(o.out.empty() ? default_out(x) : o.out).lexically_normal().string();
  s.job_name = x.name;
  s.cpus_per_task = o.jobs == 0 ? 1 : o.jobs;
  s.script_path = o.slurm_file.empty() ? ex::file_stem_from_name(x.name) + ".slurm" : o.slurm_file;
  const std::string script = ex::slurm_script(s);
  write_file_atomically(s.script_path, [&](std::ostream& out) { out << script; });
  fs::permissions(s.script_path, fs::perms::owner_exec | fs::perms::group_exec,
                  fs::perm_options::add);
  if (o.json) {
    print_json({{"slurm_script", s.script_path}, {"shards", s.shards}, {"out", s.out_dir}});
  } else {
    std::cout << "wrote " << s.script_path << " (" << s.shards << " shards of " << x.runs()
              << " runs); submit it with: sbatch " << ex::shell_quote(s.script_path) << '\n';
  }
}

// The experiment's comparisons over the runs recorded in `dir` (after fspm run, or after merging
// shards with fspm compare).
ex::ComparisonResults compare_runs(const std::string& dir, std::size_t jobs, bool quiet) {
  ex::ComparisonResults c = ex::compare_results(dir, jobs);
  // A small version of a big experiment falls short in every group: a few notes suffice.
  constexpr std::size_t kShownNotes = 3;
  for (std::size_t i = 0; i < c.notes.size() && i < kShownNotes; ++i) {
    std::cerr << "fspm: " << c.notes[i] << '\n';
  }
  if (c.notes.size() > kShownNotes) {
    std::cerr << "fspm: ... and " << c.notes.size() - kShownNotes << " more notes in "
              << (fs::path(dir) / ex::kComparisonsFile).string() << '\n';
  }
  if (quiet) return c;
  std::cout << (fs::path(dir) / ex::kPairsFile).string() << ": " << c.pairs.size()
            << " pairs compared in " << format_significant(c.seconds) << " s\n";
  for (const ex::TTestRow& t : c.tests) {
    std::cout << "t-test " << t.a << " vs " << t.b << " (" << t.group << ", "
              << ex::distance_scale_name(t.scale) << " distance): t = " << format_significant(t.t)
              << ", df = " << format_significant(t.df) << ", " << format_p_value(t.p)
              << (t.significant() ? " (significant)" : " (not significant)") << '\n';
  }
  return c;
}

// `fspm compare --json`: the files written, the number of pairs and every t-test.
nlohmann::json comparisons_json(const std::string& dir, const ex::ComparisonResults& c) {
  nlohmann::json tests = nlohmann::json::array();
  for (const ex::TTestRow& t : c.tests) {
    tests.push_back({{"a", t.a},
                     {"b", t.b},
                     {"group", t.group},
                     {"test", t.welch ? "welch" : "student"},
                     {"alternative", std::string(alternative_name(t.alternative))},
                     {"distance", std::string(ex::distance_scale_name(t.scale))},
                     {"t", t.t},
                     {"df", t.df},
                     {"p", t.p},
                     {"alpha", t.alpha},
                     {"significant", t.significant()},
                     {"mean_a", t.mean_a},
                     {"sd_a", t.sd_a},
                     {"n_a", t.n_a},
                     {"mean_b", t.mean_b},
                     {"sd_b", t.sd_b},
                     {"n_b", t.n_b}});
  }
  return {{"pairs_file", (fs::path(dir) / ex::kPairsFile).string()},
          {"pairs", c.pairs.size()},
          {"seconds", c.seconds},
          {"notes", c.notes.size()},
          {"ttests", std::move(tests)}};
}

// The experiment a result database was made from, read back from its stored text.
ex::Experiment stored_experiment(const ex::ResultsDb& db) {
  return ex::parse_experiment(db.info().experiment_text, db.info().experiment_path);
}

// Where and how the runs go: output folder, threads, shard, time limit, files kept per run.
ex::RunnerOptions runner_options(const RunOptions& o, const ex::Experiment& x) {
  ex::RunnerOptions r;
  r.out_dir = o.out.empty() ? default_out(x) : o.out;
  r.jobs = o.jobs;
  r.resume = o.resume;
  if (!o.shard.empty()) std::tie(r.shard_index, r.shard_count) = parse_shard(o.shard);
  if (o.time_limit_s > 0.0) r.time_limit_s = o.time_limit_s;
  r.interrupt = &g_interrupted;
  r.longest_first = !o.grid_order;
  if (o.mpi && !ex::mpi_available()) {
    throw ValueError("--mpi: this fspm was built without MPI (install libopenmpi-dev, rebuild)");
  }
  r.file_writers = graphics_run_file_writers(x);
  ex::check_run_file_writers(x, r.file_writers);
  return r;
}

// Images kept per run are rendered with VTK, which needs an X display: found (or started under
// xvfb-run) before the first run.
void require_display_for_images(const RunOptions& o, const ex::Experiment& x) {
  if (std::find(x.keep.begin(), x.keep.end(), ex::KeptFile::kImage) == x.keep.end()) return;
  // Under mpirun every rank would start its own virtual server: the ranks need a display.
  if (!o.mpi) rerun_under_xvfb_if_needed();
  if (graphics::display_available()) return;
  throw IoError(
      "outputs.keep: images are rendered with VTK, which needs an X display; run under "
      "xvfb-run -a" +
          std::string(o.mpi ? " (every rank needs a display: xvfb-run -a mpirun ... on one "
                              "machine, mpirun ... xvfb-run -a fspm run ... on several)"
                            : ""),
      x.path, x.keep_line);
}

// Runs the plan, stopping cleanly at SIGINT or SIGTERM (the runs done so far are kept).
ex::RunnerSummary run_interruptibly(const RunOptions& o, const ex::Experiment& x,
                                    const ex::Model& model, const ex::RunnerOptions& r,
                                    bool& is_root) {
  g_interrupted = false;
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  const ex::RunnerSummary s =
      o.mpi ? ex::run_experiment_mpi(x, model, r, is_root) : ex::run_experiment(x, model, r);
  std::signal(SIGINT, fspm_signal_cleanup_handler);
  std::signal(SIGTERM, fspm_signal_cleanup_handler);
  return s;
}

void print_run_summary(const RunOptions& o, const ex::Experiment& x, const ex::RunnerSummary& s) {
  if (o.json) {
    print_json({{"experiment", x.name},
                {"database", s.database},
                {"total_runs", s.total_runs},
                {"shard_runs", s.shard_runs},
                {"already_done", s.already_done},
                {"ran", s.ran},
                {"ok", s.ok},
                {"error", s.failed},
                {"timeout", s.timed_out},
                {"interrupted", s.interrupted},
                {"seconds", s.seconds}});
    return;
  }
  std::cout << s.database << ": " << s.ran << " runs in " << s.seconds << " s (" << s.ok << " ok, "
            << s.failed << " error, " << s.timed_out << " timeout)";
  if (s.already_done > 0) std::cout << ", " << s.already_done << " were already done";
  std::cout << '\n';
}

void run_command(const RunOptions& o) {
  ex::Experiment x = ex::read_experiment(o.experiment);
  if (o.replicates > 0) {
    if (o.emit_slurm) throw ValueError("--replicates: not with --emit-slurm (edit the file)");
    ex::override_replicates(x, o.replicates);
  }
  // Everything is checked before the first run: keys, ranges, model file, parameter names.
  const std::unique_ptr<ex::Model> model = ex::make_model(x);
  const ex::RunPlan plan(x);
  ex::check_experiment(x, *model, plan);
  if (o.emit_slurm) {
    emit_slurm(o, x);
    return;
  }
  ex::RunnerOptions r = runner_options(o, x);
  require_display_for_images(o, x);
  if (verbosity() > 0) {
    r.progress = &std::cerr;
    r.progress_bar = ::isatty(STDERR_FILENO) != 0;
    if (!o.mpi)
      std::cerr << "experiment " << x.name << ": " << plan.size() << " runs (" << plan.points()
                << " points x " << x.replicates << " replicates) into " << r.out_dir << '\n';
  }
  bool is_root = true;
  const ex::RunnerSummary s = run_interruptibly(o, x, *model, r, is_root);
  if (!is_root) return;  // rank 0 reports for everyone
  print_run_summary(o, x, s);
  if (!s.interrupted && r.shard_count == 1 && !x.comparisons.empty()) {
    compare_runs(r.out_dir, o.jobs, o.json);
  }
  if (s.interrupted) {
    std::cerr << "fspm: interrupted; " << (s.shard_runs - s.already_done - s.ran)
              << " runs are missing, continue with --resume\n";
    std::cout.flush();
    std::exit(128 + g_interrupt_signal.load());
  }
}

void export_command(const ExportOptions& o) {
  if (o.csv == o.json) throw ValueError("results export: give exactly one of --csv and --json");
  refuse_overwriting_input(o.output, {(fs::path(o.dir) / ex::kDatabaseFile).string()});
  const ex::ResultsDb db(o.dir, ex::ResultsDb::Mode::kRead);
  const std::vector<ex::RunRecord> runs = db.read_all();
  auto write = [&](std::ostream& out) {
    if (o.csv) {
      ex::write_results_csv(db.info(), runs, out);
    } else {
      out << ex::results_json(db.info(), runs);
    }
  };
  if (o.output.empty()) {
    write(std::cout);
  } else {
    write_file_atomically(o.output, write);
  }
}

void show_command(const ShowOptions& o) {
  const ex::ResultsDb db(o.dir, ex::ResultsDb::Mode::kRead);
  const std::vector<ex::RunRecord> runs = db.read_all();
  std::cout << (o.json ? ex::results_summary_json(db.info(), runs)
                       : ex::results_summary_text(db.info(), runs));
}

void compare_command(const CompareOptions& o) {
  const ex::ComparisonResults c = compare_runs(o.dir, o.jobs, o.json);
  if (o.json) print_json(comparisons_json(o.dir, c));
}

// What the report is made of: the database, the experiment read back from it (when its model
// files are still there) and the comparisons (when computed).
struct ReportInputs {
  std::vector<ex::RunRecord> runs;
  std::optional<ex::Experiment> x;
  std::optional<ex::ComparisonResults> comparisons;
  std::string note;  // why the experiment's extras are left out
};

ReportInputs read_report_inputs(const ex::ResultsDb& db, const std::string& dir) {
  ReportInputs in;
  in.runs = db.read_all();
  try {
    in.x = stored_experiment(db);
  } catch (const Error& e) {
    // The report's main tables need only the database; the extras need the model files too.
    in.note = "\nNote: summary tables and comparisons left out: " + std::string(e.what()) + '\n';
  }
  ex::ComparisonResults c;
  if (in.x && !in.x->comparisons.empty() && ex::read_comparisons(dir, c)) {
    c.tests = ex::comparison_ttests(*in.x, c.pairs);
    in.comparisons = std::move(c);
  }
  return in;
}

// The Markdown report; `figures` draws the PNG figures and renders, `html` puts the HTML page's
// placeholders in their place instead (the page adds the trees itself).
std::string report_markdown(const ex::ResultsDb& db, const ReportInputs& in, const std::string& dir,
                            bool figures, bool html) {
  const ex::Experiment* x = in.x ? &*in.x : nullptr;
  // What was found first (findings, comparisons and their plots), then the metrics per point,
  // the timings last.
  std::string opening = x ? ex::report_introduction(*x) : "";
  if (x != nullptr && in.comparisons) {
    opening += ex::findings_markdown(*x, in.comparisons->tests);
    opening += ex::comparisons_markdown(*x, *in.comparisons);
    if (html) opening += html_comparisons_markdown();
    if (figures) opening += comparison_figures(*x, *in.comparisons, dir);
    opening += "\n";
  } else if (x != nullptr && !x->comparisons.empty()) {
    opening += "The comparisons have not been computed yet: run `fspm compare " + dir + "`.\n\n";
  }
  std::string md = ex::markdown_report(db.info(), in.runs, opening);
  md += in.note;
  if (x == nullptr) return md;
  if (html) md += html_sweeps_markdown(db.info(), in.runs);
  if (figures) md += sweep_figures(*x, db.info(), in.runs, dir);
  md += ex::summary_tables_markdown(*x, in.runs);
  if (figures) md += tree_renders(*x, in.runs, dir);
  if (figures) md += light_profile_figure(*x, in.runs, dir);
  md += ex::timings_markdown(db.info(), in.runs);  // last: for whoever plans the next sweep
  return md;
}

void report_command(const ReportOptions& o) {
  // Figures and renders draw through VTK, which needs an X display.
  if (!o.no_figures && graphics::render_available()) rerun_under_xvfb_if_needed();
  const ex::ResultsDb db(o.dir, ex::ResultsDb::Mode::kRead);
  const ReportInputs in = read_report_inputs(db, o.dir);
  const std::string md = report_markdown(db, in, o.dir, !o.no_figures, false);
  const std::string path = o.output.empty() ? (fs::path(o.dir) / "report.md").string() : o.output;
  write_file_atomically(path, [&](std::ostream& out) { out << md; });
  std::string html_path;
  if (o.html || o.single_file || (in.x && in.x->report_html)) {
    HtmlReportInput h;
    h.experiment = in.x ? &*in.x : nullptr;
    h.info = &db.info();
    h.runs = &in.runs;
    h.comparisons = in.comparisons ? &*in.comparisons : nullptr;
    h.markdown = report_markdown(db, in, o.dir, false, true);
    h.dir = o.dir;
    html_path = write_html_report(h).string();
    if (o.single_file) {
      const fs::path single = fs::path(o.dir) / "report.html";
      const std::uintmax_t bytes =
          write_single_file_report(fs::path(html_path).parent_path(), single);
      spdlog::info("{}: the HTML report in one file, {:.1f} MB", single.string(), bytes / 1e6);
      html_path = single.string();
    }
  }
  if (!o.json) {
    std::cout << path << '\n';
    if (!html_path.empty()) std::cout << html_path << '\n';
    return;
  }
  // What went in, and what was left out (a note in the report says why).
  print_json({{"report", path},
              {"html", html_path.empty() ? nlohmann::json(nullptr) : nlohmann::json(html_path)},
              {"runs", in.runs.size()},
              {"experiment", in.x.has_value()},
              {"figures", md.find("](figures/") != std::string::npos},
              {"notes", md.find("\nNote: ") != std::string::npos}});
}

void merge_command(const MergeOptions& o) {
  const ex::MergeSummary m = ex::merge_results(o.out, o.inputs);
  if (o.json) {
    print_json({{"out", o.out},
                {"inputs", m.inputs},
                {"rows", m.rows},
                {"duplicates", m.duplicates},
                {"missing", m.missing}});
  } else {
    std::cout << "merged " << m.inputs << " databases into " << o.out << ": " << m.rows << " runs, "
              << m.duplicates << " duplicates skipped, " << m.missing << " runs missing\n";
  }
}

}  // namespace

void add_experiment_commands(CLI::App& app) {
  auto run = std::make_shared<RunOptions>();
  CLI::App* r = app.add_subcommand(kRunCommand.name, kRunCommand.description);
  r->add_option("EXPERIMENT", run->experiment, "Experiment file (.toml, see docs/experiments.md)")
      ->required();
  r->add_option("-j,--jobs", run->jobs, "Worker threads (default: one per hardware thread)")
      ->check(number_in(0, kMaxJobs));
  r->add_option("-o,--out", run->out, "Output directory (default: NAME-results)");
  r->add_flag("--resume", run->resume, "Continue the database in the output directory");
  r->add_option("--shard", run->shard, "Run only shard I of N (runs with index % N == I)");
  r->add_option("--time-limit", run->time_limit_s, "Seconds per run (overrides the file)")
      ->check(positive_number(1e9));
  r->add_option("--replicates", run->replicates,
                "Replicates per point (overrides the file; a quick, smaller version of a sweep)")
      ->check(number_in(1, 1e9));
  r->add_flag("--grid-order", run->grid_order,
              "Hand out runs in index order (default: the costliest first)");
  r->add_flag("--json", run->json, "Machine-readable JSON summary on stdout");
  r->add_flag("--mpi", run->mpi, "Spread the runs over the MPI ranks (under mpirun)");
  r->add_flag("--emit-slurm", run->emit_slurm, "Write a Slurm job-array script instead of running");
  r->add_option("--shards", run->slurm.shards, "--emit-slurm: number of array tasks")
      ->check(number_in(1, 1e6))
      ->capture_default_str();
  r->add_option("--slurm-file", run->slurm_file, "--emit-slurm: script path (default NAME.slurm)");
  r->add_option("--slurm-time", run->slurm.time_limit, "--emit-slurm: time limit of one task")
      ->capture_default_str();
  r->callback([run] { run_command(*run); });

  auto compare = std::make_shared<CompareOptions>();
  CLI::App* cmp = app.add_subcommand(kCompareCommand.name, kCompareCommand.description);
  cmp->add_option("DIR", compare->dir, "Output directory of fspm run (or of results merge)")
      ->required();
  cmp->add_option("-j,--jobs", compare->jobs, "Threads (default: one per hardware thread)")
      ->check(number_in(0, kMaxJobs));
  cmp->add_flag("--json", compare->json,
                "One JSON object on stdout: pairs, seconds and every t-test (t, df, p, means)");
  cmp->callback([compare] { compare_command(*compare); });

  auto report = std::make_shared<ReportOptions>();
  CLI::App* rep = app.add_subcommand(kReportCommand.name, kReportCommand.description);
  rep->add_option("DIR", report->dir, "Output directory of fspm run")->required();
  rep->add_option("-o,--output", report->output, "Report path (default DIR/report.md)");
  rep->add_flag("--no-figures", report->no_figures, "Tables only (figures need an X display)");
  rep->add_flag("--html", report->html,
                "Also an interactive HTML report, DIR/report/index.html (as [report] html = true)");
  rep->add_flag("--single-file", report->single_file,
                "Also DIR/report.html, the HTML report in one file with its "
                "libraries, data and trees (glTF) inside, to send or archive (implies --html)");
  rep->add_flag("--json", report->json,
                "One JSON object on stdout: report path, runs, and whether the experiment's "
                "tables, figures and notes are in it");
  rep->callback([report] { report_command(*report); });

  CLI::App* results = app.add_subcommand(kResultsCommand.name, kResultsCommand.description);
  results->require_subcommand(1);

  auto exp = std::make_shared<ExportOptions>();
  CLI::App* e = results->add_subcommand("export", "Export every run as CSV or JSON");
  e->add_option("DIR", exp->dir, "Output directory of fspm run")->required();
  e->add_flag("--csv", exp->csv, "CSV: run, seed, status, seconds, parameters, metrics");
  e->add_flag("--json", exp->json, "JSON: every column of every run");
  e->add_option("-o,--output", exp->output, "File to write (default: stdout)");
  e->callback([exp] { run_reporting_command([&] { export_command(*exp); }); });

  auto show = std::make_shared<ShowOptions>();
  CLI::App* s = results->add_subcommand("show", "Summary of a result database");
  s->add_option("DIR", show->dir, "Output directory of fspm run")->required();
  s->add_flag("--json", show->json, "Machine-readable JSON on stdout");
  s->callback([show] { show_command(*show); });

  auto merge = std::make_shared<MergeOptions>();
  CLI::App* m = results->add_subcommand("merge", "Combine the databases of an experiment's shards");
  m->add_option("OUT_DIR", merge->out, "New output directory")->required();
  m->add_option("DIR", merge->inputs, "Shard output directories")->required();
  m->add_flag("--json", merge->json, "Machine-readable JSON on stdout");
  m->callback([merge] { merge_command(*merge); });
}

}  // namespace fspm::cli
