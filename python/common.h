#pragma once
// Shared by the bindings of motostab._core: calls into the libraries without the GIL and without
// printing, NumPy arrays that own C++ buffers, and the conversion of results to Python objects.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <Eigen/Dense>
#include <complex>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "analysis/sweep.h"
#include "analysis/turn_map.h"
#include "io/input_error.h"
#include "scenario/scenario_source.h"

namespace motostab::python {

namespace py = pybind11;

// ---- errors and messages (errors.cpp) ----------------------------------------------------------------

/// Registers the translation of the libraries' exceptions: io::InputError -> motostab.InputError (a
/// ValueError with file, line, column, key and reason), io::ResultError and the computations that
/// could not give a result -> motostab.ResultError. The one place that maps C++ errors to Python.
void registerErrors(py::module_& m);

/// While alive, text the libraries write to std::cerr (e.g. unused .tir coefficients) is kept instead
/// of printed; take() returns it. Calls may overlap (threads): the first swaps std::cerr's buffer,
/// the last puts it back.
class CerrCapture {
 public:
  CerrCapture();
  ~CerrCapture();
  CerrCapture(const CerrCapture&) = delete;
  CerrCapture& operator=(const CerrCapture&) = delete;
  std::string take();
};

/// Sends each line of `text` to the Python logger "motostab" at INFO level (silent unless the user
/// configures logging). Needs the GIL.
void logMessages(const std::string& text);

/// Runs `f` without the GIL and with std::cerr captured (logged afterwards, also when `f` throws).
template <class F>
auto callQuietly(F&& f) -> decltype(f()) {
  CerrCapture capture;
  struct Flush {
    CerrCapture& c;
    ~Flush() { logMessages(c.take()); }
  } flush{capture};
  py::gil_scoped_release release;
  return f();
}

/// The location of a keyword argument `name` of a Python call, for InputError.
io::InputLocation argumentLocation(const std::string& name);

// ---- arrays that own their C++ buffers (no copy) --------------------------------------------------------

/// A 1-D array owning `values` (moved, not copied).
template <class T>
py::array_t<T> makeArray(std::vector<T>&& values) {
  auto* owner = new std::vector<T>(std::move(values));
  py::capsule base(owner, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>({static_cast<py::ssize_t>(owner->size())}, {static_cast<py::ssize_t>(sizeof(T))}, owner->data(),
                        base);
}

/// A 2-D array (rows x cols) owning `values` in row-major order (moved).
template <class T>
py::array_t<T> makeArray2(std::vector<T>&& values, size_t rows, size_t cols) {
  auto* owner = new std::vector<T>(std::move(values));
  py::capsule base(owner, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  const auto s = static_cast<py::ssize_t>(sizeof(T));
  return py::array_t<T>({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(cols)},
                        {static_cast<py::ssize_t>(cols) * s, s}, owner->data(), base);
}

/// A 2-D array viewing an Eigen matrix (column-major, so Fortran order) that it owns (moved).
template <class Scalar>
py::array_t<Scalar> makeArray(Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>&& m) {
  using M = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;
  auto* owner = new M(std::move(m));
  py::capsule base(owner, [](void* p) { delete static_cast<M*>(p); });
  const auto s = static_cast<py::ssize_t>(sizeof(Scalar));
  return py::array_t<Scalar>({static_cast<py::ssize_t>(owner->rows()), static_cast<py::ssize_t>(owner->cols())},
                             {s, s * static_cast<py::ssize_t>(owner->rows())}, owner->data(), base);
}

/// A 1-D array owning an Eigen vector (moved).
template <class Scalar>
py::array_t<Scalar> makeArray(Eigen::Matrix<Scalar, Eigen::Dynamic, 1>&& v) {
  using V = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  auto* owner = new V(std::move(v));
  py::capsule base(owner, [](void* p) { delete static_cast<V*>(p); });
  return py::array_t<Scalar>({static_cast<py::ssize_t>(owner->size())}, {static_cast<py::ssize_t>(sizeof(Scalar))},
                             owner->data(), base);
}

// ---- results as Python objects (convert.cpp): the one place each result struct is mapped ------------------

/// JSON (as the writers of output/ build it for the files) as Python dicts, lists, floats, ints,
/// strings, booleans and None.
py::object toPython(const nlohmann::json& j);

/// A sweep as a dict: speeds (n), eigenvalues (n x roots, complex), branch_labels (roots), roll_rad,
/// state_names, A (n x states x states), summary (summary.json), scenario. Consumes `sweep`.
py::dict convertSweep(analysis::SweepResult&& sweep, const std::string& scenarioName);

/// A speed x roll map: rolls_rad and one converted sweep per roll. Consumes `map`.
py::dict convertTurnMap(analysis::TurnMapResult&& map, const std::string& scenarioName);

/// A linear model: A, B, state_names, input_names, eigenvalues, eigenvectors, labels, speed_mps,
/// roll_rad, heading_frame. Consumes `lin`.
py::dict convertLinearModel(analysis::LinearModel&& lin, std::vector<std::string> labels);

// ---- registration of each group of bindings ----------------------------------------------------------------
void bindScenario(py::module_& m);
void bindAnalysis(py::module_& m);
void bindStudies(py::module_& m);
void bindTyre(py::module_& m);

}  // namespace motostab::python
