#include "analysis/modes.h"

#include "core/parallel.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace motostab::analysis {

using core::runParallel;


bool isComplianceCoordinate(const std::string& name) {
  auto starts = [&](const char* p) { return name.rfind(p, 0) == 0; };
  return starts("swingarm") || starts("fork_bending") || starts("fork_torsion") || starts("rider_lean");
}

DofGroup getDofGroup(const std::string& name) {
  auto starts = [&](const char* p) { return name.rfind(p, 0) == 0; };
  if (starts("roll")) return DofGroup::Roll;
  if (starts("steer")) return DofGroup::Steer;
  if (starts("yaw")) return DofGroup::Yaw;
  if (name == "y" || name == "vy") return DofGroup::Lateral;
  if (starts("pitch")) return DofGroup::Pitch;
  if (name == "height" || name == "vz") return DofGroup::Bounce;
  if (isComplianceCoordinate(name)) return DofGroup::Compliance;
  if (starts("suspension")) return DofGroup::Suspension;
  if (name == "x" || name == "vx" || name.find("wheel_angle") != std::string::npos) return DofGroup::Forward;
  return DofGroup::Relaxation;
}

namespace {
std::string coordinateOf(const LinearState& s) {
  const std::string& n = s.name;
  if (n.size() > 5 && n.compare(n.size() - 5, 5, "_rate") == 0) return n.substr(0, n.size() - 5);
  if (n == "vx") return "x";
  if (n == "vy") return "y";
  if (n == "vz") return "height";
  return n;
}
}  // namespace

namespace {

bool hasSameStates(const LinearModel& a, const LinearModel& b) {
  if (a.states.size() != b.states.size()) return false;
  for (size_t i = 0; i < a.states.size(); ++i)
    if (a.states[i].name != b.states[i].name) return false;
  return true;
}

// What each state of a linear model contributes to mode content: its group and how to weigh it.
struct StateWeights {
  std::vector<int> group;         // DofGroup, or -1: skipped (a rate whose coordinate is kept, wheel spin)
  std::vector<char> isRate;       // divided by max(1, |lambda|)
  std::vector<char> perWheelbase; // lateral and forward displacements, divided by the wheelbase
  std::vector<int> compliance;    // indices of compliance coordinates (isComplianceCoordinate)
};

StateWeights calcStateWeights(const LinearModel& lin) {
  StateWeights w;
  const size_t n = lin.states.size();
  w.group.resize(n);
  w.isRate.resize(n);
  w.perWheelbase.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const LinearState& st = lin.states[i];
    const std::string coordinate = coordinateOf(st);
    const DofGroup g = getDofGroup(coordinate);
    w.group[i] = static_cast<int>(g);
    w.isRate[i] = st.entry.slot == Slot::U;
    w.perWheelbase[i] = g == DofGroup::Lateral || g == DofGroup::Forward;
    // A rate whose coordinate is kept counts through it; wheel spin follows pitch and tyre slip and
    // says nothing about the mode's character.
    if (st.entry.slot == Slot::U && (lin.findState(coordinate) >= 0 || st.name.find("wheel_angle") != std::string::npos))
      w.group[i] = -1;
    if (st.entry.slot == Slot::Q && isComplianceCoordinate(st.name)) w.compliance.push_back(static_cast<int>(i));
  }
  return w;
}

ModeContent calcModeContent(const LinearModel& lin, int k, double wheelbase, const StateWeights& w) {
  ModeContent c{};
  const double rateScale = std::max(1.0, std::abs(lin.eigenvalues[k]));
  for (size_t i = 0; i < w.group.size(); ++i) {
    if (w.group[i] < 0) continue;
    double scale = 1.0;  // squared magnitudes: no hypot
    if (w.isRate[i]) scale *= rateScale;
    if (w.perWheelbase[i]) scale *= wheelbase;
    c[w.group[i]] += std::norm(lin.eigenvectors(i, k)) / (scale * scale);
  }
  double sum = 0;
  for (double v : c) sum += v;
  if (sum > 0)
    for (double& v : c) v /= sum;
  return c;
}

}  // namespace

ModeContent calcModeContent(const LinearModel& lin, int k, double wheelbase) {
  return calcModeContent(lin, k, wheelbase, calcStateWeights(lin));
}

