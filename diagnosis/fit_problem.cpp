#include "diagnosis/fit_problem.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "diagnosis/findings.h"
#include "diagnosis/priors.h"
#include "scenario/parameter_paths.h"

namespace motostab::diagnosis {

using scenario::ParameterOverrides;

int ModelSpec::size() const {
  int n = 0;
  for (const auto* c : parts) n += static_cast<int>(c->parameters.size());
  return n;
}

std::vector<const CandidateParameter*> ModelSpec::getParameters() const {
  std::vector<const CandidateParameter*> out;
  for (const auto* c : parts)
    for (const auto& p : c->parameters) out.push_back(&p);
  return out;
}

Eigen::VectorXd ModelSpec::getStart() const {
  const auto ps = getParameters();
  Eigen::VectorXd x(ps.size());
  for (size_t i = 0; i < ps.size(); ++i) x(i) = ps[i]->logScale ? std::log(ps[i]->start) : ps[i]->start;
  return x;
}

double ModelSpec::getValue(int i, const Eigen::VectorXd& x) const {
  return getParameters()[i]->logScale ? std::exp(x(i)) : x(i);
}

ParameterOverrides ModelSpec::makeOverrides(const Eigen::VectorXd& x) const {
  ParameterOverrides out;
  int i = 0;
  for (const auto* c : parts) {
    out.append(c->fixedOverrides);
    for (const auto& p : c->parameters) {
      const double key = p.keyOffset + p.keyScale * (p.logScale ? std::exp(x(i)) : x(i));
      out.set(p.path, key);
      for (size_t a = 0; a < p.alsoPaths.size(); ++a)
        out.set(p.alsoPaths[a], a < p.alsoScales.size() ? p.keyOffset + p.alsoScales[a] * (key - p.keyOffset) / p.keyScale : key);
      ++i;
    }
  }
  return out;
}

Eigen::VectorXd ModelSpec::calcPriorResiduals(const Eigen::VectorXd& x) const {
  const auto ps = getParameters();
  std::vector<double> r;
  for (size_t i = 0; i < ps.size(); ++i)
    if (ps[i]->priorSigma > 0) r.push_back(calcPriorResidual(getValue(static_cast<int>(i), x), ps[i]->priorMean, ps[i]->priorSigma));
  return Eigen::Map<Eigen::VectorXd>(r.data(), static_cast<int>(r.size()));
}

void FitProblem::setNoise(const NoiseState& n) {
  if (n.sigma.size() != components.size() || n.ar.size() != components.size())
    throw std::logic_error("FitProblem::setNoise: " + std::to_string(n.sigma.size()) + " sigmas for " +
                           std::to_string(components.size()) + " components");
  componentSigma = n.sigma, componentAr = n.ar;
}

int FitProblem::countNoiseParameters() const {
  int k = 0;
  for (size_t c = 0; c < components.size(); ++c)
    if (!componentKnown[c] && seriesLength[c] > 0) k += componentAr[c].getOrder();
  return k;
}

FitProblem::FitProblem(const Predictor& predictor, const MeasuredData& data, int folds)
    : predictor_(predictor), data_(data) {
  addEigenvalueObservations();
  addResponseObservations();
  addFindingObservations();
  poolSmallComponents();
  markGivenComponents();
  assignFolds(folds);
  indexSeries();
}

// Each response signal's samples are contiguous in `observations`, in time order.
void FitProblem::indexSeries() {
  componentAr.assign(components.size(), ArNoise());
  seriesStart.assign(components.size(), -1);
  seriesLength.assign(components.size(), 0);
  for (size_t i = 0; i < observations.size(); ++i) {
    const Observation& o = observations[i];
    if (o.run < 0) continue;
    if (seriesStart[o.component] < 0) seriesStart[o.component] = static_cast<int>(i);
    ++seriesLength[o.component];
  }
}

double FitProblem::getMarginalSigma(const Observation& o) const {
  return o.knownSigma > 0 ? o.knownSigma : componentSigma[o.component] * componentAr[o.component].calcMarginalFactor();
}

// A component whose every row has its stderr is known: its sigma (reported only) is their RMS.
void FitProblem::markGivenComponents() {
  std::vector<double> sum(components.size(), 0.0);
  std::vector<int> given(components.size(), 0), all(components.size(), 0);
  for (const auto& o : observations) {
    ++all[o.component];
    if (o.knownSigma > 0) ++given[o.component], sum[o.component] += o.knownSigma * o.knownSigma;
  }
  for (size_t c = 0; c < components.size(); ++c)
    if (!componentKnown[c] && all[c] > 0 && given[c] == all[c]) componentKnown[c] = true, componentSigma[c] = std::sqrt(sum[c] / all[c]);
}

// A part of a mode with fewer than kMinEstimatedRows estimated rows (a pair that is complex at one or
// two speeds only) shares one noise level with the other part: a sigma profiled from one or two
// residuals goes to zero with any fit that matches them (held-out data: castor.imag from 2 rows at
// 5.5e-6 1/s gave a damping stderr of 1.4e-6 and a gain factor of 7000).
void FitProblem::poolSmallComponents() {
  std::vector<int> count(components.size(), 0);
  for (const auto& o : observations)
    if (o.knownSigma <= 0) ++count[o.component];
  std::vector<std::string> names = components;
  auto split = [](const std::string& n, std::string& mode) {
    const size_t dot = n.rfind('.');
    if (dot == std::string::npos || n.rfind("run", 0) == 0) return std::string();
    mode = n.substr(0, dot);
    return n.substr(dot + 1);
  };
  for (size_t c = 0; c < components.size(); ++c) {
    std::string mode;
    const std::string part = split(components[c], mode);
    if (componentKnown[c] || count[c] == 0 || count[c] >= kMinEstimatedRows || (part != "real" && part != "imag")) continue;
    const auto partner = std::find(components.begin(), components.end(), mode + (part == "real" ? ".imag" : ".real"));
    if (partner != components.end()) names[c] = names[partner - components.begin()] = mode + ".real+imag";
  }
  if (names == components) return;
  std::vector<std::string> pooled;
  std::vector<int> newIndex;
  for (const auto& n : names) {
    auto it = std::find(pooled.begin(), pooled.end(), n);
    if (it == pooled.end()) it = pooled.insert(pooled.end(), n);
    newIndex.push_back(static_cast<int>(it - pooled.begin()));
  }
  std::vector<double> sigma(pooled.size(), 1.0);
  std::vector<bool> known(pooled.size(), false);
  for (size_t c = 0; c < components.size(); ++c)
    sigma[newIndex[c]] = componentSigma[c], known[newIndex[c]] = componentKnown[c];
  for (auto& o : observations) o.component = newIndex[o.component];
  components = pooled, componentSigma = sigma, componentKnown = known;
}

int FitProblem::addComponent(const std::string& name, bool known) {
  const auto it = std::find(components.begin(), components.end(), name);
  if (it != components.end()) return static_cast<int>(it - components.begin());
  components.push_back(name);
  componentSigma.push_back(1.0);
  componentKnown.push_back(known);
  return static_cast<int>(components.size()) - 1;
}

void FitProblem::addEigenvalueObservations() {
  for (size_t i = 0; i < data_.eigenvalues.size(); ++i) {
    const auto& e = data_.eigenvalues[i];
    const std::string mode = e.mode ? analysis::toString(*e.mode) : "nearest";
    for (int part = 0; part < (e.imag != 0 ? 2 : 1); ++part) {
      Observation o;
      o.value = part ? e.imag : e.real;
      o.knownSigma = part ? e.imagStderr : e.realStderr;
      o.component = addComponent(mode + (part ? ".imag" : ".real"), false);
      o.unit = static_cast<int>(i);
      o.speed = e.speed;
      o.row = static_cast<int>(i);
      o.part = part;
      observations.push_back(o);
    }
  }
}

void FitProblem::addResponseObservations() {
  const int rows = static_cast<int>(data_.eigenvalues.size());
  for (size_t r = 0; r < data_.responses.size(); ++r) {
    const auto& run = data_.responses[r];
    for (size_t j = 0; j < run.signals.size(); ++j) {
      const int c = addComponent("run" + std::to_string(r + 1) + "." + run.signals[j].column, false);
      if (run.signals[j].noiseStd > 0) componentSigma[c] = run.signals[j].noiseStd, componentKnown[c] = true;
      for (size_t s = 0; s < run.time.size(); ++s) {
        Observation o;
        o.value = run.signals[j].values[s];
        o.knownSigma = run.signals[j].noiseStd;
        o.component = c;
        o.unit = rows + static_cast<int>(r);
        o.speed = run.speed;
        o.run = static_cast<int>(r);
        o.signal = static_cast<int>(j);
        o.sample = static_cast<int>(s);
        observations.push_back(o);
      }
    }
  }
}

// Each finding one observation, predicted from its probe rows (after the measured rows).
void FitProblem::addFindingObservations() {
  const int rows = static_cast<int>(data_.eigenvalues.size()), runs = static_cast<int>(data_.responses.size());
  int probe = rows;
  for (size_t f = 0; f < data_.findings.size(); ++f) {
    const Finding& finding = data_.findings[f];
    findingProbeStart_.push_back(probe);
    probe += static_cast<int>(countProbeRows(finding));
    Observation o;
    o.knownSigma = finding.tolerance;
    o.component = addComponent("finding" + std::to_string(f + 1) + "." + analysis::toString(finding.mode) + "." + getFindingKindName(finding.kind), true);
    componentSigma[o.component] = finding.tolerance;
    o.unit = rows + runs + static_cast<int>(f);
    o.speed = 0.5 * (finding.speedMin + finding.speedMax);
    o.finding = static_cast<int>(f);
    observations.push_back(o);
  }
}

// Units (rows, runs and findings) sorted by speed and cut into contiguous blocks.
void FitProblem::assignFolds(int folds) {
  const int rows = static_cast<int>(data_.eigenvalues.size()), runs = static_cast<int>(data_.responses.size());
  const int finds = static_cast<int>(data_.findings.size());
  const int units = rows + runs + finds;
  if (folds <= 0) folds = rows + finds == 0 ? runs : 5;
  numFolds = std::max(1, std::min(folds, units));
  std::vector<double> speed(units);
  for (int i = 0; i < rows; ++i) speed[i] = data_.eigenvalues[i].speed;
  for (int r = 0; r < runs; ++r) speed[rows + r] = data_.responses[r].speed;
  for (int f = 0; f < finds; ++f) speed[rows + runs + f] = 0.5 * (data_.findings[f].speedMin + data_.findings[f].speedMax);
  std::vector<int> order(units), foldOf(units);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return speed[a] < speed[b]; });
  for (int k = 0; k < units; ++k) foldOf[order[k]] = k * numFolds / units;
  for (auto& o : observations) o.fold = foldOf[o.unit];
}

