#include "greenlab/calibration.hpp"

#include <ceres/ceres.h>

#include <toml++/toml.h>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "fspm/error.hpp"
#include "fspm/input_file.hpp"
#include "fspm/toml_text.hpp"
#include "greenlab/functional.hpp"
#include "greenlab/simulation.hpp"

namespace fspm::greenlab {
namespace {

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) {
    const auto b = field.find_first_not_of(" \t\r");
    const auto e = field.find_last_not_of(" \t\r");
    out.push_back(b == std::string::npos ? std::string() : field.substr(b, e - b + 1));
  }
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

// Structure and organ counts are fixed during a fit: only GL1 numbers change.
struct Model {
  PlantParams params;
  OrganTable counts;
  int cycles = 0;
};

double target_value(const Gl1Result& r, const Target& t) {
  const auto c = static_cast<std::size_t>(t.cycle);
  const auto a = static_cast<std::size_t>(t.age);
  if (t.quantity == "leaf_mass") return r.leaf_mass[a][c];
  if (t.quantity == "internode_mass") return r.internode_mass[a][c];
  if (t.quantity == "leaf_area") return r.leaf_area[c];
  return r.production[c];  // "production", checked when read
}

void check_targets(const Model& m, const std::vector<Target>& targets) {
  const int ages = static_cast<int>(m.params.ages.size());
  for (const Target& t : targets) {
    const bool organ = t.quantity == "leaf_mass" || t.quantity == "internode_mass";
    const int min_cycle = t.quantity == "production" ? 0 : 1;
    if (t.cycle < min_cycle || t.cycle > m.cycles || (organ && (t.age < 1 || t.age > ages))) {
      throw ValueError("target on line " + std::to_string(t.line) + " (" + t.quantity + ", age " +
                       std::to_string(t.age) + ", cycle " + std::to_string(t.cycle) +
                       ") is outside the simulated plant (" + std::to_string(ages) + " ages, " +
                       std::to_string(m.cycles) + " cycles)");
    }
  }
}

class Gl1Residuals {
 public:
  Gl1Residuals(const Model& model, const std::vector<Target>& targets,
               const std::vector<std::string>& names)
      : model_(model), targets_(targets), names_(names) {}

  bool operator()(double const* const* x, double* residuals) const {
    PlantParams p = model_.params;
    for (std::size_t i = 0; i < names_.size(); ++i) set_parameter(p, names_[i], x[0][i]);
    const Gl1Result r = run_gl1(p, model_.counts, model_.cycles);
    for (std::size_t k = 0; k < targets_.size(); ++k) {
      residuals[k] = target_value(r, targets_[k]) - targets_[k].value;
      if (!std::isfinite(residuals[k])) return false;
    }
    return true;
  }

 private:
  const Model& model_;
  const std::vector<Target>& targets_;
  const std::vector<std::string>& names_;
};

Model make_model(const PlantParams& params) {
  if (!params.functional.enabled) {
    throw ValueError("the plant has no [functional] table: nothing to calibrate");
  }
  Model m;
  m.params = params;
  m.cycles = params.cycles;
  std::mt19937_64 rng(params.seed);
  const CompressedTreeGraph g = simulate_compressed(params, rng);
  m.counts = organ_counts(g, static_cast<int>(params.ages.size()), m.cycles);
  return m;
}

}  // namespace

std::vector<Target> parse_targets_csv(const std::string& text, const std::string& source) {
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  std::vector<Target> out;
  bool header = false;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[0] == '#') continue;
    const auto f = split_csv_line(line);
    if (!header) {
      if (f != std::vector<std::string>{"quantity", "age", "cycle", "value"}) {
        throw ParseError("expected the header 'quantity,age,cycle,value'", source, line_no, 1);
      }
      header = true;
      continue;
    }
    if (f.size() != 4) {
      throw ParseError(
          "expected 4 fields (quantity,age,cycle,value), found " + std::to_string(f.size()), source,
          line_no, 1);
    }
    Target t;
    t.line = line_no;
    t.quantity = f[0];
    if (t.quantity != "leaf_mass" && t.quantity != "internode_mass" && t.quantity != "leaf_area" &&
        t.quantity != "production") {
      throw ParseError("unknown quantity '" + t.quantity +
                           "' (expected leaf_mass, internode_mass, leaf_area or production)",
                       source, line_no, 1);
    }
    auto column_of = [&](std::size_t field) {
      int col = 1;
      for (std::size_t i = 0; i < field; ++i) col += static_cast<int>(f[i].size()) + 1;
      return col;
    };
    try {
      std::size_t used = 0;
      t.age = f[1].empty() ? 0 : std::stoi(f[1], &used);
      if (used != f[1].size()) throw std::invalid_argument("age");
      t.cycle = std::stoi(f[2], &used);
      if (used != f[2].size()) throw std::invalid_argument("cycle");
    } catch (const std::exception&) {
      throw ParseError("age and cycle must be integers", source, line_no, column_of(1));
    }
    try {
      std::size_t used = 0;
      t.value = std::stod(f[3], &used);
      if (used != f[3].size() || !std::isfinite(t.value)) throw std::invalid_argument("value");
    } catch (const std::exception&) {
      throw ParseError("value must be a finite number", source, line_no, column_of(3));
    }
    out.push_back(t);
  }
  if (!header) throw ParseError("empty target file: expected 'quantity,age,cycle,value'", source);
  if (out.empty()) throw ParseError("target file has no data rows", source, line_no);
  return out;
}