double calcMac(const LinearModel& a, int ka, const LinearModel& b, int kb) {
  std::complex<double> dot = 0;
  double na = 0, nb = 0;
  for (size_t i = 0; i < a.states.size(); ++i) {
    // Same layout at the same speed grid is the rule; look names up only when it differs.
    const int j = (i < b.states.size() && b.states[i].name == a.states[i].name) ? static_cast<int>(i)
                                                                                : b.findState(a.states[i].name);
    if (j < 0) continue;
    const auto x = a.eigenvectors(i, ka), y = b.eigenvectors(j, kb);
    dot += std::conj(x) * y;
    na += std::norm(x);
    nb += std::norm(y);
  }
  return (na > 0 && nb > 0) ? std::norm(dot) / (na * nb) : 0.0;
}

double calcMatchCost(double distance, double absA, double absB, double mac) {
  // Eigenvalue proximity dominates; MAC separates modes that pass close to each other.
  return distance / (1.0 + 0.5 * (absA + absB)) + 0.2 * (1.0 - mac);
}

double calcMatchCost(std::complex<double> la, std::complex<double> lb, double mac) {
  return calcMatchCost(std::abs(la - lb), std::abs(la), std::abs(lb), mac);
}

double calcMatchCost(const LinearModel& a, int ka, const LinearModel& b, int kb) {
  return calcMatchCost(a.eigenvalues[ka], b.eigenvalues[kb], calcMac(a, ka, b, kb));
}

int findBestMatch(const LinearModel& a, int ka, const LinearModel& b) {
  int best = -1;
  double bestCost = std::numeric_limits<double>::infinity();
  for (int kb = 0; kb < b.eigenvalues.size(); ++kb) {
    const double c = calcMatchCost(a, ka, b, kb);
    if (c < bestCost) bestCost = c, best = kb;
  }
  return best;
}


namespace {

// Share of the in-plane content above which the rear suspension coordinate makes a mode rear_hop.
constexpr double kRearHopShare = 0.9;


struct BranchStats {
  ModeContent content{};        // mean over speeds
  double oscillatory = 0;       // fraction of speeds with a complex eigenvalue
  double wobbleLike = 0;        // fraction of oscillatory speeds: steer-led and above 4 Hz
  bool neutral = true;
  std::map<std::string, double> compliance;
};

BranchStats calcBranchStats(const std::vector<LinearModel>& models, const std::vector<const StateWeights*>& weights,
                            double wheelbase, const ModeBranch& br) {
  BranchStats st;
  const double n = static_cast<double>(models.size());
  double osc = 0;
  const StateWeights* shareLayout = nullptr;
  size_t shareModel = 0;  // a model with shareLayout, for the names
  std::vector<double> shares;
  auto flushShares = [&]() {
    for (size_t c = 0; c < shares.size(); ++c) st.compliance[models[shareModel].states[shareLayout->compliance[c]].name] += shares[c];
    shares.clear();
  };
  for (size_t s = 0; s < models.size(); ++s) {
    const std::complex<double> l = br.eigenvalue[s];
    const ModeContent c = calcModeContent(models[s], br.index[s], wheelbase, *weights[s]);
    for (int g = 0; g < kNumDofGroups; ++g) st.content[g] += c[g] / n;
    const double inPlaneOrLateral = 1.0 - c[int(DofGroup::Forward)] - c[int(DofGroup::Yaw)] - c[int(DofGroup::Lateral)];
    if (!(std::abs(l) < 1e-6 && inPlaneOrLateral < 1e-3)) st.neutral = false;
    // Compliance shares (isComplianceCoordinate), summed per layout and named once.
    if (weights[s] != shareLayout) {
      flushShares();
      shareLayout = weights[s], shareModel = s;
      shares.assign(shareLayout->compliance.size(), 0.0);
    }
    for (size_t c = 0; c < shares.size(); ++c) shares[c] += std::norm(models[s].eigenvectors(shareLayout->compliance[c], br.index[s]));
    if (std::abs(l.imag()) > 1e-9 * std::max(1.0, std::abs(l))) {
      ++osc;
      const double steer = c[int(DofGroup::Steer)];
      if (std::abs(l.imag()) / (2 * M_PI) > 4.0 && steer > 0.4 && steer > c[int(DofGroup::Roll)]) st.wobbleLike += 1;
    }
  }
  flushShares();
  st.oscillatory = osc / n;
  st.wobbleLike = osc > 0 ? st.wobbleLike / osc : 0;
  return st;
}

}  // namespace

