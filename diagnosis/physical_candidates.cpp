#include "diagnosis/physical_candidates.h"

#include <algorithm>
#include <cmath>

namespace motostab::diagnosis {
namespace {

// A wheel's scalar key, or `fallback` when absent or no number (the scenario loader reports those).
double getWheelValue(const YAML::Node& tree, const char* wheel, const char* key, double fallback) {
  const YAML::Node w = tree[wheel];
  return w && w.IsMap() && w[key] ? w[key].as<double>(fallback) : fallback;
}

void addTyreCrown(const YAML::Node& tree, std::vector<Candidate>& out) {
  const double front = getWheelValue(tree, "front_wheel", "crown_radius_m", 0), rear = getWheelValue(tree, "rear_wheel", "crown_radius_m", 0);
  const double radius = std::min(getWheelValue(tree, "front_wheel", "radius_m", 0), getWheelValue(tree, "rear_wheel", "radius_m", 0));
  if (front != 0 || rear != 0 || !(radius > 0)) return;
  CandidateParameter p;
  p.name = "crown_radius_m";
  p.path = "front_wheel.crown_radius_m";
  p.alsoPaths = {"rear_wheel.crown_radius_m"};
  p.lower = 0, p.upper = std::min(0.5 * radius, 0.15);  // a toroidal tyre's crown within half the wheel
  p.start = std::min(kDefaultCrownRadius_m, 0.5 * p.upper);
  p.step = 1e-5;
  p.off = 0, p.offAtBound = true;
  out.push_back({"tyre_crown", {}, {p}});
}

}  // namespace

double calcFrictionDampingFactor(double steerRateAmplitude) { return 4 / (M_PI * steerRateAmplitude); }

void addPhysicalCandidates(const YAML::Node& tree, std::vector<Candidate>& out) {
  std::vector<Candidate> added;
  addTyreCrown(tree, added);
  out.insert(out.end(), added.begin(), added.end());
}

}  // namespace motostab::diagnosis