std::vector<std::vector<double>> FitProblem::getResponseSigma() const {
  std::vector<std::vector<double>> s(data_.responses.size());
  for (const auto& o : observations)
    if (o.run >= 0 && o.sample == 0) s[o.run].push_back(getMarginalSigma(o));
  return s;
}

std::vector<std::vector<ArNoise>> FitProblem::getResponseNoise() const {
  std::vector<std::vector<ArNoise>> s(data_.responses.size());
  for (const auto& o : observations)
    if (o.run >= 0 && o.sample == 0) s[o.run].push_back(o.knownSigma > 0 ? ArNoise() : componentAr[o.component]);
  return s;
}

Prediction FitProblem::predict(const ModelSpec& model, const Eigen::VectorXd& x, bool exact) const {
  return predictor_.predict(model.makeOverrides(x), getResponseSigma(), exact, getResponseNoise());
}

double FitProblem::getPredicted(const Prediction& p, const Observation& o) const {
  if (o.finding >= 0) return calcFindingViolation(data_.findings[o.finding], &p.eigenvalues[findingProbeStart_[o.finding]]);
  if (o.row >= 0) return o.part ? p.eigenvalues[o.row].imag() : p.eigenvalues[o.row].real();
  return p.responses[o.run].predicted[o.signal][o.sample];
}

