#include "studies/study.h"

#include <cmath>
#include <memory>

#include "core/parallel.h"
#include "io/result_error.h"
#include "scenario/scenario_source.h"

namespace motostab::studies {

using analysis::LinearModel;
using analysis::LinearizeOptions;
using analysis::ModeBranch;
using analysis::Slot;
using analysis::SweepOptions;
using analysis::SweepResult;
using analysis::TrimResult;
using analysis::findBestMatch;
using analysis::linearize;
using analysis::restoreTrim;
using analysis::runSweep;
using analysis::updTrim;
using scenario::ParameterOverrides;
using scenario::Scenario;
using scenario::ScenarioSource;
using vehicle::VehicleModel;

const ModeBranch* findBranch(const SweepResult& sweep, analysis::ModeLabel label) {
  for (const auto& b : sweep.branches)
    if (b.label == label && b.eigenvalue.back().imag() >= 0) return &b;
  return nullptr;
}

ModeShape calcWeaveShape(const VehicleModel& model, const SweepResult& sweep, double speed, const SweepOptions& opt) {
  const ModeBranch* weave = findBranch(sweep, analysis::ModeLabel::Weave);
  if (!weave) throw io::ResultError("no weave mode in the sweep: no mode shape at " + std::to_string(speed) + " m/s");
  size_t k = 0;
  for (size_t i = 0; i < sweep.speeds.size(); ++i)
    if (std::abs(sweep.speeds[i] - speed) < std::abs(sweep.speeds[k] - speed)) k = i;
  TrimResult trim = restoreTrim(model, sweep.trims[k]);
  updTrim(model, speed, opt.trim, trim);
  LinearizeOptions lo = opt.linearize;
  lo.removeYaw = sweep.models[k].findState(vehicle::StateRole::Yaw, vehicle::StateKind::Coordinate) < 0 ? 1 : 0;
  const LinearModel lin = linearize(model, trim, lo);
  int e = findBestMatch(sweep.models[k], weave->index[k], lin);
  if (lin.eigenvalues[e].imag() < 0) {  // the conjugate member: take the upper one
    for (int j = 0; j < lin.eigenvalues.size(); ++j)
      if (std::abs(lin.eigenvalues[j] - std::conj(lin.eigenvalues[e])) < 1e-9 * std::abs(lin.eigenvalues[e])) e = j;
  }
  ModeShape shape;
  shape.speed = speed;
  shape.eigenvalue = lin.eigenvalues[e];
  const double w = model.getScenario().geometry.wheelbase;
  using vehicle::StateKind;
  using vehicle::StateRole;
  auto component = [&](StateRole role, StateKind kind) -> std::complex<double> {
    const int i = lin.findState(role, kind);
    return i < 0 ? 0.0 : lin.eigenvectors(i, e);
  };
  std::vector<std::pair<std::string, std::complex<double>>> parts{
      {"roll", component(StateRole::Roll, StateKind::Coordinate)},
      {"yaw", component(StateRole::Yaw, StateKind::Coordinate)},
      {"steer", component(StateRole::Steer, StateKind::Coordinate)},
      // lateral displacement of the rear hub / wheelbase
      {"lateral", component(StateRole::Lateral, StateKind::Rate) / shape.eigenvalue / w}};
  for (size_t i = 0; i < lin.states.size(); ++i) {
    const auto& st = lin.states[i];
    const bool swingarm = st.role == StateRole::SwingarmBending || st.role == StateRole::SwingarmTorsion ||
                          st.role == StateRole::SwingarmTwist;
    if (st.entry.slot == Slot::Q && swingarm) parts.push_back({st.name, lin.eigenvectors(i, e)});
  }
  const std::complex<double> steerPhase = std::polar(1.0, -std::arg(component(StateRole::Steer, StateKind::Coordinate)));
  double largest = 0;
  for (const auto& p : parts) largest = std::max(largest, std::abs(p.second));
  for (const auto& [name, value] : parts) {
    const std::complex<double> v = value * steerPhase;
    shape.components.push_back({name, std::abs(v) / largest, std::arg(v) * 180 / M_PI});
  }
  return shape;
}

StudyResult runStudy(const ScenarioSource& source, const StudyOptions& opt) {
  StudyResult out;
  const Scenario base = source.load(opt.overrides);
  out.scenario = base.name;
  out.wheelbase = base.geometry.wheelbase;
  // Each variant owns its model, so variants run in parallel safely.
  struct Job {
    ParameterOverrides overrides;
    bool halved;
    std::string name;
  };
  std::vector<Job> jobs;
  for (int halved = 0; halved < 2; ++halved)
    for (const auto& v : opt.variants) {
      ParameterOverrides o = opt.overrides;
      o.set("swingarm.compliance", v);
      if (halved) {  // the scale factors as doubles, at full precision
        o.set("swingarm.stiffness_scale", opt.stiffnessScale);
        o.set("swingarm.damping_scale", opt.dampingScale);
      }
      jobs.push_back({o, halved == 1, v});
    }
  std::vector<SweepResult> results(jobs.size());
  auto runJob = [&](size_t j) {
    const VehicleModel model(source.load(jobs[j].overrides));
    results[j] = runSweep(model, opt.sweep);
  };
  core::runParallel(jobs.size(), opt.threads, runJob);
  for (size_t j = 0; j < jobs.size(); ++j)
    (jobs[j].halved ? out.halved : out.nominal).push_back({jobs[j].name, jobs[j].overrides, std::move(results[j])});

  for (const auto& v : out.nominal) {
    if (v.name != opt.shapeVariant) continue;
    const VehicleModel model(source.load(v.overrides));
    for (double speed : opt.shapeSpeeds) out.weaveShapes.push_back(calcWeaveShape(model, v.sweep, speed, opt.sweep));
  }
  return out;
}

}  // namespace motostab::studies
