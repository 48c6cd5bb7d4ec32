// Bindings of fspm/statistics.hpp: mean, standard deviation, confidence intervals, Student, Welch
// and paired t-tests, the Mann-Whitney U test and Cohen's d (conventions of R's t.test and
// wilcox.test, so scipy.stats gives the same numbers).
#include <pybind11/stl.h>

#include "fspm/number_text.hpp"
#include "fspm/statistics.hpp"
#include "python/bindings.hpp"

namespace fspm::python {
namespace {

using TTestFn = TTestResult (*)(std::span<const double>, std::span<const double>, Alternative,
                                double);

void def_t_test(py::module_& m, const char* name, TTestFn fn, const char* doc) {
  m.def(
      name,
      [fn](const Sample& a, const Sample& b, const std::string& alternative, double level) {
        const auto sa = as_sample(a, "a");
        const auto sb = as_sample(b, "b");
        const Alternative alt = alternative_from_name(alternative);
        py::gil_scoped_release release;
        return fn(sa, sb, alt, level);
      },
      py::arg("a"), py::arg("b"), py::arg("alternative") = "two-sided", py::arg("level") = 0.95,
      doc);
}

py::tuple interval(const Interval& i) { return py::make_tuple(i.low, i.high); }

void bind_test_results(py::module_& m) {
  py::class_<TTestResult>(m, "TTestResult", "A t-test: statistic, degrees of freedom, p-value")
      .def_readonly("t", &TTestResult::t, "t statistic")
      .def_readonly("df", &TTestResult::df, "Degrees of freedom")
      .def_readonly("p", &TTestResult::p, "p-value of the chosen alternative, in [0, 1]")
      .def_readonly("mean_a", &TTestResult::mean_a, "Mean of sample a")
      .def_readonly("mean_b", &TTestResult::mean_b, "Mean of sample b")
      .def_readonly("sd_a", &TTestResult::sd_a, "Standard deviation of sample a (divisor n - 1)")
      .def_readonly("sd_b", &TTestResult::sd_b, "Standard deviation of sample b (divisor n - 1)")
      .def_readonly("n_a", &TTestResult::n_a, "Size of sample a")
      .def_readonly("n_b", &TTestResult::n_b, "Size of sample b")
      .def_readonly("estimate", &TTestResult::estimate, "mean_a - mean_b (paired: mean difference)")
      .def_property_readonly(
          "confidence_interval",
          [](const TTestResult& r) { return interval(r.confidence_interval); },
          "(low, high) of the estimate; one-sided tests have an infinite end")
      .def(
          "to_dict",
          [](const TTestResult& r) {
            py::dict d;
            d["t"] = r.t;
            d["df"] = r.df;
            d["p"] = r.p;
            d["mean_a"] = r.mean_a;
            d["mean_b"] = r.mean_b;
            d["sd_a"] = r.sd_a;
            d["sd_b"] = r.sd_b;
            d["n_a"] = r.n_a;
            d["n_b"] = r.n_b;
            d["estimate"] = r.estimate;
            d["confidence_interval"] = interval(r.confidence_interval);
            return d;
          },
          "Every field as a dict (confidence_interval as (low, high))")
      .def("__repr__", [](const TTestResult& r) {
        return "TTestResult(t=" + format_significant(r.t) + ", df=" + format_significant(r.df) +
               ", p=" + format_significant(r.p) + ", estimate=" + format_significant(r.estimate) +
               ")";
      });

  py::class_<MannWhitneyResult>(m, "MannWhitneyResult", "A Mann-Whitney U test")
      .def_readonly("u", &MannWhitneyResult::u, "U of sample a (R's W)")
      .def_readonly("p", &MannWhitneyResult::p, "p-value of the chosen alternative, in [0, 1]")
      .def_readonly("exact", &MannWhitneyResult::exact, "Exact null distribution or normal")
      .def(
          "to_dict",
          [](const MannWhitneyResult& r) {
            py::dict d;
            d["u"] = r.u;
            d["p"] = r.p;
            d["exact"] = r.exact;
            return d;
          },
          "u, p and exact as a dict")
      .def("__repr__", [](const MannWhitneyResult& r) {
        return "MannWhitneyResult(u=" + format_significant(r.u) + ", p=" + format_significant(r.p) +
               ", exact=" + (r.exact ? "True" : "False") + ")";
      });
}

void bind_statistics_functions(py::module_& m) {
  m.def(
      "mean", [](const Sample& v) { return mean(as_sample(v, "values")); }, py::arg("values"),
      "Arithmetic mean");
  m.def(
      "variance", [](const Sample& v) { return variance(as_sample(v, "values")); },
      py::arg("values"), "Sample variance (divisor n - 1)");
  m.def(
      "standard_deviation",
      [](const Sample& v) { return standard_deviation(as_sample(v, "values")); }, py::arg("values"),
      "Sample standard deviation (divisor n - 1)");
  m.def(
      "mean_confidence_interval",
      [](const Sample& v, double level) {
        return interval(mean_confidence_interval(as_sample(v, "values"), level));
      },
      py::arg("values"), py::arg("level") = 0.95,
      "Two-sided Student-t confidence interval of the mean: (low, high)");
  def_t_test(m, "student_t_test", &student_t_test,
             "Two-sample t-test with equal variances (df = n_a + n_b - 2)");
  def_t_test(m, "welch_t_test", &welch_t_test,
             "Welch's t-test (Welch-Satterthwaite degrees of freedom)");
  def_t_test(m, "paired_t_test", &paired_t_test, "Paired t-test on the differences a_i - b_i");
  m.def(
      "mann_whitney_u_test",
      [](const Sample& a, const Sample& b, const std::string& alternative, bool correction) {
        const auto sa = as_sample(a, "a");
        const auto sb = as_sample(b, "b");
        const Alternative alt = alternative_from_name(alternative);
        py::gil_scoped_release release;
        return mann_whitney_u_test(sa, sb, alt, correction);
      },
      py::arg("a"), py::arg("b"), py::arg("alternative") = "two-sided",
      py::arg("continuity_correction") = true,
      "Mann-Whitney U (Wilcoxon rank-sum) test, exact without ties and below 50 values");
  m.def(
      "cohens_d",
      [](const Sample& a, const Sample& b) {
        return cohens_d(as_sample(a, "a"), as_sample(b, "b"));
      },
      py::arg("a"), py::arg("b"), "(mean_a - mean_b) / pooled standard deviation");
}

}  // namespace

void bind_statistics(py::module_& m) {
  bind_test_results(m);
  bind_statistics_functions(m);
}

}  // namespace fspm::python