Eigen::VectorXd FitProblem::calcRawResiduals(const Prediction& p) const {
  Eigen::VectorXd e(observations.size());
  for (size_t i = 0; i < observations.size(); ++i) e(i) = observations[i].value - getPredicted(p, observations[i]);
  return e;
}

Eigen::VectorXd FitProblem::calcResiduals(const Prediction& p) const {
  Eigen::VectorXd r = calcRawResiduals(p);
  for (size_t i = 0; i < observations.size(); ++i) r(i) /= getSigma(observations[i]);
  std::vector<double> series;
  for (size_t c = 0; c < components.size(); ++c) {
    if (componentAr[c].getOrder() == 0 || seriesLength[c] == 0) continue;
    series.assign(r.data() + seriesStart[c], r.data() + seriesStart[c] + seriesLength[c]);
    whitenSeries(componentAr[c], series.data(), r.data() + seriesStart[c], seriesLength[c]);
  }
  return r;
}

double FitProblem::calcDeviance(const Eigen::VectorXd& r) const {
  const int n = static_cast<int>(observations.size());
  std::vector<double> rss(components.size(), 0.0);
  std::vector<int> count(components.size(), 0);
  double d = r.tail(r.size() - n).squaredNorm();  // priors
  for (int i = 0; i < n; ++i) {
    const Observation& o = observations[i];
    if (o.knownSigma > 0 || componentKnown[o.component]) {
      d += r(i) * r(i);
      continue;
    }
    const double raw = r(i) * componentSigma[o.component];
    rss[o.component] += raw * raw;
    ++count[o.component];
  }
  for (size_t c = 0; c < components.size(); ++c) {
    if (count[c] > 0) d += count[c] * (std::log(std::max(rss[c] / count[c], 1e-300)) + 1.0);
    if (count[c] > 0) d += componentAr[c].calcLogDeterminant();
  }
  return d;
}

