#pragma once
// Shared helpers of the Python bindings: read-only numpy views of C++ columns, numpy arrays that
// take over a C++ vector without copying, (N, 3) point arrays as spans of Eigen vectors, lists of
// dicts, and the keyword-argument constructors of the parameter structs. Each bind_*() adds one
// family of functions to the module.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "fspm/error.hpp"

namespace fspm::python {

namespace py = pybind11;

template <typename T>
struct ColumnScalar {
  using type = T;
};
template <typename S, int R>
struct ColumnScalar<Eigen::Matrix<S, R, 1>> {
  using type = S;
};
template <typename S, std::size_t N>
struct ColumnScalar<std::array<S, N>> {
  using type = S;
};

// A read-only 1-D (width 1) or N x width numpy view of a column owned by `owner`. Rows are whole
// elements: one double, or one packed Eigen vector / std::array of `width` scalars.
template <typename T>
py::array column(const std::span<const T> values, py::handle owner, std::size_t width = 1) {
  using Scalar = typename ColumnScalar<T>::type;
  static_assert(sizeof(T) % sizeof(Scalar) == 0);
  std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(values.size())};
  std::vector<py::ssize_t> strides{static_cast<py::ssize_t>(sizeof(T))};
  if (width > 1) {
    shape.push_back(static_cast<py::ssize_t>(width));
    strides.push_back(sizeof(Scalar));
  }
  py::array a(py::dtype::of<Scalar>(), shape, strides,
              reinterpret_cast<const Scalar*>(values.data()), owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

// Parent ids as a read-only signed view: the root's parent (kNoNode, all ones) reads -1.
inline py::array parent_column(std::span<const std::uint32_t> parents, py::handle owner) {
  return column(std::span<const std::int32_t>(reinterpret_cast<const std::int32_t*>(parents.data()),
                                              parents.size()),
                owner);
}

// A 1-D numpy array that takes ownership of `values` (no copy of the elements).
template <typename T>
py::array_t<T> adopt(std::vector<T>&& values) {
  auto* owned = new std::vector<T>(std::move(values));
  py::capsule free_when_done(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>({static_cast<py::ssize_t>(owned->size())}, {sizeof(T)}, owned->data(),
                        free_when_done);
}

// An (N, 3) copy of a list of 3-vectors (float or double), e.g. mesh vertices or scan points.
template <typename S>
py::array_t<S> vector_rows(const std::vector<Eigen::Matrix<S, 3, 1>>& v) {
  py::array_t<S> out({static_cast<py::ssize_t>(v.size()), py::ssize_t{3}});
  auto a = out.template mutable_unchecked<2>();
  for (std::size_t i = 0; i < v.size(); ++i) {
    for (int k = 0; k < 3; ++k) a(static_cast<py::ssize_t>(i), k) = v[i][k];
  }
  return out;
}

// A list of one dict per element of `items`, each filled by `fill(dict, element)`.
template <typename Range, typename Fill>
py::list dict_list(const Range& items, Fill fill) {
  py::list out;
  for (const auto& item : items) {
    py::dict d;
    fill(d, item);
    out.append(d);
  }
  return out;
}

// A C-contiguous float64 array of shape (N, 3) (or one point of shape (3,)) seen as N Eigen
// vectors; the array must outlive the span. Throws ValueError naming `what` for another shape.
using PointArray = py::array_t<double, py::array::c_style | py::array::forcecast>;
std::span<const Eigen::Vector3d> as_points(const PointArray& points, const char* what);

// A 1-D float64 sample (lists and integer arrays are converted).
using Sample = py::array_t<double, py::array::c_style | py::array::forcecast>;
std::span<const double> as_sample(const Sample& values, const char* what);

// Field names of a bound parameter struct, kept on the class as `_fields` so the keyword
// constructor, to_dict() and __repr__ know them.
template <typename C>
class Fields {
 public:
  explicit Fields(py::class_<C>& cls) : cls_(cls) {}
  template <typename T>
  Fields& add(const char* name, T C::*member, const char* doc = "") {
    cls_.def_readwrite(name, member, doc);
    names_.append(name);
    return *this;
  }
  // Records a property bound separately (e.g. an enum shown as a name).
  Fields& existing(const char* name) {
    names_.append(name);
    return *this;
  }
  // Adds to_dict(), __repr__ and the keyword constructor C(**values). `base`, when given, makes
  // the starting value from (and removes) keys that are not fields, e.g. a preset name.
  void finish(C (*base)(py::dict& values) = nullptr);

 private:
  py::class_<C>& cls_;
  py::list names_;
};

// Sets `values` (a dict of field name -> value) on `target` through the bound properties. Throws
// TypeError naming the known fields for an unknown name.
void set_fields(py::handle target, const py::dict& values);
py::dict fields_dict(py::handle target);
std::string fields_repr(py::handle target);

template <typename C>
void Fields<C>::finish(C (*base)(py::dict& values)) {
  cls_.attr("_fields") = py::tuple(names_);
  cls_.def(py::init([base](const py::kwargs& kwargs) {
             py::dict values(kwargs);
             C value = base != nullptr ? base(values) : C{};
             set_fields(py::cast(&value, py::return_value_policy::reference), values);
             return value;
           }),
           "Defaults, with any field given as a keyword argument")
      .def(
          "to_dict", [](py::handle self) { return fields_dict(self); },
          "The fields as a dict (field name -> value), as the keyword constructor takes them")
      .def("__repr__", [](py::handle self) { return fields_repr(self); })
      .def("__copy__", [](const C& self) { return C(self); })
      .def(
          "__deepcopy__", [](const C& self, py::dict) { return C(self); }, py::arg("memo"));
}

void bind_errors(py::module_& m);
void bind_tree(py::module_& m);
void bind_mtg(py::module_& m);
void bind_distance(py::module_& m);
void bind_greenlab(py::module_& m);
void bind_experiments(py::module_& m);
void bind_lsystem(py::module_& m);
void bind_environment(py::module_& m);
void bind_statistics(py::module_& m);
void bind_graphics(py::module_& m);
void bind_calibration(py::module_& m);
void bind_stages(py::module_& m);
void bind_scans(py::module_& m);
void bind_io(py::module_& m);
// Adds reconstruct_crown when fspm was built with OpenImageIO (the crown module).
void bind_crown(py::module_& m);

}  // namespace fspm::python
