#pragma once
// The free response of a linear model fitted to one measured run (output-error fit).
//
// Constant speed: x' = A x at the run's speed, y_j(t) = g_j c_j x(t) + o_j, x(t) = exp(A (t - t0)) x0
// (t0: the window's first sample). A run whose speed varies over the window (a speed trace: the
// vehicle slowing down) is predicted with the speed varying: piecewise-frozen linear models along
// the trace, x(t_i) = exp(A(v_i') (t_i - t_{i-1})) x(t_{i-1}) with v_i' the trace's speed at the
// interval's middle and A(v) interpolated quadratically (Lagrange) from linear models at the lowest,
// middle and highest speed of the window (exact where A is quadratic in speed, as for the Whipple
// bicycle, Meijaard et al. 2007 eq. 1). The frozen-coefficient approximation neglects the trim's own
// change with speed, of the order of the deceleration times the trim's sensitivity to speed.
//
// The initial state x0 and the offsets o_j enter linearly; the free gains g_j (scale: free) make the
// fit bilinear, solved by alternating least squares (a nested fit: x0 and offsets by minimum-norm
// least squares for fixed gains, then each free gain with its offset), to a relative change of the
// weighted residual below 1e-13. With no calibrated signal the first free gain is 1 (the overall
// scale is in x0). Calibrated: g_j = 1/scale.
#include <Eigen/Dense>
#include <vector>

#include "analysis/linearize.h"
#include "diagnosis/measured_data.h"
#include "diagnosis/noise_model.h"

namespace motostab::diagnosis {

/// The fitted free response of one run.
struct ResponseFit {
  std::vector<std::vector<double>> predicted;  ///< per signal, per sample (column unit)
  Eigen::VectorXd initialState;                ///< x0 in the linear model's states
  std::vector<double> gains, offsets;          ///< per signal (column unit per rad(/s); column unit)
  std::vector<double> vaf;                     ///< per signal, % (100 (1 - var(residual)/var(signal)))
  int numLinear = 0;                           ///< fitted linear/bilinear parameters (x0, offsets, free gains)
};

/// Fits one run's free response for a linear model (A at the run's speed). `sigma` per signal
/// (column unit, the noise's marginal sigma) weights the signals; `noise` per signal (optional): its
/// AR noise, which prewhitens the fit (generalised least squares, noise_model.h). Throws InputError
/// (at the run) if a signal's quantity is not a state of the model.
ResponseFit fitFreeResponse(const analysis::LinearModel& lin, const ResponseRun& run, const std::vector<double>& sigma,
                            const std::vector<ArNoise>& noise = {});

/// The same for a run with a speed trace (run.speeds): `models` are linear models (same states) at
/// getTraceSpeeds(run), A interpolated between them along the trace (piecewise-frozen, see above).
ResponseFit fitFreeResponse(const std::vector<analysis::LinearModel>& models, const ResponseRun& run,
                            const std::vector<double>& sigma, const std::vector<ArNoise>& noise = {});

/// The speeds (m/s, sorted) whose linear models predict `run`: its speed without a trace (or with a
/// trace of constant speed), else the lowest, middle and highest speed of the trace in the window.
std::vector<double> getTraceSpeeds(const ResponseRun& run);

}  // namespace motostab::diagnosis
