#include "diagnosis/prediction.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "diagnosis/findings.h"
#include "vehicle/vehicle_model.h"

namespace motostab::diagnosis {

using analysis::LinearModel;
using analysis::ModeBranch;
using analysis::SweepOptions;
using analysis::SweepResult;
using analysis::makeSpeedGrid;
using analysis::runSweep;
using scenario::ParameterOverrides;
using scenario::Scenario;
using scenario::ScenarioSource;
using vehicle::VehicleModel;

namespace {

// Accuracy asked of the fast predictions' interpolation (chooseNodes), 1/s per (1 + |lambda| s).
constexpr double kNodeTolerance = 3e-4;

// The options of the predictions' chains: the sweep's, on the calling thread (a diagnosis runs
// predictions in parallel), without critical speeds.
SweepOptions makeChainOptions() {
  SweepOptions opt;
  opt.threads = 1;
  opt.findCriticalSpeeds = false;
  return opt;
}

// `data` with its findings' probe rows appended to its eigenvalue rows (and no findings left).
MeasuredData addProbeRows(const MeasuredData& data) {
  MeasuredData out = data;
  for (auto& row : makeProbeRows(data.findings)) out.eigenvalues.push_back(std::move(row));
  out.findings.clear();
  return out;
}

}  // namespace

Predictor::Predictor(const std::string& scenarioFile, ParameterOverrides baseChanges, const MeasuredData& data)
    : Predictor(ScenarioSource::open(scenarioFile), std::move(baseChanges), data) {}

Predictor::Predictor(std::shared_ptr<const ScenarioSource> source, ParameterOverrides baseChanges, const MeasuredData& data,
                     std::shared_ptr<SweepCache> cache)
    : source_(std::move(source)),
      baseChanges_(std::move(baseChanges)),
      withProbes_(data.findings.empty() ? nullptr : std::make_shared<const MeasuredData>(addProbeRows(data))),
      data_(withProbes_ ? *withProbes_ : data),
      cache_(std::move(cache)) {
  if (data_.eigenvalues.empty() && data_.responses.empty())
    throw std::logic_error("Predictor: the measured data hold no eigenvalue rows, response runs or findings: nothing to predict");
  makeControllerParts();
  if (!parts_.empty()) return;
  speeds_ = collectSpeeds();
  makeReferenceSweep();
  matcher_ = std::make_unique<ModeMatcher>(*reference_, data_.eigenvalues);
  chooseFastSpeeds();
}

void Predictor::makeControllerParts() {
  for (ControllerGroup& g : splitByController(data_)) {
    auto part = std::make_shared<ControllerPart>();
    part->group = std::move(g);
    ParameterOverrides base = baseChanges_;
    base.append(ParameterOverrides(part->group.overrides));
    part->predictor = std::make_unique<Predictor>(source_, base, part->group.data, cache_);
    for (double v : part->predictor->speeds_) speeds_.push_back(v);
    parts_.push_back(part);
  }
  if (parts_.empty()) return;
  speeds_ = makeSortedUnique(speeds_);
  reference_ = parts_.front()->predictor->reference_;
}

// Every speed an exact prediction needs: the rows' evaluation speeds and the runs' (trace) speeds.
std::vector<double> Predictor::collectSpeeds() const {
  std::vector<double> speeds;
  for (const auto& row : data_.eigenvalues)
    for (double v : getEvaluationSpeeds(row)) speeds.push_back(v);
  for (const auto& run : data_.responses)
    for (double v : getTraceSpeeds(run)) speeds.push_back(v);
  return makeSortedUnique(speeds);
}

// The base scenario's sweep over its own range widened to the measured speeds (0.1 m/s at most
// between speeds), for the mode labels. Through the cache, a rerun whose speeds need the same range
// shares it (a two-thread sweep agrees with a new one to the trim tolerance, not to the bit:
// analysis/sweep.h).
void Predictor::makeReferenceSweep() {
  const Scenario scenario = source_->load(baseChanges_);
  SweepOptions opt;
  opt.step = std::min(scenario.speeds.step, 0.1);
  opt.start = std::min(scenario.speeds.start, std::floor(speeds_.front() / opt.step) * opt.step);
  opt.stop = std::max(scenario.speeds.stop, std::ceil(speeds_.back() / opt.step) * opt.step);
  opt.threads = 2;
  const auto compute = [&] { return runSweep(VehicleModel(scenario), opt); };
  if (!cache_) {
    reference_ = std::make_shared<const SweepResult>(compute());
    return;
  }
  const std::vector<double> range{opt.start, opt.stop, opt.step};
  reference_ = cache_->get(SweepCache::makeKey("reference", baseChanges_, range), makeSpeedGrid(opt.start, opt.stop, opt.step).size(), compute);
}

// The fast predictions' speeds: Chebyshev nodes over the interpolated labelled rows, plus the speeds
// of the rows taken exactly and of the runs.
void Predictor::chooseFastSpeeds() {
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const auto& row : data_.eigenvalues)
    for (double v : getEvaluationSpeeds(row))
      if (row.mode) lo = std::min(lo, v), hi = std::max(hi, v);
  if (hi > lo) exactModes_ = findBranchPointModes(lo, hi);
  std::vector<double> others;  // speeds predicted exactly inside the fast predictions
  int labelled = 0;            // evaluations of interpolated rows
  lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const auto& row : data_.eigenvalues)
    for (double v : getEvaluationSpeeds(row)) {
      if (!row.mode || isExactMode(*row.mode)) others.push_back(v);
      else lo = std::min(lo, v), hi = std::max(hi, v), ++labelled;
    }
  if (hi > lo) nodes_ = chooseNodes(lo, hi, labelled);
  for (const auto& run : data_.responses)
    for (double v : getTraceSpeeds(run)) others.push_back(v);
  fastSpeeds_ = nodes_;
  fastSpeeds_.insert(fastSpeeds_.end(), others.begin(), others.end());
  fastSpeeds_ = makeSortedUnique(fastSpeeds_);
}