void FitProblem::updateSigma(const Eigen::VectorXd& r, int k) {
  Eigen::VectorXd e = r;
  for (size_t i = 0; i < observations.size(); ++i) e(i) *= componentSigma[observations[i].component];
  setWhiteSigma(e, k);
}

// Unknown components' sigma from raw (or whitened raw) residuals e: RSS / n times n / (n - k).
void FitProblem::setWhiteSigma(const Eigen::VectorXd& e, int k) {
  const int n = static_cast<int>(observations.size());
  const double dof = n > k ? static_cast<double>(n) / (n - k) : 1.0;
  std::vector<double> rss(components.size(), 0.0);
  std::vector<int> count(components.size(), 0);
  for (int i = 0; i < n; ++i) {
    const Observation& o = observations[i];
    if (o.knownSigma > 0) continue;
    rss[o.component] += e(i) * e(i);
    ++count[o.component];
  }
  for (size_t c = 0; c < components.size(); ++c)
    if (!componentKnown[c] && count[c] > 0) componentSigma[c] = std::max(std::sqrt(rss[c] / count[c] * dof), 1e-12);
}

void FitProblem::updateNoise(const Eigen::VectorXd& e, int k) {
  setWhiteSigma(e, k);
  const int n = static_cast<int>(observations.size());
  const double dof = n > k ? static_cast<double>(n) / (n - k) : 1.0;
  for (size_t c = 0; c < components.size(); ++c) {
    if (componentKnown[c] || seriesLength[c] == 0) continue;
    double v = 0;
    componentAr[c] = fitArNoise(e.data() + seriesStart[c], seriesLength[c], &v);
    componentSigma[c] = std::max(std::sqrt(v * dof), 1e-12);
  }
}

}  // namespace motostab::diagnosis
