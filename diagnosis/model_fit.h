#pragma once
// Fitting one model of a diagnosis (the current causes plus a candidate) and scoring it.
//
// Each model is scored with its own noise: the unknown components' sigma and each estimated response
// series' AR(p) noise (noise_model.h) are re-estimated from that model's residuals and the model is
// refitted by generalised least squares with them, alternately, until the noise changes by less than
// kNoiseTolerance (at most kMaxNoiseIterations fits): iterated Cochrane-Orcutt estimation (Cochrane &
// Orcutt 1949, JASA 44:32), whose fixed point is the joint maximum of the likelihood in the model's
// parameters and its noise (Brockwell & Davis 2002, Introduction to Time Series and Forecasting, 2nd
// ed., sect. 6.6, regression with ARMA errors). Deviance, BIC and the likelihood ratio thus compare each
// model's own maximised likelihood (Wilks 1938; Schwarz 1978), never a model scored with the noise
// fitted to another one's residuals. The final deviance is evaluated after the last noise update, so
// no score is left from an older noise. BIC's k counts the AR coefficients too, since two models may
// choose different orders.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "diagnosis/diagnosis.h"
#include "diagnosis/fit_problem.h"
#include "diagnosis/least_squares.h"

namespace motostab::diagnosis {

constexpr int kMaxNoiseIterations = 4;    ///< fits per model at most, each after a noise update
/// NoiseState::calcChange below which the noise has converged. The deviance profiles each estimated
/// sigma out and is evaluated with the final noise, so a remaining change of the weights moves it only
/// to second order.
constexpr double kNoiseTolerance = 0.03;
/// Fits stop when chi2 falls by less than this fraction of itself: a chi2 within about 1e-6 chi2 of
/// its minimum (5e-4 for 500 observations) leaves a parameter within 0.03 standard errors of it.
constexpr double kFitTolerance = 1e-6;

/// The model made of `causes` and `candidate` (none: nullptr).
ModelSpec makeModel(const std::vector<const Candidate*>& causes, const Candidate* candidate);

/// Least-squares residuals of `model` at x (data, then priors) with the problem's noise.
Eigen::VectorXd calcFitResiduals(const FitProblem& problem, const ModelSpec& model, const Eigen::VectorXd& x);

/// Fits `model` from x0 with the problem's noise held (on every observation when fold < 0, else on those
/// outside that fold); a model without parameters is evaluated. fixIndex >= 0 holds that parameter at
/// its x0 value (profile likelihood).
LeastSquaresResult fitModel(const FitProblem& problem, const ModelSpec& model, const Eigen::VectorXd& x0, int fold,
                            int maxIterations = 30, int fixIndex = -1, bool statistics = true);

/// The full-data fit of `model` from x0, its noise iterated from `startNoise` (nullptr: the problem's),
/// scored: deviance, BIC (k = model parameters + the responses' linear ones + AR coefficients), estimates.
/// A candidate's own parameters are the last part's when `name` is that part's; else all.
FitSummary fitFull(const FitProblem& problem, const ModelSpec& model, const Eigen::VectorXd& x0, const std::string& name,
                   const NoiseState* startNoise = nullptr);

/// fitFull, or a fit marked failed (infinite chi2, BIC and deviance; failed = {"fit failed: ..."}) when
/// the start is no valid vehicle or a trim fails.
FitSummary fitOrFail(const FitProblem& problem, const ModelSpec& model, const Eigen::VectorXd& x0, const std::string& name,
                     const NoiseState& startNoise);

/// K-fold cross-validation of a model around its full fit s.x, every fold fitted and scored with
/// `noise` (one noise for every model compared, so that held-out errors share one metric).
void crossValidate(const FitProblem& problem, const ModelSpec& model, const NoiseState& noise, FitSummary& s,
                   int threads = 1);

/// The CV RMS of `s` (crossValidate) over the folds not marked in `skip`: sqrt(sum of fold RMS^2 times
/// the fold's observation count over their count); NaN when every fold is skipped.
double calcCvRmsOver(const FitProblem& problem, const FitSummary& s, const std::vector<bool>& skip);

/// RMS of the normalised (whitened) data residuals of `model` at x with `noise`: models compared by RMS
/// must share one noise (each model's own sigma makes its own RMS about 1).
double calcRms(const FitProblem& problem, const ModelSpec& model, const Eigen::VectorXd& x, const NoiseState& noise);

/// A copy of `problem` carrying `noise`.
FitProblem withNoise(const FitProblem& problem, const NoiseState& noise);

}  // namespace motostab::diagnosis
