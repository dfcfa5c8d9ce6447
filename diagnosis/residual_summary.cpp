#include "diagnosis/residual_summary.h"

#include <cmath>

namespace motostab::diagnosis {
namespace {

// Least-squares slope of the real residuals against speed, its stderr and two-sided normal p.
void fitTrend(const std::vector<std::pair<double, double>>& t, ComponentResidual& c) {
  if (t.size() < 3) return;
  double mv = 0, mr = 0;
  for (auto [v, r] : t) mv += v / t.size(), mr += r / t.size();
  double sxx = 0, sxy = 0;
  for (auto [v, r] : t) sxx += (v - mv) * (v - mv), sxy += (v - mv) * (r - mr);
  if (sxx <= 0) return;
  c.slopeRealPerMps = sxy / sxx;
  double sse = 0;
  for (auto [v, r] : t) sse += std::pow(r - mr - c.slopeRealPerMps * (v - mv), 2);
  c.slopeStderr = std::sqrt(sse / (t.size() - 2) / sxx);
  c.slopeP = c.slopeStderr > 0 ? std::erfc(std::abs(c.slopeRealPerMps / c.slopeStderr) / std::sqrt(2.0)) : 0.0;
}

}  // namespace

std::vector<double> calcWhitenedResiduals(const FitProblem& problem, const Prediction& p) {
  const Eigen::VectorXd r = problem.calcResiduals(p);
  return std::vector<double>(r.data(), r.data() + r.size());
}

std::vector<ComponentResidual> summariseResiduals(const FitProblem& problem, const Prediction& p) {
  std::vector<ComponentResidual> out(problem.components.size());
  std::vector<std::vector<std::pair<double, double>>> trend(out.size());  // speed, real residual
  std::vector<double> ss(out.size(), 0.0);
  const Eigen::VectorXd z = problem.calcResiduals(p);
  for (size_t i = 0; i < problem.observations.size(); ++i) {
    const Observation& o = problem.observations[i];
    const double raw = o.value - problem.getPredicted(p, o);
    ComponentResidual& c = out[o.component];
    ++c.count;
    c.meanReal += raw;
    ss[o.component] += z(i) * z(i);
    if (o.row >= 0) trend[o.component].push_back({o.speed, raw});
  }
  for (size_t k = 0; k < out.size(); ++k) {
    ComponentResidual& c = out[k];
    c.name = problem.components[k];
    c.meanReal /= std::max(c.count, 1);
    c.rmsReal = std::sqrt(ss[k] / std::max(c.count, 1));
    fitTrend(trend[k], c);
  }
  for (size_t r = 0; r < p.responses.size(); ++r)
    for (size_t j = 0; j < p.responses[r].vaf.size(); ++j)
      for (auto& c : out)
        if (c.name == "run" + std::to_string(r + 1) + "." + problem.getData().responses[r].signals[j].column)
          c.vafAfter = p.responses[r].vaf[j];
  return out;
}

}  // namespace motostab::diagnosis