std::vector<Target> read_targets_csv(const std::string& path) {
  return parse_targets_csv(read_input_file(path), path);
}

std::vector<double> predict_targets(const PlantParams& params, const std::vector<Target>& targets) {
  const Model m = make_model(params);
  check_targets(m, targets);
  const Gl1Result r = run_gl1(m.params, m.counts, m.cycles);
  std::vector<double> out;
  out.reserve(targets.size());
  for (const Target& t : targets) out.push_back(target_value(r, t));
  return out;
}

void FitOptions::validate() const {
  if (max_iterations < 1) {
    throw ValueError("max_iterations: expected a count >= 1, got " +
                     std::to_string(max_iterations));
  }
}

FitResult fit_gl1(const PlantParams& params, const std::vector<Target>& targets,
                  const std::vector<std::string>& names_in, const FitOptions& options) {
  const std::vector<std::string> names =
      names_in.empty() ? params.calibration_parameters : names_in;
  if (names.empty()) {
    throw ValueError("no parameters to fit: list them in [calibration] parameters = [...]");
  }
  options.validate();
  if (targets.size() < names.size()) {
    throw ValueError("fitting " + std::to_string(names.size()) + " parameters needs at least as " +
                     "many targets, got " + std::to_string(targets.size()));
  }
  const Model model = make_model(params);
  check_targets(model, targets);

  FitResult res;
  res.names = names;
  for (const auto& n : names) res.initial.push_back(get_parameter(params, n));
  std::vector<double> x = res.initial;

  ceres::Problem problem;
  auto* cost = new ceres::DynamicNumericDiffCostFunction<Gl1Residuals, ceres::CENTRAL>(
      new Gl1Residuals(model, targets, names));
  cost->AddParameterBlock(static_cast<int>(x.size()));
  cost->SetNumResiduals(static_cast<int>(targets.size()));
  problem.AddResidualBlock(cost, nullptr, x.data());
  // Sinks, shapes and plant parameters are all positive.
  for (int i = 0; i < static_cast<int>(x.size()); ++i) {
    problem.SetParameterLowerBound(x.data(), i, 1e-9);
  }
  ceres::Solver::Options so;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = options.max_iterations;
  so.function_tolerance = 1e-12;
  so.parameter_tolerance = 1e-12;
  so.gradient_tolerance = 1e-14;
  so.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  res.initial_cost = summary.initial_cost;
  res.final_cost = summary.final_cost;
  res.iterations = static_cast<int>(summary.iterations.size()) - 1;
  res.converged = summary.termination_type == ceres::CONVERGENCE;
  if (!res.converged) {
    std::ostringstream msg;
    msg << "calibration did not converge after " << res.iterations << " iterations: final cost "
        << res.final_cost << " (initial " << res.initial_cost << "); " << summary.message;
    throw ValueError(msg.str());
  }
  res.estimates = x;
  res.fitted = params;
  for (std::size_t i = 0; i < names.size(); ++i) set_parameter(res.fitted, names[i], x[i]);

  // Standard errors: sqrt(diag((J^T J)^-1) * s^2), s^2 = sum r^2 / (m - k).
  res.standard_errors.assign(x.size(), std::numeric_limits<double>::quiet_NaN());
  ceres::Covariance::Options co;
  co.algorithm_type = ceres::DENSE_SVD;
  co.null_space_rank = -1;
  ceres::Covariance covariance(co);
  std::vector<std::pair<const double*, const double*>> blocks{{x.data(), x.data()}};
  const double dof = static_cast<double>(targets.size()) - static_cast<double>(x.size());
  if (dof > 0 && covariance.Compute(blocks, &problem)) {
    std::vector<double> c(x.size() * x.size());
    if (covariance.GetCovarianceBlock(x.data(), x.data(), c.data())) {
      const double s2 = 2.0 * res.final_cost / dof;
      for (std::size_t i = 0; i < x.size(); ++i) {
        res.standard_errors[i] = std::sqrt(std::max(c[i * x.size() + i], 0.0) * s2);
      }
    }
  }
  res.residuals.resize(targets.size());
  const double* xs[] = {x.data()};
  Gl1Residuals(model, targets, names)(xs, res.residuals.data());
  return res;
}

std::string fitted_toml(const std::string& original_text, const FitResult& fit,
                        const std::string& source) {
  toml::table root = parse_toml_text(original_text, source);
  for (std::size_t i = 0; i < fit.names.size(); ++i) {
    const std::string& name = fit.names[i];
    const double v = fit.estimates[i];
    if (name.rfind("age.", 0) == 0) {
      const auto dot = name.find('.', 4);
      const auto index = static_cast<std::size_t>(std::stoi(name.substr(4, dot - 4)));
      toml::array* ages = root["age"].as_array();
      if (ages == nullptr || index < 1 || index > ages->size()) {
        throw ValueError("cannot write '" + name + "': no such [[age]]");
      }
      (*ages)[index - 1].as_table()->insert_or_assign(name.substr(dot + 1), v);
    } else {
      toml::table* f = root["functional"].as_table();
      if (f == nullptr) throw ValueError("cannot write '" + name + "': no [functional] table");
      f->insert_or_assign(name, v);
    }
  }
  std::ostringstream out;
  out << root << '\n';
  return out.str();
}

}  // namespace fspm::greenlab
