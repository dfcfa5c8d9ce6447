#pragma once
// Priors of fitted scenario parameters and the rule that keeps a measured value from being overruled
// by a fit that merely reaches far enough.
//
// Prior: Student-t with nu = kPriorNu degrees of freedom around the scenario's value, its scale set so
// that the curvature at the mean is that of the Gaussian with the stated sigma (scale s =
// sigma sqrt((nu + 1) / nu)). With z = (value - mean) / sigma,
//   -2 ln p(value) = (nu + 1) ln(1 + z^2 / (nu + 1)) + const,                  (eq. 1)
// which is z^2 near the mean and grows only logarithmically in the tails, so a gross error the data
// insist on (a value mistyped, a wheelbase measured to the wrong axle) can still be fitted, while a
// small change costs what the measurement says. nu = 4 is the robust choice of Lange, Little & Taylor
// (1989, Robust statistical modeling using the t distribution, JASA 84:881, sect. 4). The least-squares
// residual of the prior is sign(z) sqrt(eq. 1).
//
// Contradiction rule: a candidate that meets every criterion of a cause but moves a *measured*
// parameter (its sigma from the scenario's `uncertainty:` section) by more than kContradictionSigmas
// sigma "fits, but contradicts the measurement": it is reported as such and not named, unless its
// evidence is overwhelming, i.e. its BIC is at least kOverwhelmingBic below that of the best
// alternative (the baseline, or the best candidate meeting every criterion without contradicting a
// measurement): posterior odds of e^(kOverwhelmingBic / 2) (Kass & Raftery 1995, JASA 90:773, sect. 3.2:
// a BIC difference above 10 is already "very strong"). A contradicting fit whose only unmet criterion is
// an estimate held at the bound of its search range (kParameterRangeSigmas sigma: a gross error beyond
// even that) is reported as contradicting too, never dropped silently. The rule reads the point
// estimate: a change the data put beyond 3 sigma is reported, however wide its interval.
#include <vector>

#include "diagnosis/diagnosis.h"

namespace motostab::diagnosis {

constexpr double kPriorNu = 4;              ///< Student-t degrees of freedom of every prior
constexpr double kContradictionSigmas = 3;  ///< a named change beyond this many sigma of a measured value contradicts it
constexpr double kOverwhelmingBic = 40;     ///< BIC lead that lets a contradicting candidate be named
/// Half-width of a measured scenario parameter's search range in its sigmas (candidates.cpp): wide enough for a
/// gross error (a 40-sigma wheelbase) to be fitted; the t prior costs 5 ln(1 + z^2 / 5) = 38 there.
constexpr double kParameterRangeSigmas = 100;

/// True when some estimate moves a measured parameter by more than kContradictionSigmas sigma.
bool contradictsMeasurement(const std::vector<ParameterEstimate>& estimates);

/// Least-squares residual sign(z) sqrt(eq. 1) of the Student-t prior, z = (value - mean) / sigma.
double calcPriorResidual(double value, double mean, double sigma);

/// True when a contradicting candidate (BIC `contradicting`) is named over the best alternative (BIC
/// `alternative`: the baseline's, or the best non-contradicting cause's when lower).
bool isOverwhelming(double contradicting, double alternative);

/// The cause of a step among `fits` (judged: `failed` empty means every criterion is met): the lowest
/// BIC among those that contradict no measurement, unless a contradicting one is overwhelming (then
/// the lowest-BIC such one). -1: none. `contradicting` gets the indices of the contradicting ones
/// that met every criterion (but the bound of the search range) and were not named.
int pickCause(const std::vector<FitSummary>& fits, double baselineBic, std::vector<int>* contradicting);

}  // namespace motostab::diagnosis
