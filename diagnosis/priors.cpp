#include "diagnosis/priors.h"

#include <algorithm>
#include <cmath>

#include "diagnosis/cause_criteria.h"

namespace motostab::diagnosis {

double calcPriorResidual(double value, double mean, double sigma) {
  const double z = (value - mean) / sigma;
  const double r = std::sqrt((kPriorNu + 1) * std::log1p(z * z / (kPriorNu + 1)));
  return z < 0 ? -r : r;
}

bool isOverwhelming(double contradicting, double alternative) { return contradicting <= alternative - kOverwhelmingBic; }

bool contradictsMeasurement(const std::vector<ParameterEstimate>& estimates) {
  for (const ParameterEstimate& e : estimates)
    if (e.priorMeasured && std::abs(e.sigmas) > kContradictionSigmas) return true;
  return false;
}

namespace {

// Every criterion met but, possibly, the bound of the search range (cause_criteria.h).
bool meetsAllButBound(const FitSummary& f) {
  for (const auto& why : f.failed)
    if (why != kAtBoundFailure) return false;
  return true;
}

}  // namespace

int pickCause(const std::vector<FitSummary>& fits, double baselineBic, std::vector<int>* contradicting) {
  int best = -1, bestContra = -1;
  for (size_t i = 0; i < fits.size(); ++i) {
    if (!fits[i].failed.empty()) continue;
    int& slot = fits[i].contradictsMeasurement ? bestContra : best;
    if (slot < 0 || fits[i].bic < fits[slot].bic) slot = static_cast<int>(i);
  }
  const double alternative = best >= 0 ? std::min(baselineBic, fits[best].bic) : baselineBic;
  const int named = bestContra >= 0 && isOverwhelming(fits[bestContra].bic, alternative) ? bestContra : best;
  if (contradicting)
    for (size_t i = 0; i < fits.size(); ++i)
      if (fits[i].contradictsMeasurement && meetsAllButBound(fits[i]) && static_cast<int>(i) != named)
        contradicting->push_back(static_cast<int>(i));
  return named;
}

}  // namespace motostab::diagnosis
