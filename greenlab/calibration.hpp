#pragma once
// Calibration of GL1 ("model inversion", Yan et al. 2004): hidden parameters (sink strengths,
// beta-law shapes, resistance, seed biomass ...) fitted by least squares to target data with
// Ceres (Levenberg-Marquardt); standard errors from the covariance (J^T J)^-1 scaled by the
// residual variance.
#include <string>
#include <vector>

#include "greenlab/plant_params.hpp"

namespace fspm::greenlab {

// One observation. quantity: "leaf_mass" or "internode_mass" (one organ of physiological age
// `age` born in `cycle`, at the end of the simulation), "leaf_area" (green leaf area of the plant
// after `cycle`) or "production" (Q(cycle)); `age` is ignored for the last two.
struct Target {
  std::string quantity;
  int age = 0;
  int cycle = 0;
  double value = 0.0;
  int line = 0;  // in the CSV file
};

// CSV with the header `quantity,age,cycle,value`. Throws ParseError naming line and column.
std::vector<Target> parse_targets_csv(const std::string& text, const std::string& source = {});
std::vector<Target> read_targets_csv(const std::string& path);

struct FitOptions {
  int max_iterations = 200;

  // Throws ValueError naming the field out of range.
  void validate() const;
};

struct FitResult {
  std::vector<std::string> names;
  std::vector<double> initial;
  std::vector<double> estimates;
  std::vector<double> standard_errors;  // NaN when the covariance is rank deficient
  std::vector<double> residuals;        // model - target at the estimates
  double initial_cost = 0.0;            // 1/2 sum of squared residuals
  double final_cost = 0.0;
  int iterations = 0;
  bool converged = false;
  PlantParams fitted;
};

// Fits params.calibration_parameters (or `names` when given). Throws ValueError when the plant
// has no [functional] table, a target is outside the simulated cycles or ages, or the solver
// does not converge (the message gives the final cost).
FitResult fit_gl1(const PlantParams& params, const std::vector<Target>& targets,
                  const std::vector<std::string>& names = {}, const FitOptions& options = {});

// Model values for the targets (what the residuals compare).
std::vector<double> predict_targets(const PlantParams& params, const std::vector<Target>& targets);

// The original TOML text with the fitted values written in (comments are not kept).
std::string fitted_toml(const std::string& original_text, const FitResult& fit,
                        const std::string& source = {});

}  // namespace fspm::greenlab