bool Predictor::isExactMode(analysis::ModeLabel mode) const {
  return std::find(exactModes_.begin(), exactModes_.end(), mode) != exactModes_.end();
}

// Labelled modes of the rows whose base branch is real at some reference speed in [lo, hi] and
// complex at another (e.g. capsize and castor joining into a pair at low speed).
std::vector<analysis::ModeLabel> Predictor::findBranchPointModes(double lo, double hi) const {
  const SweepResult& ref = *reference_;
  std::vector<analysis::ModeLabel> out;
  for (const auto& row : data_.eigenvalues) {
    if (!row.mode || std::find(out.begin(), out.end(), *row.mode) != out.end()) continue;
    const auto b = std::find_if(ref.branches.begin(), ref.branches.end(), [&](const ModeBranch& x) { return x.label == *row.mode; });
    if (b == ref.branches.end()) continue;
    bool real = false, complex = false;
    for (size_t k = 0; k < ref.speeds.size(); ++k)
      if (ref.speeds[k] >= lo && ref.speeds[k] <= hi && b->index[k] >= 0)
        (std::abs(b->eigenvalue[k].imag()) > 0 ? complex : real) = true;
    if (real && complex) out.push_back(*row.mode);
  }
  return out;
}

// The fewest Chebyshev points (5 to 16) on [lo, hi] whose interpolant reproduces every interpolated
// labelled mode of the base scenario at the reference sweep's speeds in [lo, hi] to kNodeTolerance
// (absolute, 1/s, plus that times |lambda|); none when the rows' own speeds are fewer, 16 when no
// count does (docs/diagnosis.md, Known limits).
std::vector<double> Predictor::chooseNodes(double lo, double hi, int labelled) const {
  const SweepResult& ref = *reference_;
  std::vector<double> nodes;
  for (int n = 5; n <= 16 && n < labelled; ++n) {
    nodes = makeChebyshevNodes(lo, hi, n);
    const auto shared = getSweep({}, nodes);
    const SweepResult& sweep = *shared;
    double worst = 0;
    for (const ModeTrack& t : matcher_->track(sweep)) {
      if (isExactMode(t.mode)) continue;
      std::vector<std::complex<double>> f;
      for (size_t k = 0; k < sweep.models.size() && t.index[k] >= 0; ++k) {
        const auto l = sweep.models[k].eigenvalues(t.index[k]);
        f.push_back({l.real(), std::abs(l.imag())});
      }
      const auto b = std::find_if(ref.branches.begin(), ref.branches.end(), [&](const ModeBranch& x) { return x.label == t.mode; });
      if (f.size() != nodes.size() || b == ref.branches.end()) return {};  // the mode is not smooth over the rows
      for (size_t k = 0; k < ref.speeds.size(); ++k) {
        if (ref.speeds[k] < lo || ref.speeds[k] > hi || b->index[k] < 0) continue;
        const std::complex<double> e(b->eigenvalue[k].real(), std::abs(b->eigenvalue[k].imag()));
        worst = std::max(worst, std::abs(interpolateChebyshev(nodes, f, ref.speeds[k]) - e) / (1 + std::abs(e)));
      }
    }
    if (worst <= kNodeTolerance) return nodes;
  }
  return nodes.size() >= 5 ? nodes : std::vector<double>();
}

SweepResult Predictor::calcSweep(const ParameterOverrides& changes, const std::vector<double>& speeds) const {
  ParameterOverrides all = baseChanges_;
  all.append(changes);
  const VehicleModel model(source_->load(all));
  return runSweep(model, speeds, makeChainOptions());
}

