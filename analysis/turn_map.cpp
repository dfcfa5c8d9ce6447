#include "analysis/turn_map.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace motostab::analysis {

using vehicle::VehicleModel;

size_t TurnMapResult::countFailedPoints() const {
  size_t n = 0;
  for (const auto& s : sweeps) n += s.failures.size();
  return n;
}

namespace {

// The trim of `sweep` at speed v (m/s), if it has one.
const TrimPoint* findTrimAt(const SweepResult& sweep, double v) {
  for (size_t k = 0; k < sweep.speeds.size(); ++k)
    if (sweep.speeds[k] == v) return &sweep.trims[k];
  return nullptr;
}

}  // namespace

TurnMapResult runTurnMap(const VehicleModel& model, const TurnMapOptions& opt) {
  if (opt.rolls.empty()) throw std::logic_error("runTurnMap: no roll angle");
  TurnMapResult map;
  const std::vector<double> speeds = makeSpeedGrid(opt.sweep.start, opt.sweep.stop, opt.sweep.step);
  // The sweeps' lead chains start at the first speed of at least 1 m/s (at the first speed when none is).
  const size_t atLeast1 = std::find_if(speeds.begin(), speeds.end(), [](double v) { return v >= 1.0; }) - speeds.begin();
  const double first = speeds[atLeast1 < speeds.size() ? atLeast1 : 0];
  std::optional<TrimError> firstError;  // of the first roll angle none of whose speeds trimmed
  for (double roll : opt.rolls) {
    SweepOptions o = opt.sweep;
    o.trim.roll = roll;
    o.trim.condition = TurnCondition::Speed;
    o.criticalSpeedTolerance = opt.criticalSpeedTolerance;
    o.keepFailedSpeeds = true;
    // Each roll starts from its neighbour's trim at the first speed: one roll step, not a climb from upright.
    o.warmStart = map.sweeps.empty() ? nullptr : findTrimAt(map.sweeps.back(), first);
    try {
      SweepResult s = runSweep(model, speeds, o);
      map.rolls.push_back(roll);
      map.sweeps.push_back(std::move(s));
    } catch (const TrimError& e) {
      map.failedRolls.push_back({roll, e.what()});
      if (!firstError) firstError = e;
    }
  }
  if (map.sweeps.empty()) throw TrimError("no roll angle of the map could be trimmed at any speed", *firstError);
  return map;
}

}  // namespace motostab::analysis
