#pragma once
// The steer-rate amplitude Omega (rad/s) of the measured oscillations, at which the steer_friction
// candidate's equivalent viscous damping c_eq = 4 T_f / (pi Omega) is taken (physical_candidates.h
// eq. 1). Sources, first that applies:
// (a) the measured-data file's `steer_rate_amplitude_rad_s` (docs/measured-data-format.md);
// (b) response runs with a calibrated steer_rate signal: its amplitude in the fit window,
//       Omega = sqrt(2) RMS(y - mean y)                                                   (eq. 1)
//     (the amplitude of the sinusoid with the window's mean power; for a decaying or growing oscillation
//     an amplitude averaged over the window, not its peak); else runs with a calibrated steer_angle
//     signal: its amplitude by eq. 1 times |lambda| of the nominal model's weave at the run's speed
//     (for delta = A e^(sigma t) cos(w t + phi), |delta'| peaks at A |lambda|);
// (c) else runs with a calibrated roll_rate signal: its amplitude by eq. 1 times the nominal weave's
//     mode-shape ratio |steer rate| / |roll rate| (the weave eigenvector at the run's speed).
// Several runs of the chosen kind: the mean of their amplitudes. Uncalibrated signals (scale: free)
// carry no amplitude in rad/s and are not used.
#include "diagnosis/candidates.h"
#include "diagnosis/measured_data.h"
#include "diagnosis/prediction.h"

namespace motostab::diagnosis {

/// Omega from `data` by (a)-(c) above, the weave from `nominal`'s reference sweep (the speed nearest the
/// run's); value 0 and the reason in `source` when no source applies.
SteerRateAmplitude findSteerRateAmplitude(const MeasuredData& data, const Predictor& nominal);

/// sqrt(2) times the RMS of `values` about their mean (eq. 1), in their unit.
double calcSinusoidAmplitude(const std::vector<double>& values);

}  // namespace motostab::diagnosis
