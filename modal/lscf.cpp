#include "modal/lscf.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "io/result_error.h"

namespace motostab::modal {
namespace {

using cd = std::complex<double>;

std::vector<size_t> getBandBins(const std::vector<double>& f, double fMin, double fMax) {
  std::vector<size_t> bins;
  for (size_t k = 0; k < f.size(); ++k)
    if (f[k] >= fMin && f[k] <= fMax && f[k] > 0) bins.push_back(k);
  return bins;
}

double calcMedian(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Robust standard deviation: 1.4826 x median absolute deviation (poorly converged low orders are outliers).
double calcRobustSpread(const std::vector<double>& v) {
  if (v.size() < 2) return 0;
  const double med = calcMedian(v);
  std::vector<double> dev;
  for (double x : v) dev.push_back(std::abs(x - med));
  return 1.4826 * calcMedian(dev);
}

}  // namespace

double calcNaturalFrequencyHz(std::complex<double> lambda) { return std::abs(lambda) / (2 * M_PI); }
double calcDampingRatio(std::complex<double> lambda) { return -lambda.real() / std::abs(lambda); }

LscfEstimator::LscfEstimator(const std::vector<double>& frequency, const std::vector<std::vector<cd>>& h,
                             const LscfOptions& options)
    : options_(options) {
  if (!(options.fMax > options.fMin && options.fMin >= 0))
    throw std::logic_error("LSCF: the band must satisfy 0 <= fMin < fMax");
  if (options.minOrder < 2 || options.maxOrder < options.minOrder)
    throw std::logic_error("LSCF: orders must satisfy 2 <= minOrder <= maxOrder");
  const auto bins = getBandBins(frequency, options.fMin, options.fMax);
  const int n = options.maxOrder;
  if (bins.size() < static_cast<size_t>(n + 2)) throw io::ResultError("LSCF: too few frequency bins in the band: widen processing.band_hz or record longer hits");
  dt_ = 1.0 / (2 * options.fMax);
  r_ = Eigen::VectorXd::Zero(n + 1);
  for (size_t k : bins) {
    const double th = 2 * M_PI * frequency[k] * dt_;
    for (int m = 0; m <= n; ++m) r_[m] += std::cos(m * th);
  }
  for (const auto& hc : h) {
    double rms = 0;
    for (size_t k : bins) rms += std::norm(hc[k]);
    rms = std::sqrt(rms / bins.size());
    if (rms == 0) rms = 1;  // a dead channel adds nothing
    Eigen::VectorXd s = Eigen::VectorXd::Zero(2 * n + 1), t = Eigen::VectorXd::Zero(2 * n + 1);
    for (size_t k : bins) {
      const double th = 2 * M_PI * frequency[k] * dt_;
      const cd hk = hc[k] / rms;
      for (int m = -n; m <= n; ++m) {
        const cd om = std::polar(1.0, m * th);
        s[m + n] -= (hk * om).real();
        t[m + n] += std::norm(hk) * om.real();
      }
    }
    s_.push_back(s);
    t_.push_back(t);
  }
}

std::vector<cd> LscfEstimator::calcRawPoles(int p) const {
  const int n = options_.maxOrder;
  if (p < 1 || p > n) throw std::logic_error("LSCF: order out of range");
  Eigen::MatrixXd R(p + 1, p + 1);
  for (int j = 0; j <= p; ++j)
    for (int l = 0; l <= p; ++l) R(j, l) = r_[std::abs(l - j)];
  const auto Rf = R.ldlt();
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(p + 1, p + 1);
  for (size_t o = 0; o < s_.size(); ++o) {
    Eigen::MatrixXd S(p + 1, p + 1), T(p + 1, p + 1);
    for (int j = 0; j <= p; ++j)
      for (int l = 0; l <= p; ++l) {
        S(j, l) = s_[o][l - j + n];
        T(j, l) = t_[o][l - j + n];
      }
    M += T - S.transpose() * Rf.solve(S);
  }
  // Monic denominator (alpha_p = 1): M[0:p,0:p] alpha = -M[0:p,p].
  const Eigen::VectorXd alpha = M.topLeftCorner(p, p).colPivHouseholderQr().solve(-M.col(p).head(p));
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(p, p);
  for (int i = 1; i < p; ++i) C(i, i - 1) = 1;
  for (int i = 0; i < p; ++i) C(i, p - 1) = -alpha[i];
  const Eigen::VectorXcd z = Eigen::EigenSolver<Eigen::MatrixXd>(C, false).eigenvalues();
  std::vector<cd> poles;
  for (int i = 0; i < z.size(); ++i) {
    if (std::abs(z[i]) == 0) continue;
    const cd lambda = std::log(z[i]) / dt_;
    const double fd = lambda.imag() / (2 * M_PI);
    if (lambda.imag() > 0 && lambda.real() < 0 && fd >= options_.fMin && fd <= options_.fMax &&
        calcDampingRatio(lambda) < options_.maxDampingRatio)
      poles.push_back(lambda);
  }
  std::sort(poles.begin(), poles.end(), [](cd a, cd b) { return a.imag() < b.imag(); });
  return poles;
}

std::vector<StabilisationPole> calcStabilisationDiagram(const LscfEstimator& estimator) {
  const auto& o = estimator.getOptions();
  std::vector<StabilisationPole> all, previous;
  for (int p = o.minOrder; p <= o.maxOrder; ++p) {
    std::vector<StabilisationPole> current;
    for (const cd raw : estimator.calcRawPoles(p)) {
      StabilisationPole sp;
      sp.order = p;
      sp.rawLambda = raw;
      const cd corrected = raw + o.windowDecayRate;
      sp.frequencyHz = calcNaturalFrequencyHz(corrected);
      sp.dampingRatio = calcDampingRatio(corrected);
      const StabilisationPole* best = nullptr;
      for (const auto& q : previous)
        if (!best || std::abs(q.frequencyHz - sp.frequencyHz) < std::abs(best->frequencyHz - sp.frequencyHz)) best = &q;
      if (best) {
        sp.stableFrequency = std::abs(best->frequencyHz - sp.frequencyHz) < o.frequencyTolerance * sp.frequencyHz;
        const double zr = calcDampingRatio(raw), zq = calcDampingRatio(best->rawLambda);
        sp.stableDamping = sp.stableFrequency && std::abs(zr - zq) < o.dampingTolerance * zr;
      }
      current.push_back(sp);
    }
    all.insert(all.end(), current.begin(), current.end());
    previous = std::move(current);
  }
  return all;
}

namespace {

// Greedy clusters of the poles stable in frequency and damping, in ascending frequency: a pole joins the
// current cluster if within clusterTolerance of the cluster mean.
std::vector<std::vector<StabilisationPole>> clusterStablePoles(const std::vector<StabilisationPole>& diagram,
                                                               double clusterTolerance) {
  std::vector<StabilisationPole> stable;
  for (const auto& p : diagram)
    if (p.stableDamping) stable.push_back(p);
  std::sort(stable.begin(), stable.end(),
            [](const StabilisationPole& a, const StabilisationPole& b) { return a.frequencyHz < b.frequencyHz; });
  std::vector<std::vector<StabilisationPole>> clusters;
  double mean = 0;
  for (const auto& p : stable) {
    if (clusters.empty() || std::abs(p.frequencyHz - mean) > clusterTolerance * mean) {
      clusters.push_back({p});
      mean = p.frequencyHz;
    } else {
      clusters.back().push_back(p);
      mean += (p.frequencyHz - mean) / clusters.back().size();
    }
  }
  return clusters;
}

// One pole per order (the nearest to the cluster median) summarised as a mode estimate.
ModalEstimate summariseCluster(const std::vector<StabilisationPole>& cluster) {
  std::vector<double> fs;
  for (const auto& p : cluster) fs.push_back(p.frequencyHz);
  const double fMed = calcMedian(fs);
  std::map<int, StabilisationPole> perOrder;
  for (const auto& p : cluster) {
    auto it = perOrder.find(p.order);
    if (it == perOrder.end() || std::abs(p.frequencyHz - fMed) < std::abs(it->second.frequencyHz - fMed))
      perOrder[p.order] = p;
  }
  std::vector<double> f, z;
  for (const auto& [order, p] : perOrder) f.push_back(p.frequencyHz), z.push_back(p.dampingRatio);
  ModalEstimate m;
  m.frequencyHz = calcMedian(f);
  m.dampingRatio = calcMedian(z);
  m.frequencyScatterHz = calcRobustSpread(f);
  m.dampingScatter = calcRobustSpread(z);
  m.count = static_cast<int>(perOrder.size());
  const StabilisationPole* rep = nullptr;
  for (const auto& [order, p] : perOrder)
    if (!rep || std::abs(p.frequencyHz - m.frequencyHz) < std::abs(rep->frequencyHz - m.frequencyHz)) rep = &p;
  m.order = rep->order;
  m.rawLambda = rep->rawLambda;
  return m;
}

}  // namespace

size_t calcRequiredStableOrders(const LscfOptions& o) {
  const int nOrders = o.maxOrder - o.minOrder + 1;
  return std::max<size_t>(2, static_cast<size_t>(std::ceil(o.minStableFraction * nOrders)));
}

std::vector<ModalEstimate> selectStableModes(const std::vector<StabilisationPole>& diagram, const LscfOptions& o,
                                            std::vector<ModalEstimate>* rejected) {
  std::vector<ModalEstimate> modes;
  for (const auto& c : clusterStablePoles(diagram, o.clusterTolerance)) {
    const ModalEstimate m = summariseCluster(c);
    // A passive structure has positive damping; <= 0 after removing the window is resolution-limited.
    if (static_cast<size_t>(m.count) >= calcRequiredStableOrders(o) && m.dampingRatio > 0)
      modes.push_back(m);
    else if (rejected)
      rejected->push_back(m);
  }
  return modes;
}

double calcJackknifeSpread(const std::vector<double>& v) {
  if (v.size() < 2) return 0;
  double mean = 0, s = 0;
  for (double x : v) mean += x / v.size();
  for (double x : v) s += (x - mean) * (x - mean);
  return std::sqrt((v.size() - 1.0) / v.size() * s);
}

std::vector<std::pair<double, double>> calcJackknifeStdErr(const FrfEstimate& frf, const LscfOptions& options,
                                                           const std::vector<ModalEstimate>& modes) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const size_t nHits = frf.forceSpectra.size();
  std::vector<std::pair<double, double>> out(modes.size(), {nan, nan});
  if (nHits < 3) return out;
  std::vector<std::vector<double>> fs(modes.size()), zs(modes.size());
  for (size_t i = 0; i < nHits; ++i) {
    std::vector<bool> use(nHits, true);
    use[i] = false;
    std::vector<std::vector<cd>> h;
    calcH1FromSpectra(frf, use, h);
    const LscfEstimator est(frf.frequency, h, options);
    std::map<int, std::vector<cd>> cache;
    for (size_t m = 0; m < modes.size(); ++m) {
      auto it = cache.find(modes[m].order);
      if (it == cache.end()) it = cache.emplace(modes[m].order, est.calcRawPoles(modes[m].order)).first;
      double bestF = nan, bestZ = nan;
      const double tol = std::max(options.clusterTolerance * modes[m].frequencyHz, 2 * frf.df);
      for (const cd raw : it->second) {
        const cd c = raw + options.windowDecayRate;
        const double f = calcNaturalFrequencyHz(c);
        if (std::abs(f - modes[m].frequencyHz) < tol &&
            (std::isnan(bestF) || std::abs(f - modes[m].frequencyHz) < std::abs(bestF - modes[m].frequencyHz)))
          bestF = f, bestZ = calcDampingRatio(c);
      }
      if (!std::isnan(bestF)) fs[m].push_back(bestF), zs[m].push_back(bestZ);
    }
  }
  for (size_t m = 0; m < modes.size(); ++m) {
    if (fs[m].size() == nHits) out[m] = {calcJackknifeSpread(fs[m]), calcJackknifeSpread(zs[m])};
  }
  return out;
}

std::complex<double> ModalModel::evaluate(double f) const {
  const cd iw(0, 2 * M_PI * f);
  cd h = upperResidual;
  if (f > 0) h -= lowerResidual / std::pow(2 * M_PI * f, 2);
  for (size_t r = 0; r < poles.size(); ++r)
    h += residues[r] / (iw - poles[r]) + std::conj(residues[r]) / (iw - std::conj(poles[r]));
  return h;
}

ModalModel fitModalModel(const std::vector<double>& frequency, const std::vector<cd>& h, double fMin, double fMax,
                         const std::vector<cd>& rawPoles, bool relativeWeighting) {
  const auto bins = getBandBins(frequency, fMin, fMax);
  const int np = static_cast<int>(rawPoles.size()), nc = 2 * np + 2;
  if (bins.size() * 2 < static_cast<size_t>(nc)) throw io::ResultError("LSFD: too few frequency bins in the band for the poles: widen processing.band_hz or record longer hits");
  Eigen::MatrixXd A(2 * bins.size(), nc);
  Eigen::VectorXd b(2 * bins.size());
  for (size_t i = 0; i < bins.size(); ++i) {
    const double w = 2 * M_PI * frequency[bins[i]];
    const cd iw(0, w);
    std::vector<cd> col(nc);
    for (int r = 0; r < np; ++r) {
      const cd a = 1.0 / (iw - rawPoles[r]), c = 1.0 / (iw - std::conj(rawPoles[r]));
      col[2 * r] = a + c;
      col[2 * r + 1] = cd(0, 1) * (a - c);
    }
    col[2 * np] = 1.0;
    col[2 * np + 1] = -1.0 / (w * w);
    const double wt = relativeWeighting ? 1.0 / std::max(std::abs(h[bins[i]]), 1e-300) : 1.0;
    for (int j = 0; j < nc; ++j) A(2 * i, j) = wt * col[j].real(), A(2 * i + 1, j) = wt * col[j].imag();
    b[2 * i] = wt * h[bins[i]].real();
    b[2 * i + 1] = wt * h[bins[i]].imag();
  }
  const Eigen::VectorXd scale = A.colwise().norm().transpose().cwiseMax(1e-300);
  const Eigen::VectorXd x = (A * scale.cwiseInverse().asDiagonal()).colPivHouseholderQr().solve(b).cwiseQuotient(scale);
  ModalModel m;
  m.poles = rawPoles;
  for (int r = 0; r < np; ++r) m.residues.emplace_back(x[2 * r], x[2 * r + 1]);
  m.upperResidual = x[2 * np];
  m.lowerResidual = x[2 * np + 1];
  return m;
}

}  // namespace motostab::modal
