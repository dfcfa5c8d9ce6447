#pragma once
// Least-squares complex frequency-domain (LSCF, "PolyMAX"-type, common denominator) modal parameter
// estimation with a stabilisation diagram, automatic selection of stable poles and an LSFD modal model.
#include <complex>
#include <vector>

#include <Eigen/Dense>

#include "modal/spectra.h"

namespace motostab::modal {

/// Undamped natural frequency |lambda|/(2 pi), Hz, of a continuous-time pole lambda (1/s).
double calcNaturalFrequencyHz(std::complex<double> lambda);
/// Viscous damping ratio -Re(lambda)/|lambda| of a pole.
double calcDampingRatio(std::complex<double> lambda);

/// Settings for LSCF, stabilisation and pole selection.
struct LscfOptions {
  double fMin = 0, fMax = 0;       ///< Hz, analysis band (fMax > fMin >= 0)
  int minOrder = 4, maxOrder = 40;  ///< denominator polynomial orders swept in the stabilisation diagram
  double windowDecayRate = 0;       ///< 1/s added by an exponential window; removed from every pole
  double maxDampingRatio = 0.2;     ///< poles more damped than this are discarded as computational
  double frequencyTolerance = 0.01; ///< relative change to the previous order for "stable frequency"
  double dampingTolerance = 0.05;   ///< relative change for "stable damping"
  double clusterTolerance = 0.002;  ///< relative frequency width of a cluster of stable poles
  double minStableFraction = 0.3;   ///< a mode needs stable poles at this fraction of the orders
};

/// One pole of the stabilisation diagram (window decay removed).
struct StabilisationPole {
  int order = 0;
  double frequencyHz = 0, dampingRatio = 0;
  bool stableFrequency = false, stableDamping = false;
  std::complex<double> rawLambda;  ///< pole of the windowed FRF, 1/s
};

/// A mode selected from the stabilisation diagram.
struct ModalEstimate {
  double frequencyHz = 0, dampingRatio = 0;  ///< medians over the stable cluster
  double frequencyScatterHz = 0, dampingScatter = 0;  ///< robust (1.4826 MAD) spread over model orders
  int count = 0;                             ///< stable poles in the cluster
  int order = 0;                             ///< model order of the representative pole
  std::complex<double> rawLambda;            ///< representative pole of the windowed FRF, 1/s
};

/// LSCF estimator for one FRF set (one reference, several responses) in a band. The reduced normal
/// equations are Toeplitz in the z-domain basis Omega_k^j = exp(i w_k dt j) (dt = 1/(2 fMax)), so all
/// orders up to maxOrder are built once from lag sums.
class LscfEstimator {
 public:
  /// frequency in Hz (uniform bins), h[channel][bin] complex FRFs.
  LscfEstimator(const std::vector<double>& frequency, const std::vector<std::vector<std::complex<double>>>& h,
                const LscfOptions& options);
  /// Physical poles (Im > 0, Re < 0 before window correction, damped frequency in band) of the
  /// common-denominator model of `order`; raw (window decay not removed), 1/s.
  std::vector<std::complex<double>> calcRawPoles(int order) const;
  const LscfOptions& getOptions() const { return options_; }

 private:
  LscfOptions options_;
  double dt_ = 0;
  Eigen::VectorXd r_;                  // lags 0..2n of the basis autocorrelation
  std::vector<Eigen::VectorXd> s_, t_; // per channel, lags -n..n (index m+n)
};

/// Poles of every order from minOrder to maxOrder, with stability flags against the previous order.
std::vector<StabilisationPole> calcStabilisationDiagram(const LscfEstimator& estimator);

/// Clusters poles stable in frequency and damping; a cluster at enough orders (minStableFraction of the
/// orders swept, at least 2) with a positive damping ratio (window decay removed) is a mode. Other
/// clusters go to `rejected` if given.
std::vector<ModalEstimate> selectStableModes(const std::vector<StabilisationPole>& diagram, const LscfOptions& options,
                                            std::vector<ModalEstimate>* rejected = nullptr);

/// Number of orders at which a cluster must be stable to count as a mode.
size_t calcRequiredStableOrders(const LscfOptions& options);

/// Jackknife standard error from leave-one-out estimates: sqrt((n-1)/n sum (x_i - mean)^2).
double calcJackknifeSpread(const std::vector<double>& leaveOneOutEstimates);

/// Jackknife (leave-one-hit-out) standard errors of frequency (Hz) and damping ratio of `modes`, using
/// the per-hit spectra kept in `frf` and LSCF at each mode's order. Needs >= 3 hits; NaN otherwise or if
/// a mode is not found again within max(clusterTolerance * f, 2 df) in a resample.
std::vector<std::pair<double, double>> calcJackknifeStdErr(const FrfEstimate& frf, const LscfOptions& options,
                                                           const std::vector<ModalEstimate>& modes);

/// Modal model of one FRF: conjugate pole pairs with complex residues, plus real upper (constant) and
/// lower (-LR/w^2) residual terms, fitted by linear least squares (LSFD) over the band.
struct ModalModel {
  std::vector<std::complex<double>> poles, residues;
  double upperResidual = 0, lowerResidual = 0;
  /// Model value at f Hz.
  std::complex<double> evaluate(double frequencyHz) const;
};

/// LSFD fit of `h` (one channel) over [fMin, fMax] with the given raw poles. Unweighted (absolute error:
/// best residues near the peaks), or with relativeWeighting each bin weighted by 1/|H| (the model then
/// follows the FRF on a log scale, for plots).
ModalModel fitModalModel(const std::vector<double>& frequency, const std::vector<std::complex<double>>& h,
                         double fMin, double fMax, const std::vector<std::complex<double>>& rawPoles,
                         bool relativeWeighting = false);

}  // namespace motostab::modal
