#include "diagnosis/profile_likelihood.h"

#include <cmath>
#include <stdexcept>

#include "diagnosis/model_fit.h"

namespace motostab::diagnosis {
namespace {

// chi2 with parameter i held at internal value v, the others refitted; infinite where v makes no
// valid vehicle (an inertia past the triangle inequality, a trim that fails): the profile then ends
// at the edge of the valid values.
double calcProfileChi2(const FitProblem& problem, const ModelSpec& model, Eigen::VectorXd x, int i, double v) {
  x(i) = v;
  try {
    return fitModel(problem, model, x, -1, 15, i).chi2;
  } catch (const std::exception&) {
    return HUGE_VAL;
  }
}

// One end of the interval in direction dir, internal units: doubling steps out from the standard error
// (from 1 % of the range where it is zero or not finite: a flat likelihood), then bisection.
double findProfileEnd(const FitProblem& problem, const ModelSpec& model, const FitSummary& s, int i, double se,
                      double range, double bound, int dir) {
  const double target = s.chi2 + kProfileChi2_95, x0 = s.x(i);
  const double first = se > 0 && std::isfinite(se) ? se : 0.01 * range;
  double inside = x0, outside = x0, d = std::max(first, 1e-6 * std::max(1.0, std::abs(x0)));
  for (int k = 0; k < 24; ++k, d *= 2) {
    outside = dir > 0 ? std::min(x0 + d, bound) : std::max(x0 - d, bound);
    if (calcProfileChi2(problem, model, s.x, i, outside) >= target) break;
    inside = outside;
    if (outside == bound) return bound;
  }
  for (int k = 0; k < 8; ++k) {
    const double mid = 0.5 * (inside + outside);
    (calcProfileChi2(problem, model, s.x, i, mid) >= target ? outside : inside) = mid;
  }
  return 0.5 * (inside + outside);
}

}  // namespace

double calcProfileRise(const FitProblem& problem, const ModelSpec& model, const FitSummary& s, int index,
                       double internalValue) {
  return calcProfileChi2(problem, model, s.x, index, internalValue) - s.chi2;
}

void calcProfiles(const FitProblem& problem, const ModelSpec& model, FitSummary& s) {
  const auto ps = model.getParameters();
  for (size_t i = 0; i < ps.size(); ++i) {
    ParameterEstimate& e = s.allParameters[i];
    const bool lg = ps[i]->logScale;
    const double se = lg ? e.stderr_ / e.value : e.stderr_;
    const double lo = lg ? std::log(ps[i]->lower) : ps[i]->lower, hi = lg ? std::log(ps[i]->upper) : ps[i]->upper;
    const double a = findProfileEnd(problem, model, s, static_cast<int>(i), se, hi - lo, lo, -1);
    const double b = findProfileEnd(problem, model, s, static_cast<int>(i), se, hi - lo, hi, +1);
    e.profileLow = lg ? std::exp(a) : a;
    e.profileHigh = lg ? std::exp(b) : b;
    e.hasProfile = true;
  }
}

}  // namespace motostab::diagnosis
