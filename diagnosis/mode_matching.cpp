#include "diagnosis/mode_matching.h"

#include <algorithm>
#include <cmath>

#include "io/input_error.h"

namespace motostab::diagnosis {

using analysis::LinearModel;
using analysis::ModeBranch;
using analysis::ModeLabel;
using analysis::SweepResult;
using analysis::calcMatchCost;
using io::InputError;

ModeMatcher::ModeMatcher(const SweepResult& reference, const std::vector<MeasuredEigenvalue>& rows)
    : reference_(reference), rows_(rows) {}

// Eigenvalue indices at candidate speed k on branches labelled `mode`.
std::vector<int> ModeMatcher::findLabelled(const SweepResult& candidate, ModeLabel mode, size_t k) const {
  std::vector<int> out;
  for (const ModeBranch& b : candidate.branches)
    if (b.label == mode && k < b.index.size() && b.index[k] >= 0) out.push_back(b.index[k]);
  return out;
}

// Cost of each eigenvalue at candidate speed k as `mode` (infinite off the mode's labelled branches
// when it has any there): the base branch at the nearest reference speed plus, when prevIndex >= 0,
// the mode's eigenvalue at the previous speed. Empty where the base sweep has no such branch.
Eigen::VectorXd ModeMatcher::calcCosts(ModeLabel mode, const SweepResult& candidate, size_t k,
                                       int prevIndex) const {
  const LinearModel& lin = candidate.models[k];
  const size_t r = std::min_element(reference_.speeds.begin(), reference_.speeds.end(), [&](double a, double b) {
                     return std::abs(a - lin.speed) < std::abs(b - lin.speed);
                   }) - reference_.speeds.begin();
  const auto branch = std::find_if(reference_.branches.begin(), reference_.branches.end(),
                                   [&](const ModeBranch& b) { return b.label == mode && b.index[r] >= 0; });
  if (branch == reference_.branches.end()) return {};
  const std::vector<int> labelled = findLabelled(candidate, mode, k);
  Eigen::VectorXd c = Eigen::VectorXd::Constant(lin.eigenvalues.size(), HUGE_VAL);
  for (int kb = 0; kb < lin.eigenvalues.size(); ++kb) {
    if (!labelled.empty() && std::find(labelled.begin(), labelled.end(), kb) == labelled.end()) continue;
    c[kb] = calcMatchCost(reference_.models[r], branch->index[r], lin, kb);
    if (k > 0 && prevIndex >= 0) c[kb] += calcMatchCost(candidate.models[k - 1], prevIndex, lin, kb);
  }
  return c;
}

std::vector<ModeTrack> ModeMatcher::track(const SweepResult& candidate) const {
  const std::vector<LinearModel>& models = candidate.models;
  std::vector<ModeTrack> out;
  for (const auto& row : rows_)
    if (row.mode && std::none_of(out.begin(), out.end(), [&](const ModeTrack& t) { return t.mode == *row.mode; }))
      out.push_back({*row.mode, std::vector<int>(models.size(), -1)});
  for (size_t k = 0; k < models.size(); ++k) {
    std::vector<Eigen::VectorXd> costs;
    std::vector<size_t> order;
    for (size_t m = 0; m < out.size(); ++m) {
      costs.push_back(calcCosts(out[m].mode, candidate, k, k ? out[m].index[k - 1] : -1));
      if (costs.back().size() > 0) order.push_back(m);
    }
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return costs[a].minCoeff() < costs[b].minCoeff(); });
    std::vector<bool> taken(static_cast<size_t>(models[k].eigenvalues.size()), false);
    for (size_t m : order) {
      int best = -1;
      for (int kb = 0; kb < costs[m].size(); ++kb)
        if (!taken[kb] && std::isfinite(costs[m][kb]) && (best < 0 || costs[m][kb] < costs[m][best])) best = kb;
      out[m].index[k] = best;
      if (best >= 0 && models[k].eigenvalues[best].imag() == 0) taken[best] = true;
    }
  }
  return out;
}

std::complex<double> ModeMatcher::pick(const SweepResult& candidate, size_t k, const MeasuredEigenvalue& row,
                                       const std::vector<ModeTrack>& tracks) const {
  const LinearModel& lin = candidate.models[k];
  std::complex<double> best;
  if (!row.mode) {
    double dmin = HUGE_VAL;
    for (int i = 0; i < lin.eigenvalues.size(); ++i) {
      const std::complex<double> l = lin.eigenvalues(i);
      const double d = std::abs(std::complex<double>(l.real(), std::abs(l.imag())) - std::complex<double>(row.real, row.imag));
      if (d < dmin) dmin = d, best = l;
    }
    return {best.real(), std::abs(best.imag())};
  }
  const auto t = std::find_if(tracks.begin(), tracks.end(), [&](const ModeTrack& m) { return m.mode == *row.mode; });
  if (t->index[k] < 0)
    throw InputError(row.where, std::string("the scenario has no ") + toString(*row.mode) + " mode near " +
                                    std::to_string(lin.speed) + " m/s");
  best = lin.eigenvalues(t->index[k]);
  const std::vector<int> pair = findLabelled(candidate, *row.mode, k);
  if (best.imag() == 0 && pair.size() == 2 && lin.eigenvalues(pair[0]).imag() == 0 && lin.eigenvalues(pair[1]).imag() == 0 &&
      pair[0] != pair[1])
    return {0.5 * (lin.eigenvalues(pair[0]).real() + lin.eigenvalues(pair[1]).real()), 0.0};  // a split pair
  return {best.real(), std::abs(best.imag())};
}

}  // namespace motostab::diagnosis
