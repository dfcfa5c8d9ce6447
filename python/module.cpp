// motostab._core: the extension behind the Python package motostab (python/motostab/__init__.py is
// the API users call; docs/python.md).
#include <cmath>

#include "diagnosis/diagnosis.h"
#include "python/common.h"
#include "simulation/simulation.h"
#include "studies/study.h"
#include "uncertainty/uncertainty_study.h"

namespace motostab::python {
namespace {

// The libraries' defaults of the options the Python functions take, so that their signatures show
// the same values as the command line's.
py::dict getDefaults() {
  const simulation::SimulationOptions sim;
  const studies::StudyOptions study;
  const diagnosis::DiagnosisOptions diag;
  const uncertainty::UncertaintyOptions unc;
  py::dict d;
  d["simulate"] = py::dict(py::arg("output_step") = sim.outputStep, py::arg("accuracy") = sim.accuracy,
                           py::arg("fall_limit_deg") = std::round(sim.fallRollLimit * 180 / M_PI * 1e9) / 1e9);  // 60, not 60.000000000000007
  d["study"] = py::dict(py::arg("compare") = py::tuple(py::cast(study.variants)), py::arg("stiffness_scale") = study.stiffnessScale,
                        py::arg("shape_speeds") = py::tuple(py::cast(study.shapeSpeeds)), py::arg("threads") = study.threads);
  d["diagnose"] = py::dict(py::arg("max_causes") = diag.maxCauses);
  d["uncertainty"] = py::dict(py::arg("samples") = unc.samples, py::arg("seed") = unc.seed);
  return d;
}

}  // namespace
}  // namespace motostab::python

PYBIND11_MODULE(_core, m) {
  m.doc() = "motostab's libraries for Python: the calls behind the motostab package (use motostab, not this)";
  motostab::python::registerErrors(m);
  motostab::python::bindScenario(m);
  motostab::python::bindAnalysis(m);
  motostab::python::bindStudies(m);
  motostab::python::bindTyre(m);
  m.def("defaults", &motostab::python::getDefaults);
}