std::shared_ptr<const SweepResult> Predictor::getSweep(const ParameterOverrides& changes, const std::vector<double>& speeds) const {
  if (!cache_) return std::make_shared<const SweepResult>(calcSweep(changes, speeds));
  ParameterOverrides all = baseChanges_;
  all.append(changes);
  return cache_->get(SweepCache::makeKey("chain", all, speeds), speeds.size(), [&] { return calcSweep(changes, speeds); });
}

std::vector<LinearModel> Predictor::calcLinearModels(const ParameterOverrides& changes,
                                                     const std::vector<double>& speeds) const {
  return calcSweep(changes, speeds).models;
}

std::vector<std::complex<double>> Predictor::predictInterpolated(const SweepResult& sweep) const {
  std::vector<std::complex<double>> out;
  const std::vector<ModeTrack> tracks = matcher_->track(sweep);
  std::vector<std::vector<std::complex<double>>> atNodes(tracks.size());  // per mode, per node
  for (const auto& row : data_.eigenvalues) {
    std::complex<double> sum = 0;
    const std::vector<double> vs = getEvaluationSpeeds(row);
    for (double v : vs) {
      if (!row.mode || isExactMode(*row.mode)) {
        sum += matcher_->pick(sweep, findSpeed(sweep.speeds, v), row, tracks);
        continue;
      }
      const size_t m = std::find_if(tracks.begin(), tracks.end(), [&](const ModeTrack& t) { return t.mode == *row.mode; }) -
                       tracks.begin();
      if (atNodes[m].empty())
        for (double x : nodes_) atNodes[m].push_back(matcher_->pick(sweep, findSpeed(sweep.speeds, x), row, tracks));
      sum += interpolateChebyshev(nodes_, atNodes[m], v);
    }
    out.push_back(sum / static_cast<double>(vs.size()));
  }
  return out;
}

std::vector<std::complex<double>> Predictor::predictRows(const SweepResult& sweep, bool fast) const {
  if (fast) return predictInterpolated(sweep);
  std::vector<std::complex<double>> out;
  const std::vector<ModeTrack> tracks = matcher_->track(sweep);
  for (const auto& row : data_.eigenvalues) {
    const std::vector<double> nodes = getEvaluationSpeeds(row);
    std::complex<double> sum = 0;
    for (double v : nodes) sum += matcher_->pick(sweep, findSpeed(sweep.speeds, v), row, tracks);
    out.push_back(sum / static_cast<double>(nodes.size()));
  }
  return out;
}

ResponseFit Predictor::predictResponse(const SweepResult& sweep, size_t r, const std::vector<double>& sigma,
                                       const std::vector<ArNoise>& noise) const {
  const ResponseRun& run = data_.responses[r];
  std::vector<LinearModel> models;
  for (double v : getTraceSpeeds(run)) models.push_back(sweep.models[findSpeed(sweep.speeds, v)]);
  return fitFreeResponse(models, run, sigma, noise);
}

Prediction Predictor::predictParts(const ParameterOverrides& changes, const std::vector<std::vector<double>>& sigma,
                                   bool exact, const std::vector<std::vector<ArNoise>>& noise) const {
  Prediction p;
  p.eigenvalues.resize(data_.eigenvalues.size());
  p.responses.resize(data_.responses.size());
  for (const auto& part : parts_) {
    const ControllerGroup& g = part->group;
    std::vector<std::vector<double>> partSigma;
    std::vector<std::vector<ArNoise>> partNoise;
    for (size_t r : g.runs) {
      partSigma.push_back(sigma[r]);
      if (!noise.empty()) partNoise.push_back(noise[r]);
    }
    const Prediction q = part->predictor->predict(changes, partSigma, exact, partNoise);
    for (size_t i = 0; i < g.rows.size(); ++i) p.eigenvalues[g.rows[i]] = q.eigenvalues[i];
    for (size_t i = 0; i < g.runs.size(); ++i) p.responses[g.runs[i]] = q.responses[i];
    p.numLinear += q.numLinear;
  }
  return p;
}

Prediction Predictor::predict(const ParameterOverrides& changes, const std::vector<std::vector<double>>& sigma,
                              bool exact, const std::vector<std::vector<ArNoise>>& noise) const {
  if (!parts_.empty()) return predictParts(changes, sigma, exact, noise);
  const bool fast = !exact && !nodes_.empty();
  const auto shared = getSweep(changes, fast ? fastSpeeds_ : speeds_);
  const SweepResult& sweep = *shared;
  Prediction p;
  p.eigenvalues = predictRows(sweep, fast);
  for (size_t r = 0; r < data_.responses.size(); ++r) {
    p.responses.push_back(predictResponse(sweep, r, sigma[r], r < noise.size() ? noise[r] : std::vector<ArNoise>()));
    p.numLinear += p.responses.back().numLinear;
  }
  return p;
}

}  // namespace motostab::diagnosis
