// Helpers shared by the binding files (see bindings.hpp).
#include "python/bindings.hpp"

#include <string>

namespace fspm::python {

namespace {

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) {
    if (i > 0) s += ", ";
    s += std::to_string(a.shape(i));
  }
  return s + (a.ndim() == 1 ? ",)" : ")");
}

}  // namespace

std::span<const Eigen::Vector3d> as_points(const PointArray& points, const char* what) {
  const bool one = points.ndim() == 1 && points.shape(0) == 3;
  if (!one && (points.ndim() != 2 || points.shape(1) != 3)) {
    throw ValueError(std::string(what) + ": expected an array of shape (N, 3), got shape " +
                     shape_text(points));
  }
  // c_style guarantees rows of three packed doubles, the layout of Eigen::Vector3d.
  static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double));
  const std::size_t n = one ? 1 : static_cast<std::size_t>(points.shape(0));
  return {reinterpret_cast<const Eigen::Vector3d*>(points.data()), n};
}

std::span<const double> as_sample(const Sample& values, const char* what) {
  if (values.ndim() != 1) {
    throw ValueError(std::string(what) + ": expected a one-dimensional sample, got shape " +
                     shape_text(values));
  }
  return {values.data(), static_cast<std::size_t>(values.shape(0))};
}

void set_fields(py::handle target, const py::dict& values) {
  const py::tuple fields = target.attr("_fields");
  for (const auto& [key, value] : values) {
    if (!fields.contains(key)) {
      std::string known;
      for (const auto& f : fields) known += (known.empty() ? "" : ", ") + f.cast<std::string>();
      throw py::type_error(py::str("{}: unknown parameter '{}' (expected one of: {})")
                               .format(py::type::of(target).attr("__name__"), key, known)
                               .cast<std::string>());
    }
    py::setattr(target, key, value);
  }
}

py::dict fields_dict(py::handle target) {
  py::dict d;
  for (const auto& f : py::tuple(target.attr("_fields"))) {
    py::object v = target.attr(f);
    // Eigen vectors come out as numpy views of the struct: hand out plain lists instead.
    if (py::isinstance<py::array>(v)) v = v.attr("tolist")();
    d[f] = v;
  }
  return d;
}

std::string fields_repr(py::handle target) {
  std::string s = py::type::of(target).attr("__name__").cast<std::string>() + "(";
  bool first = true;
  for (const auto& [key, value] : fields_dict(target)) {
    if (!first) s += ", ";
    first = false;
    s += key.cast<std::string>() + "=" + py::repr(value).cast<std::string>();
  }
  return s + ")";
}

}  // namespace fspm::python
