// tyre: the steady-state forces of a Magic Formula .tir file over slip angle (`motostab tyre`),
// without its files.
#include <cmath>
#include <iostream>
#include <optional>

#include "apps/option_checks.h"
#include "python/common.h"

namespace motostab::python {

namespace {

// slipDeg: the angles (deg) themselves, or (A, B, STEP) as the command line's --slip-deg A:B:STEP.
py::dict tyreCurve(const std::string& path, double fz, const std::vector<double>& slipDeg, bool slipIsRange,
                   double camberDeg, double slipRatio, std::optional<double> speed) {
  cli::checkNumber(fz, cli::kTyreLoadN, argumentLocation("fz"));
  cli::checkNumber(camberDeg, cli::kCamberDeg, argumentLocation("camber_deg"));
  cli::checkNumber(slipRatio, cli::kSlipRatio, argumentLocation("slip_ratio"));
  if (speed) cli::checkNumber(*speed, cli::kSpeedMps, argumentLocation("speed"));
  std::vector<double> slips = slipDeg;
  if (slipIsRange) {
    if (slipDeg.size() != 3) throw io::InputError(argumentLocation("slip_deg"), "expected (A, B, STEP) in degrees");
    slips = cli::makeSlipAngles(slipDeg[0], slipDeg[1], slipDeg[2], argumentLocation("slip_deg"));
  }
  for (double v : slips)
    if (!std::isfinite(v)) throw io::InputError(argumentLocation("slip_deg"), "slip angles must be finite");
  struct Out {
    std::vector<output::TyreCurvePoint> points;
    int fitType;
    double cornering, camber, longitudinal, relaxation, longitudinalRelaxation, speed;
  };
  Out out = callQuietly([&] {
    const cli::TirForceLaw tir = cli::loadTirForCurve(path, std::cerr);
    const double v = speed ? *speed : tir.file.getNumber("LONGVL");
    const double camber = camberDeg * M_PI / 180;
    const auto& law = *tir.law;
    return Out{cli::calcTyreCurve(law, fz, slips, camber, slipRatio, v), tir.file.getFitType(),
               law.calcCorneringStiffness(fz), law.calcCamberStiffness(fz), law.calcLongitudinalStiffness(fz),
               law.calcRelaxationLength(fz, camber, v), law.calcLongitudinalRelaxationLength(fz), v};
  });
  const size_t n = out.points.size();
  std::vector<double> alpha(n), gamma(n), kappa(n), load(n), fx(n), fy(n), mz(n), mx(n), my(n);
  for (size_t k = 0; k < n; ++k) {
    const auto& p = out.points[k];
    load[k] = p.slip.Fz, alpha[k] = p.slip.alpha, gamma[k] = p.slip.gamma, kappa[k] = p.slip.kappa;
    fx[k] = p.forces.Fx, fy[k] = p.forces.Fy, mz[k] = p.forces.Mz, mx[k] = p.forces.Mx, my[k] = p.forces.My;
  }
  py::dict d;
  d["fz_N"] = makeArray(std::move(load));
  d["slip_angle_rad"] = makeArray(std::move(alpha));
  d["camber_rad"] = makeArray(std::move(gamma));
  d["slip_ratio"] = makeArray(std::move(kappa));
  d["fx_N"] = makeArray(std::move(fx));
  d["fy_N"] = makeArray(std::move(fy));
  d["mz_Nm"] = makeArray(std::move(mz));
  d["mx_Nm"] = makeArray(std::move(mx));
  d["my_Nm"] = makeArray(std::move(my));
  d["fit_type"] = out.fitType;
  d["speed_mps"] = out.speed;
  d["cornering_stiffness_N_per_rad"] = out.cornering;
  d["camber_stiffness_N_per_rad"] = out.camber;
  d["slip_stiffness_N"] = out.longitudinal;
  d["relaxation_length_m"] = out.relaxation;
  d["longitudinal_relaxation_length_m"] = out.longitudinalRelaxation;
  return d;
}

}  // namespace

void bindTyre(py::module_& m) {
  m.def("tyre_curve", &tyreCurve, py::arg("path"), py::arg("fz"), py::arg("slip_deg"), py::arg("slip_is_range"),
        py::arg("camber_deg"), py::arg("slip_ratio"), py::arg("speed"));
}

}  // namespace motostab::python
