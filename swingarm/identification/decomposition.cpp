#include "swingarm/identification/decomposition.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "io/csv.h"
#include "io/result_error.h"

namespace motostab::swingarm::identification {

using io::formatNumber;

namespace {
constexpr double kDeg = M_PI / 180;
}

BendingTorsionStiffness calcBendingTorsionStiffness(double aTw, double kTw, double beta, double aB, double betaB,
                                                    double aT, double betaT) {
  Eigen::Matrix2d m;
  m << aB, aT, std::sin((betaB - beta) * kDeg), std::sin((betaT - beta) * kDeg);
  const Eigen::Vector2d rhs(aTw * aTw / kTw, 0.0);
  if (std::abs(m.determinant()) < 1e-12 * (std::abs(aB) + std::abs(aT)))
    throw io::ResultError("seed eq. 7 and 10 are singular (modal axes parallel to each other or to the static axis)");
  const Eigen::Vector2d u = m.partialPivLu().solve(rhs);
  if (!(u[0] > 0 && u[1] > 0))
    throw io::ResultError("seed eq. 7 and 10 give a non-positive stiffness: the static axis does not lie "
                                "between the bending and torsion axes");
  return {aB / u[0], aT / u[1]};
}

double calcReducedStiffness(double k, double arm, double aTw) { return aTw * aTw / (arm * arm) * k; }

double calcSeriesStiffness(double kb, double kt) { return 1.0 / (1.0 / kb + 1.0 / kt); }

double calcModalDamping(double k, double zeta, double f) { return k * zeta / (M_PI * f); }

double calcTwistDamping(double cB, double cT, double aB, double kB, double aT, double kT, double aTw, double kTw) {
  const double rb = aB * kTw / (kB * aTw), rt = aT * kTw / (kT * aTw);
  return cB * rb * rb + cT * rt * rt;
}

SwingarmIdentification identifySwingarm(const StaticResult& s, const FrfResult& frf) {
  if (frf.bendingIndex < 0 || frf.torsionIndex < 0 || frf.bendingIndex == frf.torsionIndex)
    throw io::ResultError("the hammer test did not yield distinct bending and torsion modes with axes "
                             "(set processing.bending_mode_hz / torsion_mode_hz, or check the channels)");
  const ModeResult& b = frf.modes[frf.bendingIndex];
  const ModeResult& t = frf.modes[frf.torsionIndex];
  if (!b.hasAxis || !t.hasAxis) throw io::ResultError("bending or torsion mode without a modal axis");
  // x = [k_lat, a_tw, beta, a_b, beta_b, a_t, beta_t, f_b, zeta_b, f_t, zeta_t]
  Eigen::VectorXd x(11), sd(11);
  x << s.kLat, s.aTw, s.betaDeg, b.axis.arm, b.axis.betaDeg, t.axis.arm, t.axis.betaDeg, b.frequencyHz,
      b.dampingRatio, t.frequencyHz, t.dampingRatio;
  sd << s.kLatStderr, s.aTwStderr, s.betaStderrDeg, b.armStderr, b.betaStderrDeg, t.armStderr, t.betaStderrDeg,
      b.frequencyStderrHz, b.dampingStderr, t.frequencyStderrHz, t.dampingStderr;
  auto chain = [](const Eigen::VectorXd& v) {
    const double kTw = v[0] * v[1] * v[1];
    const auto k = calcBendingTorsionStiffness(v[1], kTw, v[2], v[3], v[4], v[5], v[6]);
    const double cB = calcModalDamping(k.kB, v[8], v[7]), cT = calcModalDamping(k.kT, v[10], v[9]);
    Eigen::VectorXd y(8);
    y << k.kB, k.kT, calcReducedStiffness(k.kB, v[3], v[1]), calcReducedStiffness(k.kT, v[5], v[1]), cB, cT,
        calcTwistDamping(cB, cT, v[3], k.kB, v[5], k.kT, v[1], kTw), kTw;
    return y;
  };
  const Eigen::VectorXd y = chain(x);
  const Eigen::MatrixXd cy = propagateCovariance(chain, x, sd.cwiseAbs2().asDiagonal().toDenseMatrix());
  auto est = [&](int i) { return Estimate{y[i], std::sqrt(std::max(cy(i, i), 0.0))}; };
  SwingarmIdentification id;
  auto fillAxis = [](LumpedModel& m, const TwistAxis& a, double armSe, double betaSe) {
    m.arm = {a.arm, armSe};
    m.betaDeg = {a.betaDeg, betaSe};
    m.point = a.point;
    m.direction = a.direction;
  };
  fillAxis(id.bending, b.axis, b.armStderr, b.betaStderrDeg);
  fillAxis(id.torsion, t.axis, t.armStderr, t.betaStderrDeg);
  fillAxis(id.twist, s.axis, s.aTwStderr, s.betaStderrDeg);
  id.bending.stiffness = est(0);
  id.torsion.stiffness = est(1);
  id.bending.reducedStiffness = est(2);
  id.torsion.reducedStiffness = est(3);
  id.bending.damping = est(4);
  id.torsion.damping = est(5);
  id.twist.damping = est(6);
  id.twist.stiffness = {s.kTw, s.kTwStderr};
  id.twist.reducedStiffness = id.twist.stiffness;
  id.bending.frequencyHz = {b.frequencyHz, b.frequencyStderrHz};
  id.bending.dampingRatio = {b.dampingRatio, b.dampingStderr};
  id.torsion.frequencyHz = {t.frequencyHz, t.frequencyStderrHz};
  id.torsion.dampingRatio = {t.dampingRatio, t.dampingStderr};
  id.eq17RelativeResidual = (1 / s.kTw - 1 / y[2] - 1 / y[3]) * s.kTw;
  const double ub = b.axis.arm / y[0], ut = t.axis.arm / y[1], utw = s.aTw / s.kTw;
  const Eigen::Vector2d r = utw * s.axis.direction - ub * b.axis.direction - ut * t.axis.direction;
  id.eq8RelativeResidual = r.norm() / utw;
  return id;
}

std::string formatSwingarmYaml(const SwingarmIdentification& id, const std::string& staticFile,
                               const std::string& frfFile, const PlatePoint& fp) {
  auto num = [](double v) { return formatNumber(v, 10); };
  std::ostringstream y;
  y << "# Swingarm lumped stiffness and damping identified by the twist-axis method (seed: Taraborrelli,\n"
    << "# Favaron, Doria). Made by `motostab identify swingarm`. Schema: docs/swingarm-identification.md.\n"
    << "# Frame: x from the pivot towards the hub, z up, y lateral; the axes lie in the plate plane y = 0.\n"
    << "identification:\n  method: twist-axis\n  static_test: \"" << staticFile << "\"\n  frf_test: \"" << frfFile
    << "\"\n  force_point_m: [" << num(fp.x) << ", 0, " << num(fp.z) << "]\n"
    << "  eq17_relative_residual: " << num(id.eq17RelativeResidual) << "\n"
    << "  eq8_relative_residual: " << num(id.eq8RelativeResidual) << "\n";
  auto model = [&](const char* name, const LumpedModel& m, bool modal, const char* note) {
    y << name << ":  # " << note << "\n  axis:\n"
      << "    arm_m: " << num(m.arm.value) << "\n    arm_m_stderr: " << num(m.arm.stderr_) << "\n"
      << "    beta_deg: " << num(m.betaDeg.value) << "\n    beta_deg_stderr: " << num(m.betaDeg.stderr_) << "\n"
      << "    point_m: [" << num(m.point[0]) << ", 0, " << num(m.point[1]) << "]\n"
      << "    direction: [" << num(m.direction[0]) << ", 0, " << num(m.direction[1]) << "]\n"
      << "  stiffness_Nm_per_rad: " << num(m.stiffness.value) << "\n"
      << "  stiffness_Nm_per_rad_stderr: " << num(m.stiffness.stderr_) << "\n"
      << "  damping_Nms_per_rad: " << num(m.damping.value) << "\n"
      << "  damping_Nms_per_rad_stderr: " << num(m.damping.stderr_) << "\n"
      << "  reduced_stiffness_Nm_per_rad: " << num(m.reducedStiffness.value) << "\n"
      << "  reduced_stiffness_Nm_per_rad_stderr: " << num(m.reducedStiffness.stderr_) << "\n";
    if (modal)
      y << "  frequency_hz: " << num(m.frequencyHz.value) << "\n  frequency_hz_stderr: " << num(m.frequencyHz.stderr_)
        << "\n  damping_ratio: " << num(m.dampingRatio.value) << "\n  damping_ratio_stderr: "
        << num(m.dampingRatio.stderr_) << "\n";
  };
  model("bending", id.bending, true, "rotation about the bending-mode axis (seed eq. 7, 10, 14, 20)");
  model("torsion", id.torsion, true, "rotation about the torsion-mode axis (seed eq. 7, 10, 15, 20)");
  model("twist", id.twist, false, "rotation about the static twist axis (seed eq. 1-4, 25)");
  return y.str();
}

}  // namespace motostab::swingarm::identification
