#pragma once
// The weighted least-squares problem of a diagnosis: observations, their noise, and models made of
// candidates (internal coordinates: ln(value) for log-scale parameters, else the value).
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "diagnosis/candidates.h"
#include "diagnosis/noise_model.h"
#include "diagnosis/prediction.h"

namespace motostab::diagnosis {

/// One scalar observation: the real or imaginary part of an eigenvalue row, one response sample, or
/// one finding (value 0, its violation predicted, its tolerance as known sigma: findings.h).
struct Observation {
  double value = 0;         ///< measured (1/s, rad/s, or the signal column's unit)
  double knownSigma = 0;    ///< stderr / noise_std when given, else 0
  int component = 0;        ///< index into FitProblem::components
  int unit = 0;             ///< eigenvalue row index, or numRows + run index
  int fold = 0;
  double speed = 0;         ///< m/s
  int row = -1, part = 0;   ///< eigenvalue row and part (0 real, 1 imag)
  int run = -1, signal = 0, sample = 0;
  int finding = -1;         ///< index into MeasuredData::findings
};

/// A model: the candidates switched on together, with their parameters stacked.
struct ModelSpec {
  std::vector<const Candidate*> parts;
  int size() const;
  std::vector<const CandidateParameter*> getParameters() const;
  Eigen::VectorXd getStart() const;
  /// The candidates' switches and parameter values at x, as typed changes of the scenario.
  scenario::ParameterOverrides makeOverrides(const Eigen::VectorXd& x) const;
  double getValue(int i, const Eigen::VectorXd& x) const;  ///< key-unit value of parameter i
  /// Residuals of the parameters' Student-t priors (priors.h eq. 1), one per parameter with a prior.
  Eigen::VectorXd calcPriorResiduals(const Eigen::VectorXd& x) const;
};

/// Fewest rows without stderr from which a component's noise is estimated on its own.
constexpr int kMinEstimatedRows = 5;

class FitProblem {
 public:
  FitProblem(const Predictor& predictor, const MeasuredData& data, int folds);
  std::vector<Observation> observations;
  /// weave.real, weave.imag, run1.gyro_V, finding1.wobble.stable, ...; <mode>.real+imag where one
  /// part had fewer than kMinEstimatedRows rows without stderr (poolSmallComponents).
  std::vector<std::string> components;
  std::vector<double> componentSigma;    ///< current sigma of each component (unknown ones estimated)
  std::vector<bool> componentKnown;
  /// AR noise of each component (order 0: white). Response signals whose noise is estimated carry the
  /// AR(p) fitted to the residuals of the model being scored (noise_model.h, model_fit.h); their componentSigma is then the
  /// innovation sigma. Eigenvalue rows and signals with a given noise_std are white.
  std::vector<ArNoise> componentAr;
  /// First observation and length of each component's time series (response signals; -1, 0 otherwise).
  std::vector<int> seriesStart, seriesLength;
  int numFolds = 1;

  double getSigma(const Observation& o) const { return o.knownSigma > 0 ? o.knownSigma : componentSigma[o.component]; }
  /// The observation's marginal noise sigma (the innovation sigma times the AR marginal factor).
  double getMarginalSigma(const Observation& o) const;
  /// Per run and signal sigma, for the response fits.
  std::vector<std::vector<double>> getResponseSigma() const;
  /// Per run and signal AR noise, for the response fits.
  std::vector<std::vector<ArNoise>> getResponseNoise() const;
  /// Fast (interpolated) predictions unless `exact`.
  Prediction predict(const ModelSpec& model, const Eigen::VectorXd& x, bool exact = false) const;
  /// (measured - predicted) / sigma of every observation, each response series prewhitened by its
  /// component's AR noise (noise_model.h eq. 1): the residuals of the likelihood, of every fit, standard
  /// error, profile and cross-validation score.
  Eigen::VectorXd calcResiduals(const Prediction& p) const;
  /// measured - predicted of every observation (its unit), not whitened.
  Eigen::VectorXd calcRawResiduals(const Prediction& p) const;
  double getPredicted(const Prediction& p, const Observation& o) const;
  /// -2 ln L (up to a constant) of normalised residuals `r` (observations first, then priors) with
  /// each unknown component's noise at its maximum-likelihood value for these residuals (profiled
  /// out: n_c ln(RSS_c / n_c) + n_c, RSS_c in the column's unit squared); known ones and priors add
  /// r^2. Every model is scored with its own noise, none with another's (Pawitan 2001, sect. 10.3).
  /// AR components add their log-determinant term (noise_model.h eq. 1).
  double calcDeviance(const Eigen::VectorXd& r) const;
  /// Sets unknown components' sigma from normalised residuals `r` of a fit with k parameters (white
  /// components; for AR ones use updateNoise).
  void updateSigma(const Eigen::VectorXd& r, int k);
  /// Re-estimates the noise from the raw residuals `e` (calcRawResiduals) of a fit with k parameters:
  /// each estimated response series its AR(p) by Burg and its innovation sigma, every other unknown
  /// component its sigma (RSS / n times n / (n - k)).
  void updateNoise(const Eigen::VectorXd& e, int k);
  const MeasuredData& getData() const { return data_; }
  NoiseState getNoise() const { return {componentSigma, componentAr}; }
  /// Takes `n` (one entry per component: throws std::logic_error otherwise).
  void setNoise(const NoiseState& n);
  /// AR coefficients estimated from the data (sum of the orders of the estimated series): parameters
  /// of the noise model that BIC counts, since models may choose different orders.
  int countNoiseParameters() const;

 private:
  void addEigenvalueObservations();
  void addResponseObservations();
  void addFindingObservations();
  void assignFolds(int folds);
  void poolSmallComponents();
  void markGivenComponents();
  void indexSeries();
  void setWhiteSigma(const Eigen::VectorXd& e, int k);
  int addComponent(const std::string& name, bool known);
  const Predictor& predictor_;
  const MeasuredData& data_;
  std::vector<int> findingProbeStart_;  ///< per finding: its first probe row in Prediction::eigenvalues
};

}  // namespace motostab::diagnosis