// Labels from content (seed sec. 4 mode names): neutral, swingarm_*, bounce, pitch, rear_hop (rear
// wheel hop: the rear suspension angle carries over 90 % of the in-plane content), relaxation,
// wobble, weave, capsize, castor, other. Weave and wobble keep only their best pair, capsize and
// castor their best branch; the rest become `other`.
void labelBranches(const std::vector<LinearModel>& models, double wheelbase, std::vector<ModeBranch>& branches,
                   int threads) {
  // State weights once per state layout (a sweep has one).
  std::vector<StateWeights> layouts;
  std::vector<const StateWeights*> weights(models.size());
  std::vector<size_t> layoutOf;
  for (size_t s = 0; s < models.size(); ++s) {
    if (s == 0 || !hasSameStates(models[s], models[s - 1])) layouts.push_back(calcStateWeights(models[s]));
    layoutOf.push_back(layouts.size() - 1);
  }
  for (size_t s = 0; s < models.size(); ++s) weights[s] = &layouts[layoutOf[s]];
  std::vector<BranchStats> stats(branches.size());
  runParallel(branches.size(), threads,
              [&](size_t b) { stats[b] = calcBranchStats(models, weights, wheelbase, branches[b]); });
  std::map<std::string, std::vector<std::pair<double, size_t>>> candidates;
  for (size_t b = 0; b < branches.size(); ++b) {
    ModeBranch& br = branches[b];
    const BranchStats& st = stats[b];
    const ModeContent& c = st.content;
    const double roll = c[int(DofGroup::Roll)], steer = c[int(DofGroup::Steer)];
    const double lateral = roll + steer + c[int(DofGroup::Yaw)] + c[int(DofGroup::Lateral)];
    const double bounce = c[int(DofGroup::Bounce)], pitch = c[int(DofGroup::Pitch)];
    const double suspension = c[int(DofGroup::Suspension)];
    const double inPlane = bounce + pitch + suspension;
    const bool oscillatory = st.oscillatory >= 0.5;
    br.label = "other";
    if (st.neutral) {
      br.label = "neutral";
    } else if (oscillatory && c[int(DofGroup::Compliance)] > 0.5 * (1.0 - c[int(DofGroup::Relaxation)])) {
      // Compliance leads the mechanical content (tyre lag states excluded).
      const auto top = std::max_element(st.compliance.begin(), st.compliance.end(),
                                        [](const auto& a, const auto& b) { return a.second < b.second; });
      br.label = top->first;
    } else if (oscillatory && inPlane > 0.5) {
      // Wheel hop: the arm swings on spring and tyre while the rear frame hardly moves. In the
      // sprung modes the suspension deflects as much as the frame moves (up to about 80 %).
      br.label = suspension > kRearHopShare * inPlane ? "rear_hop" : bounce >= pitch ? "bounce" : "pitch";
    } else if (oscillatory && st.wobbleLike > 0.5) {
      candidates["wobble"].push_back({steer, b});
    } else if (c[int(DofGroup::Relaxation)] > 0.5) {
      br.label = "relaxation";
    } else if (oscillatory && lateral > 0.3) {
      candidates["weave"].push_back({lateral, b});
    } else if (!oscillatory && lateral > 0.3) {
      if (roll >= steer) candidates["capsize"].push_back({roll, b});
      else candidates["castor"].push_back({steer, b});
    }
  }
  for (auto& [label, list] : candidates) {
    std::sort(list.begin(), list.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    const size_t keep = (label == "weave" || label == "wobble") ? 2 : 1;
    for (size_t i = 0; i < list.size(); ++i) branches[list[i].second].label = i < keep ? label : "other";
  }
}

Eigen::MatrixXd calcMatchCosts(const LinearModel& prev, const LinearModel& cur) {
  const int n = static_cast<int>(prev.eigenvalues.size()), m = static_cast<int>(cur.eigenvalues.size());
  Eigen::MatrixXd c(n, m);
  if (!hasSameStates(prev, cur)) {
    for (int kp = 0; kp < n; ++kp)
      for (int k = 0; k < m; ++k) c(kp, k) = calcMatchCost(prev, kp, cur, k);
    return c;
  }
  // Same state layout (a sweep's rule): every MAC at once from a^H b for all eigenvector pairs, in
  // real arithmetic: [Re a; Im a]^T [Re b; Im b] + i [Re a; Im a]^T [Im b; -Re b] (two real
  // products, which vectorise; the complex one does not), normalised afterwards.
  const int rows = static_cast<int>(prev.eigenvectors.rows());
  Eigen::MatrixXd p(2 * rows, n), b(2 * rows, m), bi(2 * rows, m);
  p << prev.eigenvectors.real(), prev.eigenvectors.imag();
  b << cur.eigenvectors.real(), cur.eigenvectors.imag();
  bi << cur.eigenvectors.imag(), -cur.eigenvectors.real();
  const Eigen::MatrixXd re = p.transpose() * b, im = p.transpose() * bi;
  const Eigen::VectorXd np = p.colwise().squaredNorm(), nc = b.colwise().squaredNorm();
  const Eigen::MatrixXd mac = (re.cwiseAbs2() + im.cwiseAbs2()).array() / (np * nc.transpose()).array();
  const Eigen::VectorXd absPrev = prev.eigenvalues.cwiseAbs(), absCur = cur.eigenvalues.cwiseAbs();
  for (int kp = 0; kp < n; ++kp)
    for (int k = 0; k < m; ++k)
      c(kp, k) = calcMatchCost(std::sqrt(std::norm(prev.eigenvalues[kp] - cur.eigenvalues[k])), absPrev[kp], absCur[k],
                               mac(kp, k));
  return c;
}

std::vector<ModeBranch> trackModes(const std::vector<LinearModel>& models, double wheelbase, int threads,
                                   std::vector<Eigen::MatrixXd> costs) {
  std::vector<ModeBranch> branches;
  if (models.empty()) return branches;
  const int n = static_cast<int>(models[0].eigenvalues.size());
  for (const auto& m : models)
    if (m.eigenvalues.size() != n) throw std::runtime_error("trackModes: model size changed with speed");
  // Match costs between every pair of consecutive speeds not given, independent of the
  // assignment: in parallel.
  costs.resize(models.size());
  runParallel(models.size() - 1, threads, [&](size_t i) {
    if (costs[i + 1].rows() != n || costs[i + 1].cols() != n) costs[i + 1] = calcMatchCosts(models[i], models[i + 1]);
  });
  branches.resize(n);
  for (int k = 0; k < n; ++k) {
    branches[k].index.push_back(k);
    branches[k].eigenvalue.push_back(models[0].eigenvalues[k]);
  }
  for (size_t s = 1; s < models.size(); ++s) {
    // Greedy assignment on ascending cost; when every branch's cheapest match is distinct, greedy
    // takes exactly those.
    std::vector<int> assigned(n, -1);
    std::vector<bool> taken(n, false);
    bool distinct = true;
    for (int b = 0; b < n; ++b) {
      const int kp = branches[b].index.back();
      double best = std::numeric_limits<double>::infinity();
      bool finite = true;  // NaN must not reach the sort below
      for (int k = 0; k < n; ++k) {
        const double cost = costs[s](kp, k);
        finite = finite && std::isfinite(cost);
        if (cost < best) best = cost, assigned[b] = k;
      }
      if (!finite || assigned[b] < 0) throw std::runtime_error("trackModes: non-finite eigenvalues or eigenvectors at speed index " +
                                                     std::to_string(s));
      distinct = distinct && !taken[assigned[b]];
      taken[assigned[b]] = true;
    }
    if (!distinct) {
      std::vector<std::tuple<double, int, int>> pairs;
      pairs.reserve(n * n);
      for (int b = 0; b < n; ++b)
        for (int k = 0; k < n; ++k) pairs.emplace_back(costs[s](branches[b].index.back(), k), b, k);
      std::sort(pairs.begin(), pairs.end());
      std::fill(assigned.begin(), assigned.end(), -1);
      std::fill(taken.begin(), taken.end(), false);
      for (const auto& [cost, b, k] : pairs)
        if (assigned[b] < 0 && !taken[k]) assigned[b] = k, taken[k] = true;
    }
    for (int b = 0; b < n; ++b) {
      branches[b].index.push_back(assigned[b]);
      branches[b].eigenvalue.push_back(models[s].eigenvalues[assigned[b]]);
    }
  }
  labelBranches(models, wheelbase, branches, threads);
  return branches;
}

}  // namespace motostab::analysis
