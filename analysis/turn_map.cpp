#include "analysis/turn_map.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace motostab::analysis {

using vehicle::VehicleModel;


TurnMapResult runTurnMap(const VehicleModel& model, const TurnMapOptions& opt) {
  if (opt.rolls.empty()) throw std::invalid_argument("runTurnMap: no roll angle");
  TurnMapResult map;
  map.rolls = opt.rolls;
  const std::vector<double> speeds = makeSpeedGrid(opt.sweep.start, opt.sweep.stop, opt.sweep.step);
  // The sweeps' lead chains start at the first speed of at least 1 m/s (at the first speed when none is).
  const size_t atLeast1 = std::find_if(speeds.begin(), speeds.end(), [](double v) { return v >= 1.0; }) - speeds.begin();
  const size_t first = atLeast1 < speeds.size() ? atLeast1 : 0;
  std::vector<SweepOptions> options;
  for (double roll : opt.rolls) {
    options.push_back(opt.sweep);
    options.back().trim.roll = roll;
    options.back().trim.condition = TurnCondition::Speed;
    options.back().findCriticalSpeeds = false;
    options.back().criticalSpeedTolerance = opt.criticalSpeedTolerance;
    // Each roll starts from its neighbour's trim at the first speed: one roll step, not a climb from upright.
    if (!map.sweeps.empty() && map.sweeps.back().trims.size() == speeds.size())
      options.back().warmStart = &map.sweeps.back().trims[first];
    map.sweeps.push_back(runSweep(model, options.back()));
  }
  for (auto& o : options) o.warmStart = nullptr;
  trackModesAcrossRoll(map);
  for (size_t j = 0; j < map.rolls.size(); ++j) updateCriticalSpeeds(model, options[j], map.sweeps[j]);
  return map;
}

namespace {

// Cost of continuing branch a of sweep `from` by branch b of sweep `to`: calcMatchCost summed over the
// speeds both have.
double calcBranchCost(const SweepResult& from, const ModeBranch& a, const SweepResult& to, const ModeBranch& b) {
  double cost = 0;
  const size_t n = std::min(from.models.size(), to.models.size());
  for (size_t k = 0; k < n; ++k) cost += calcMatchCost(from.models[k], a.index[k], to.models[k], b.index[k]);
  return cost;
}

// Labels of `to`'s branches from `from`'s, matched cheapest pair first (each branch used once).
void copyLabels(const SweepResult& from, SweepResult& to) {
  struct Pair {
    double cost;
    size_t a, b;
  };
  std::vector<Pair> pairs;
  for (size_t a = 0; a < from.branches.size(); ++a)
    for (size_t b = 0; b < to.branches.size(); ++b)
      pairs.push_back({calcBranchCost(from, from.branches[a], to, to.branches[b]), a, b});
  std::stable_sort(pairs.begin(), pairs.end(), [](const Pair& x, const Pair& y) { return x.cost < y.cost; });
  std::vector<bool> usedA(from.branches.size(), false), usedB(to.branches.size(), false);
  std::vector<std::string> newLabels(to.branches.size());
  for (const Pair& p : pairs) {
    if (usedA[p.a] || usedB[p.b]) continue;
    usedA[p.a] = usedB[p.b] = true;
    newLabels[p.b] = from.branches[p.a].label;
  }
  for (size_t b = 0; b < to.branches.size(); ++b)
    if (!newLabels[b].empty()) to.branches[b].label = newLabels[b];
}

}  // namespace

void trackModesAcrossRoll(TurnMapResult& map) {
  const size_t n = map.sweeps.size();
  if (n < 2) return;
  size_t ref = 0;
  for (size_t j = 1; j < n; ++j)
    if (std::abs(map.rolls[j]) < std::abs(map.rolls[ref])) ref = j;
  for (size_t j = ref + 1; j < n; ++j) copyLabels(map.sweeps[j - 1], map.sweeps[j]);
  for (size_t j = ref; j-- > 0;) copyLabels(map.sweeps[j + 1], map.sweeps[j]);
}

}  // namespace motostab::analysis
