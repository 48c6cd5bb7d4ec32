// Bindings of GreenLab plant descriptions and the GL1 calibration (greenlab/calibration.hpp):
// parameters by name, target data, least-squares fits with standard errors.
#include <pybind11/stl.h>

#include "fspm/number_text.hpp"
#include "greenlab/calibration.hpp"
#include "greenlab/plant_params.hpp"
#include "python/bindings.hpp"

namespace fspm::python {

namespace gl = fspm::greenlab;

namespace {

void bind_plant_params(py::module_& m) {
  py::class_<gl::PlantParams>(m, "PlantParams",
                              "A GreenLab plant description (TOML, docs/greenlab.md)")
      .def_readwrite("cycles", &gl::PlantParams::cycles,
                     "Growth cycles to simulate (plant.cycles, integer in [0, 10000])")
      .def_readwrite("seed", &gl::PlantParams::seed,
                     "Seed of the generator of stochastic (GL2) plants (plant.seed)")
      .def_readwrite("calibration_parameters", &gl::PlantParams::calibration_parameters,
                     "Names fitted by fit_gl1 when none are given")
      .def_property_readonly(
          "ages", [](const gl::PlantParams& p) { return p.ages.size(); },
          "Number of physiological ages")
      .def_property_readonly(
          "functional", [](const gl::PlantParams& p) { return p.functional.enabled; },
          "True when the description has a [functional] (GL1) table")
      .def_property_readonly("stochastic", &gl::PlantParams::stochastic,
                             "True when a branching, growth or survival probability is below 1 "
                             "(GL2)")
      .def("validate", &gl::PlantParams::validate,
           "Raises ParameterError when the description is inconsistent (cycles out of [0, "
           "10000], no age, transitions to lower ages ...)")
      .def(
          "get_parameter",
          [](const gl::PlantParams& p, const std::string& name) {
            return gl::get_parameter(p, name);
          },
          py::arg("name"), "A numeric parameter by name ('resistance', 'age.2.leaf_sink', ...)")
      .def(
          "set_parameter",
          [](gl::PlantParams& p, const std::string& name, double value) {
            gl::set_parameter(p, name, value);
          },
          py::arg("name"), py::arg("value"),
          "Sets a numeric parameter by name, as get_parameter names them (ParameterError for an "
          "unknown name)")
      .def("__copy__", [](const gl::PlantParams& p) { return gl::PlantParams(p); })
      .def(
          "__deepcopy__", [](const gl::PlantParams& p, py::dict) { return gl::PlantParams(p); },
          py::arg("memo"))
      .def("__repr__", [](const gl::PlantParams& p) {
        return "<fspm.PlantParams: " + std::to_string(p.ages.size()) + " ages, " +
               std::to_string(p.cycles) + " cycles>";
      });
  m.def(
      "read_plant_params",
      [](const std::string& path) {
        py::gil_scoped_release release;
        return gl::read_plant_params(path);
      },
      py::arg("path"), "A plant description from a TOML file");
  m.def(
      "parse_plant_params",
      [](const std::string& text, const std::string& source) {
        return gl::parse_plant_params(text, source);
      },
      py::arg("text"), py::arg("source") = "", "A plant description from TOML text");
}

void bind_calibration_targets(py::module_& m) {
  py::class_<gl::Target>(m, "Target", "One observation for the calibration")
      .def(py::init([](std::string quantity, int age, int cycle, double value) {
             return gl::Target{std::move(quantity), age, cycle, value, 0};
           }),
           py::arg("quantity"), py::arg("age"), py::arg("cycle"), py::arg("value"),
           "An observation of `quantity` for physiological age `age` in growth cycle `cycle`")
      .def_readwrite("quantity", &gl::Target::quantity,
                     "leaf_mass, internode_mass, leaf_area or production")
      .def_readwrite("age", &gl::Target::age,
                     "Physiological age of the organ (1 .. number of ages) for leaf_mass and "
                     "internode_mass; ignored for leaf_area and production (0 when empty in CSV)")
      .def_readwrite("cycle", &gl::Target::cycle,
                     "Growth cycle: the organ's birth cycle, or the cycle of leaf_area and "
                     "production (1 .. cycles; production from 0)")
      .def_readwrite("value", &gl::Target::value, "The observed value of the quantity")
      .def("__repr__", [](const gl::Target& t) {
        return py::str("Target({!r}, age={}, cycle={}, value={})")
            .format(t.quantity, t.age, t.cycle, t.value)
            .cast<std::string>();
      });
  m.def(
      "read_targets_csv",
      [](const std::string& path) {
        py::gil_scoped_release release;
        return gl::read_targets_csv(path);
      },
      py::arg("path"), "Targets from CSV (header quantity,age,cycle,value)");
  m.def(
      "parse_targets_csv",
      [](const std::string& text, const std::string& source) {
        return gl::parse_targets_csv(text, source);
      },
      py::arg("text"), py::arg("source") = "", "Targets from CSV text");
}

void bind_fit_result(py::module_& m) {
  using FR = gl::FitResult;
  py::class_<FR>(m, "FitResult", "A GL1 calibration: estimates, standard errors, residuals")
      .def_readonly("names", &FR::names, "Names of the fitted parameters, in order")
      .def_property_readonly(
          "initial", [](const FR& r) { return adopt(std::vector(r.initial)); },
          "Starting values of the parameters (from the plant description)")
      .def_property_readonly(
          "estimates", [](const FR& r) { return adopt(std::vector(r.estimates)); },
          "Fitted values of the parameters (bounded below by 1e-9)")
      .def_property_readonly(
          "standard_errors", [](const FR& r) { return adopt(std::vector(r.standard_errors)); },
          "NaN where the covariance is rank deficient")
      .def_property_readonly(
          "residuals", [](const FR& r) { return adopt(std::vector(r.residuals)); },
          "model - target at the estimates")
      .def_readonly("initial_cost", &FR::initial_cost, "1/2 sum of squared residuals")
      .def_readonly("final_cost", &FR::final_cost, "1/2 sum of squared residuals at the estimates")
      .def_readonly("iterations", &FR::iterations, "Levenberg-Marquardt iterations done")
      .def_readonly("converged", &FR::converged, "True when the solver converged")
      .def_readonly("fitted", &FR::fitted, "The plant description with the estimates")
      .def(
          "to_dict",
          [](const FR& r) {
            py::dict d;
            for (std::size_t i = 0; i < r.names.size(); ++i) {
              d[py::str(r.names[i])] = py::make_tuple(r.estimates[i], r.standard_errors[i]);
            }
            return d;
          },
          "name -> (estimate, standard error)")
      .def("__repr__", [](const FR& r) {
        return "<fspm.FitResult: " + std::to_string(r.names.size()) + " parameters, cost " +
               fspm::format_significant(r.final_cost) + " after " + std::to_string(r.iterations) +
               " iterations>";
      });
  m.def(
      "fit_gl1",
      [](const gl::PlantParams& params, const std::vector<gl::Target>& targets,
         const std::vector<std::string>& names, int max_iterations) {
        gl::FitOptions o;
        o.max_iterations = max_iterations;
        py::gil_scoped_release release;
        return gl::fit_gl1(params, targets, names, o);
      },
      py::arg("params"), py::arg("targets"), py::arg("names") = std::vector<std::string>{},
      py::arg("max_iterations") = 200,
      "Fit GL1 parameters (params.calibration_parameters, or `names`) to targets by least "
      "squares (Ceres, Levenberg-Marquardt)");
  m.def(
      "predict_targets",
      [](const gl::PlantParams& params, const std::vector<gl::Target>& targets) {
        std::vector<double> values;
        {
          py::gil_scoped_release release;
          values = gl::predict_targets(params, targets);
        }
        return adopt(std::move(values));
      },
      py::arg("params"), py::arg("targets"), "Model values of the targets");
  m.def("fitted_toml", &gl::fitted_toml, py::arg("original_text"), py::arg("fit"),
        py::arg("source") = "", "The original TOML with the fitted values written in");
}

}  // namespace

void bind_calibration(py::module_& m) {
  bind_plant_params(m);
  bind_calibration_targets(m);
  bind_fit_result(m);
}

}  // namespace fspm::python
