// Results of the analysis chain as Python objects: the one place where the result structs of
// analysis/ are mapped (motostab/_results.py turns these dicts into typed objects).
#include <pybind11/complex.h>

#include "output/sweep_output.h"
#include "python/common.h"

namespace motostab::python {

using analysis::LinearModel;
using analysis::ModeBranch;
using analysis::SweepResult;
using analysis::TurnMapResult;

py::object toPython(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::null:
      return py::none();
    case nlohmann::json::value_t::boolean:
      return py::bool_(j.get<bool>());
    case nlohmann::json::value_t::number_integer:
      return py::int_(j.get<int64_t>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(j.get<uint64_t>());
    case nlohmann::json::value_t::number_float:
      return py::float_(j.get<double>());
    case nlohmann::json::value_t::string:
      return py::str(j.get_ref<const std::string&>());
    case nlohmann::json::value_t::array: {
      py::list out;
      for (const auto& v : j) out.append(toPython(v));
      return std::move(out);
    }
    case nlohmann::json::value_t::object: {
      py::dict out;
      for (const auto& [key, v] : j.items()) out[py::str(key)] = toPython(v);
      return std::move(out);
    }
    default:
      return py::none();
  }
}

namespace {

// A (speeds x states x states), C order.
py::array_t<double> stackStateMatrices(const std::vector<LinearModel>& models) {
  const size_t n = models.size(), s = models.empty() ? 0 : static_cast<size_t>(models.front().A.rows());
  std::vector<double> values(n * s * s);
  for (size_t k = 0; k < n; ++k)
    for (size_t i = 0; i < s; ++i)
      for (size_t j = 0; j < s; ++j) values[(k * s + i) * s + j] = models[k].A(i, j);
  auto* owner = new std::vector<double>(std::move(values));
  py::capsule base(owner, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  const auto d = static_cast<py::ssize_t>(sizeof(double)), ss = static_cast<py::ssize_t>(s);
  return py::array_t<double>({static_cast<py::ssize_t>(n), ss, ss}, {ss * ss * d, ss * d, d}, owner->data(), base);
}

}  // namespace

py::dict convertSweep(SweepResult&& sweep, const std::string& scenarioName) {
  py::dict out;
  out["summary"] = toPython(output::makeSweepSummary(scenarioName, sweep));
  const size_t n = sweep.speeds.size(), roots = sweep.branches.size();
  std::vector<std::complex<double>> eigenvalues(n * roots);
  py::list branchLabels, labels;  // Python keeps the labels' names (analysis/mode_label.h)
  for (size_t b = 0; b < roots; ++b) {
    const ModeBranch& branch = sweep.branches[b];
    for (size_t k = 0; k < n; ++k) eigenvalues[k * roots + b] = branch.eigenvalue[k];
    branchLabels.append(analysis::toString(branch.label));
  }
  for (size_t k = 0; k < n; ++k) {  // each root's label at each speed, as eigenvalues.csv has them
    py::list row;
    for (size_t b = 0; b < roots; ++b) row.append(analysis::toString(sweep.branches[b].labels[k]));
    labels.append(row);
  }
  py::list states;
  if (!sweep.models.empty())
    for (const auto& s : sweep.models.front().states) states.append(s.name);
  out["eigenvalues"] = makeArray2(std::move(eigenvalues), n, roots);
  out["branch_labels"] = branchLabels;
  out["labels"] = labels;
  out["state_names"] = states;
  out["A"] = stackStateMatrices(sweep.models);
  out["roll_rad"] = sweep.trims.empty() ? NAN : sweep.trims.front().roll;
  out["speeds"] = makeArray(std::move(sweep.speeds));
  out["scenario"] = scenarioName;
  return out;
}

py::dict convertTurnMap(TurnMapResult&& map, const std::string& scenarioName) {
  py::dict out;
  py::list sweeps;
  for (auto& s : map.sweeps) sweeps.append(convertSweep(std::move(s), scenarioName));
  out["sweeps"] = sweeps;
  out["rolls_rad"] = makeArray(std::move(map.rolls));
  out["scenario"] = scenarioName;
  return out;
}

py::dict convertLinearModel(LinearModel&& lin, std::vector<std::string> labels) {
  py::dict out;
  py::list states;
  for (const auto& s : lin.states) states.append(s.name);
  out["state_names"] = states;
  out["input_names"] = lin.inputNames;
  out["labels"] = labels;
  out["speed_mps"] = lin.speed;
  out["roll_rad"] = lin.roll;
  out["heading_frame"] = lin.headingFrame;
  out["A"] = makeArray(std::move(lin.A));
  out["B"] = makeArray(std::move(lin.B));
  out["eigenvalues"] = makeArray(std::move(lin.eigenvalues));
  out["eigenvectors"] = makeArray(std::move(lin.eigenvectors));
  return out;
}

}  // namespace motostab::python
