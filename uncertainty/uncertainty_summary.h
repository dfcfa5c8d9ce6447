#pragma once
// Statistics of an uncertainty study: distributions of the critical speeds, their first-order
// (linearised) estimate, sensitivities, and per-speed quantiles of the labelled modes.
#include <array>
#include <string>
#include <vector>

#include "uncertainty/uncertainty_study.h"

namespace motostab::uncertainty {

/// Statistics of one critical speed over the successful samples that have it (m/s).
struct CriticalSpeedStats {
  std::string mode;
  size_t count = 0;             ///< samples with the crossing
  double fraction = 0;          ///< count / successful samples
  double mean = 0, std = 0, p05 = 0, p50 = 0, p95 = 0;  ///< NaN when count == 0 (std when count < 2)
  double nominal = 0;           ///< the nominal scenario's crossing, NaN if none
  double firstOrderStd = 0;     ///< sqrt(J Sigma J^T), NaN if a neighbour lacks the crossing
  std::vector<double> derivatives;  ///< dv/dx_j (m/s per parameter unit), NaN where unavailable
  /// Sensitivity per parameter: first-order Sobol index S_j (sobol, Jansen's estimator) or standardised regression
  /// coefficient SRC_j (mc); r2 is the regression's coefficient of determination (mc; NaN for sobol).
  std::vector<double> sensitivity;
  double r2 = 0;
};

/// Quantiles of one fan mode at each speed of the grid.
struct ModeQuantiles {
  std::string mode;
  std::vector<size_t> count;    ///< samples having the mode at each speed
  std::vector<std::array<double, 3>> real, frequency;  ///< p05, p50, p95 (1/s, Hz); NaN where count is 0
};

struct UncertaintySummary {
  SamplingMethod method = SamplingMethod::MonteCarlo;
  std::vector<double> speeds;
  size_t tasks = 0, samples = 0, succeeded = 0, failed = 0, redraws = 0;
  std::vector<CriticalSpeedStats> criticalSpeeds;  ///< in kUncertainModes order
  std::vector<ModeQuantiles> modes;                ///< fan modes present in some sample
};

/// Percentile q in [0, 1] of sorted values by linear interpolation between order statistics
/// (Hyndman and Fan 1996, definition 7).
double calcPercentile(const std::vector<double>& sorted, double q);

/// Standardised regression coefficients of y on the columns of x (rows: samples) and the fit's R^2
/// (Saltelli et al. 2008, "Global Sensitivity Analysis: The Primer", sec. 1.2.5). Columns with zero
/// spread get 0. Needs more rows than columns + 1, else NaNs.
std::vector<double> calcStandardisedRegression(const std::vector<std::vector<double>>& x, const std::vector<double>& y,
                                               double& r2);

/// The summary of all task results (indexed by task).
UncertaintySummary summarizeUncertainty(const UncertaintySetup& setup, const std::vector<TaskResult>& results);

}  // namespace motostab::uncertainty
