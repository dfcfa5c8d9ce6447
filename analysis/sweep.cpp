#include "analysis/sweep.h"

#include "analysis/state_function.h"

#include "core/parallel.h"
#include "io/csv.h"
#include "io/result_error.h"

#include <cmath>
#include <functional>
#include <algorithm>
#include <atomic>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>

namespace motostab::analysis {

using core::runWorkers;
using vehicle::VehicleModel;

std::vector<double> makeSpeedGrid(double start, double stop, double step) {
  std::string why;
  const long n = scenario::countSpeeds(start, stop, step, why);
  if (!why.empty())
    throw std::logic_error("speed grid " + std::to_string(start) + ":" + std::to_string(stop) + ":" +
                                std::to_string(step) + ": " + why);
  std::vector<double> v;
  for (long i = 0; i < n; ++i) v.push_back(start + i * step);
  return v;
}

namespace {

// A warm start at speed v (m/s) from the linear interpolation in speed of the sweep's trims at indices
// k and k + 1, without predictor data (slopes, curvature).
TrimResult interpolateTrims(const VehicleModel& model, const SweepResult& sweep, size_t k, double v) {
  const TrimPoint &a = sweep.trims[k], &b = sweep.trims[k + 1];
  const double w = (v - sweep.speeds[k]) / (sweep.speeds[k + 1] - sweep.speeds[k]);
  TrimPoint start = a;
  start.y += w * (b.y - a.y);
  start.inputs += w * (b.inputs - a.inputs);
  start.speed = v;
  start.unknownsPerSpeed.resize(0), start.unknownsCurvature.resize(0), start.jacobianPerSpeed.resize(0, 0);
  return restoreTrim(model, start);
}

// The trim at speed v between the grid speeds of indices k and k + 1 (m/s), for refining a crossing:
// warm from the trim at k with its predictor; where that fails, from the linear interpolation of the two
// bracketing trims (both converged; it starts O(dv^2) from their branch); where that fails too, by
// continuation in speed from the nearer of them, in 2, 4, ..., 64 equal steps. Throws the first TrimError.
TrimResult trimBetween(const VehicleModel& model, const SweepResult& sweep, size_t k, double v, const TrimOptions& opt) {
  TrimResult trim = restoreTrim(model, sweep.trims[k]);
  try {
    updTrim(model, v, opt, trim);
    return trim;
  } catch (const TrimError& first) {
    if (k + 1 >= sweep.trims.size()) throw;
    try {
      trim = interpolateTrims(model, sweep, k, v);
      updTrim(model, v, opt, trim);
      return trim;
    } catch (const TrimError&) {
    }
    const size_t g = v - sweep.speeds[k] <= sweep.speeds[k + 1] - v ? k : k + 1;
    for (int steps = 2; steps <= 64; steps *= 2) {
      try {
        trim = restoreTrim(model, sweep.trims[g]);
        trim.unknownsPerSpeed.resize(0), trim.unknownsCurvature.resize(0), trim.jacobianPerSpeed.resize(0, 0);
        for (int i = 1; i <= steps; ++i) updTrim(model, sweep.speeds[g] + (v - sweep.speeds[g]) * i / steps, opt, trim);
        return trim;
      } catch (const TrimError&) {
      }
    }
    throw first;
  }
}

// The linear model at speed v, trimmed from the sweep's trims at speed index k and k + 1 (trimBetween).
LinearModel linearizeFrom(const VehicleModel& model, const SweepResult& sweep, size_t k, double v, const SweepOptions& opt,
                          bool withLabels) {
  TrimResult trim = trimBetween(model, sweep, k, v, opt.trim);
  LinearizeOptions linearize = opt.linearize;
  linearize.labelModes = withLabels;
  return linearizeInPlace(model, trim, linearize);
}

// The roots of lin below its noise (labelModes' neutral threshold) count as zero.
double calcZeroRoot(const LinearModel& lin) { return std::max(1e-6, 1e-9 * lin.A.cwiseAbs().rowwise().sum().maxCoeff()); }

// Eigenvalues of lin with a positive real part, the zero roots excepted.
int countUnstable(const LinearModel& lin) {
  const double zero = calcZeroRoot(lin);
  int n = 0;
  for (Eigen::Index k = 0; k < lin.eigenvalues.size(); ++k) n += lin.eigenvalues[k].real() > 0 && std::abs(lin.eigenvalues[k]) >= zero;
  return n;
}

}  // namespace

RootAtSpeed calcBranchRoot(const VehicleModel& model, const SweepResult& sweep, const ModeBranch& branch, size_t k,
                           double v, const SweepOptions& opt, bool withLabel) {
  const LinearModel lin = linearizeFrom(model, sweep, k, v, opt, withLabel);
  const int kb = findBestMatch(sweep.models[k], branch.index[k], lin);
  return {lin.eigenvalues[kb], withLabel ? std::optional<ModeLabel>(lin.labels[kb]) : std::nullopt};
}

double calcBranchRealPart(const VehicleModel& model, const SweepResult& sweep, const ModeBranch& branch, size_t k,
                          double v, const SweepOptions& opt) {
  return calcBranchRoot(model, sweep, branch, k, v, opt, false).lambda.real();
}

namespace {

// Brent's method (Brent 1973, ch. 4) for f(a) f(b) <= 0.
double findRoot(const std::function<double(double)>& f, double a, double b, double fa, double fb, double tol) {
  double c = a, fc = fa, d = b - a, e = d;
  for (int it = 0; it < 200; ++it) {
    if (fb * fc > 0) c = a, fc = fa, d = e = b - a;
    if (std::abs(fc) < std::abs(fb)) a = b, b = c, c = a, fa = fb, fb = fc, fc = fa;
    const double tol1 = 2 * 2.2e-16 * std::abs(b) + 0.5 * tol, m = 0.5 * (c - b);
    if (std::abs(m) <= tol1 || fb == 0) return b;
    if (std::abs(e) >= tol1 && std::abs(fa) > std::abs(fb)) {
      double p, q, r, s = fb / fa;
      if (a == c) {
        p = 2 * m * s, q = 1 - s;
      } else {
        q = fa / fc, r = fb / fc;
        p = s * (2 * m * q * (q - r) - (b - a) * (r - 1));
        q = (q - 1) * (r - 1) * (s - 1);
      }
      if (p > 0) q = -q; else p = -p;
      if (2 * p < std::min(3 * m * q - std::abs(tol1 * q), std::abs(e * q))) e = d, d = p / q;
      else d = m, e = m;
    } else {
      d = m, e = m;
    }
    a = b, fa = fb;
    b += (std::abs(d) > tol1) ? d : (m > 0 ? tol1 : -tol1);
    fb = f(b);
  }
  return b;
}

// The speeds of a sweep shared among its workers. Warm-started chains of speeds: on a span shared by
// two workers one goes up and the other down from its top, each taking the next speed until they
// meet, so that within a span neither waits for the other whatever the cost per speed (where they
// meet depends on timing: threaded results agree with the serial sweep to the trim tolerance, not to
// the bit). The lead (worker 0) starts at the first speed of at least 1 m/s, sweeps down to its
// span's bottom, then turns and goes up.
struct Span {
  std::mutex lock;
  size_t lo = 0, hi = 0;  // speeds [lo, hi) not yet taken
};

struct SweepPlan {
  size_t n = 0, workers = 1;
  std::vector<Span> spans;
  size_t leadFirst = 0;    ///< the lead's first speed
  bool leadTurns = false;  ///< else worker 0 just goes up from 0
  size_t leadDown = 0;     ///< speeds leadFirst, ..., 0 before the turn
};

SweepPlan planSweep(const std::vector<double>& speeds, int threads) {
  SweepPlan p;
  p.n = speeds.size();
  p.workers = std::max<size_t>(1, std::min<size_t>(static_cast<size_t>(std::max(1, threads)), p.n));
  p.spans = std::vector<Span>((p.workers + 1) / 2);
  for (size_t k = 0; k < p.spans.size(); ++k)  // shares of the speeds: two per two-worker span
    p.spans[k].lo = p.n * std::min(2 * k, p.workers) / p.workers,
    p.spans[k].hi = p.n * std::min(2 * k + 2, p.workers) / p.workers;
  p.leadFirst = static_cast<size_t>(std::find_if(speeds.begin(), speeds.end(), [](double v) { return v >= 1.0; }) -
                                    speeds.begin());
  p.leadTurns = p.leadFirst < p.spans[0].hi;
  p.leadDown = p.leadTurns ? p.leadFirst + 1 : 0;
  if (p.leadTurns) p.spans[0].lo = p.leadFirst + 1;
  return p;
}

// A lateral group's one-evaluation column may differ from the central one by this fraction of each
// row's scale (checkMirrorSymmetry); symmetric vehicles show 1e-16 or less.
constexpr double kMirrorTolerance = 1e-8;

// One sweep in progress: the chains of trims and linearisations, shared by the workers.
class SweepRun {
 public:
  SweepRun(const VehicleModel& model, std::vector<double> speeds, const SweepOptions& opt)
      : model_(model), opt_(opt), fixed_(opt) {
    out_.speeds = std::move(speeds);
    plan_ = planSweep(out_.speeds, opt.threads);
    replicas_.resize(plan_.workers);
    out_.trims.resize(plan_.n);
    out_.models.resize(plan_.n);
    costs_.resize(plan_.n);
    failed_.assign(plan_.n, std::nullopt);
  }

  // The states must not change with speed: decide on yaw once, from a reference linearisation away
  // from standstill (every speed-dependent coupling present; also a sample of the column pattern).
  // It is the lead chain's first; the other workers make their first, cold trim meanwhile (its
  // partner's, at the top speed, is the slowest) and take the reference before linearising it.
  void prepareReference() {
    const bool decideYaw = fixed_.linearize.removeYaw < 0;
    if (decideYaw && plan_.leadTurns) {
      refReady_ = refPromise_.get_future().share();
    } else if (decideYaw) {  // no speed of 1 m/s or more in the lead's span: a separate reference
      TrimResult top = calcTrim(model_, std::max(1.0, out_.speeds.back()), opt_.trim);
      ownReference_ = linearizeInPlace(model_, top, opt_.linearize);
      ref_ = &*ownReference_;
      fixed_.linearize.removeYaw = hasYaw(*ref_) ? 0 : 1;  // the sweep's states are ref's
    }
  }

  // Every chain, on the calling thread or on one worker each (a worker builds its own model replica:
  // no shared Simbody caches). A failure stops the others at their next speed and releases any wait
  // for the reference. The lead's partner takes its first speed when its span holds one; the lead computes the
  // reference before taking any shared speed.
  void runChains() {
    if (plan_.workers == 1) {
      runChain(model_, plan_.spans[0], false, true);
      return;
    }
    runWorkers(
        plan_.workers,
        [&](size_t w) {
          if (w > 0) replicas_[w] = model_.makeReplica();
          runChain(w > 0 ? *replicas_[w] : model_, plan_.spans[w / 2], w % 2 == 1, w == 0);
        },
        [&]() {
          stopped_ = true;
          settleReference(std::make_exception_ptr(std::runtime_error("sweep stopped: another worker failed")));
        });
  }

  SweepResult takeTrackedResult() {
    dropFailedSpeeds();
    checkFinite();
    out_.branches = trackModes(out_.models, opt_.threads, std::move(costs_));
    return std::move(out_);
  }
  /// The options every speed was linearised with (removeYaw decided).
  const SweepOptions& getFixedOptions() const { return fixed_; }
  /// The workers' model replicas (empty for the calling thread's worker 0), for reuse after the chains.
  std::vector<std::unique_ptr<VehicleModel>>& updReplicas() { return replicas_; }

 private:
  static bool hasYaw(const LinearModel& lin) { return lin.findState(vehicle::StateRole::Yaw, vehicle::StateKind::Coordinate) >= 0; }

  void settleReference(std::exception_ptr e) {  // once: the value, or the failure that stops the sweep
    if (!refReady_.valid() || refSettled_.exchange(true)) return;
    if (e) refPromise_.set_exception(e);
    else refPromise_.set_value();
  }

  // The next speed of a chain: the lead's way down first, then its span's from its end.
  bool takeNext(Span& sp, bool downwards, bool lead, size_t i, size_t& k) {
    if (lead && i < plan_.leadDown) {
      k = plan_.leadFirst - i;
      return !stopped_;
    }
    std::lock_guard<std::mutex> guard(sp.lock);
    if (sp.lo == sp.hi || stopped_) return false;
    k = downwards ? --sp.hi : sp.lo++;
    return true;
  }

  // A chain's first speed (or its first after failures left it without a trim): a cold trim, or the
  // warm start of the options; the lead's first success is the reference.
  void linearizeFirst(const VehicleModel& m, size_t k, bool lead, TrimResult& work, LinearizeOptions& lo) {
    if (lead && opt_.warmStart) {
      work = restoreTrim(m, *opt_.warmStart);
      work.unknownsPerSpeed.resize(0), work.unknownsCurvature.resize(0), work.jacobianPerSpeed.resize(0, 0);
      updTrim(m, out_.speeds[k], opt_.trim, work);
    } else {
      work = calcTrim(m, out_.speeds[k], opt_.trim);
    }
    const bool isReference = lead && refReady_.valid() && !refSettled_;  // removeYaw automatic
    if (refReady_.valid() && !isReference) refReady_.get();
    out_.models[k] = linearizeInPlace(m, work, isReference ? opt_.linearize : fixed_.linearize);
    if (isReference) {
      ref_ = &out_.models[k];
      fixed_.linearize.removeYaw = hasYaw(*ref_) ? 0 : 1;
      settleReference(nullptr);  // a failure reaches the waiting workers through onFirstFailure
    }
    lo = fixed_.linearize;
  }

  // Without constraints the next speed's trim Jacobian is read off this speed's A, keeping the
  // input columns of the one this trim used (a differentiated one costs two realizations per
  // unknown), and extrapolated along speed.
  void updateTrimJacobian(const VehicleModel& m, size_t k, size_t previous, bool extrapolate, TrimResult& work,
                          Eigen::MatrixXd& lastJ) {
    Eigen::MatrixXd J = calcTrimJacobian(m, out_.models[k], work.jacobian, opt_.trim);
    if (J.size() == 0) return;
    if (extrapolate && lastJ.rows() == J.rows() && lastJ.cols() == J.cols())
      work.jacobianPerSpeed = (J - lastJ) / (out_.speeds[k] - out_.speeds[previous]);
    lastJ = J;
    work.jacobian = std::move(J);
  }

  // A chain's column grouping, from its first two speeds and the reference; lateral symmetry (one
  // evaluation per lateral group) is checked at the first speed with a symmetric trim, if any.
  void updateGrouping(const VehicleModel& m, size_t k, size_t previous, bool second, TrimResult& work,
                      LinearizeOptions& lo, bool& mirrorPending) {
    if (opt_.groupColumns && second) {
      std::vector<const LinearModel*> samples{&out_.models[previous], &out_.models[k]};
      if (ref_) samples.push_back(ref_);
      lo.grouping = calcColumnGrouping(samples);
      mirrorPending = opt_.mirrorLateralColumns && !lo.grouping.mirror.empty();
    }
    if (!mirrorPending) return;
    double defect = INFINITY;  // stays infinite, without any evaluation, while the trim is not symmetric
    checkMirrorSymmetry(m, work, lo, lo.grouping, kMirrorTolerance, &defect);
    mirrorPending = !std::isfinite(defect);
  }

  // What a chain carries from speed to speed.
  struct Chain {
    LinearizeOptions lo;
    TrimResult work, turn;         // turn: the lead's first trim, from which it goes up
    Eigen::MatrixXd lastJ, turnJ;  // the previous speed's trim Jacobian read off its A
    size_t previous = 0;           // the speed `work` holds
    bool valid = false, turnValid = false;  // work (turn) holds a trim
    size_t trimmed = 0;            // speeds trimmed so far
    bool mirrorPending = false;    // lateral symmetry proposed by the grouping, not yet checked
  };

  // A turn's trim at `speed` that a chain would warm-start without a secant slope (its second speed, or
  // the first after a failure): cold instead, since the last trim alone can start Newton's method near
  // another, unstable equilibrium (a tight turn's steer is far from the next speed's: 26 deg at 4 m/s
  // and 35 deg on the supersport-mf), and the secant from `work`'s speed to it starts the predictor.
  void trimTurnCold(const VehicleModel& m, double speed, TrimResult& work) {
    const StateFunction fn(m);
    const std::vector<StateEntry> unknowns = getTrimUnknowns(m, opt_.trim);
    const int n = static_cast<int>(unknowns.size());
    Eigen::VectorXd before(n);
    for (int j = 0; j < n; ++j) before[j] = fn.get(work.state, unknowns[j]);
    const double from = work.speed;
    work = calcTrim(m, speed, opt_.trim);
    if (std::abs(speed - from) < 1e-12) return;
    work.unknownsPerSpeed.resize(n);
    for (int j = 0; j < n; ++j) work.unknownsPerSpeed[j] = (fn.get(work.state, unknowns[j]) - before[j]) / (speed - from);
    work.secantStartSpeed = from;
  }

  // Trims and linearises speed k from the chain's last trim (or cold); false (the failure recorded)
  // when the trim fails and failed speeds are kept: the chain then goes on from its last trim. A
  // warm-started trim that fails is tried once more cold (a tight turn at low speed can be too far from
  // the next speed's for Newton's method, or lead it to an equilibrium with a wheel in the air).
  bool trimAndLinearize(const VehicleModel& m, size_t k, bool lead, Chain& c) {
    try {
      if (!c.valid) {
        linearizeFirst(m, k, lead, c.work, c.lo);
      } else {
        try {
          if (opt_.trim.isTurn() && c.work.unknownsPerSpeed.size() == 0) {
            try {
              trimTurnCold(m, out_.speeds[k], c.work);
            } catch (const TrimError&) {  // the roll continuation failed there: warm after all
              updTrim(m, out_.speeds[k], opt_.trim, c.work);
            }
          } else {
            updTrim(m, out_.speeds[k], opt_.trim, c.work);
          }
        } catch (const TrimError&) {  // e.g. a warm start that found a wheel in the air: cold
          c.work = calcTrim(m, out_.speeds[k], opt_.trim);
          c.lastJ.resize(0, 0);
        }
        out_.models[k] = linearizeInPlace(m, c.work, c.lo);
      }
      return true;
    } catch (const TrimError& e) {
      if (!opt_.keepFailedSpeeds) throw;
      failed_[k] = FailedSpeed{out_.speeds[k], e.residual, e.what()};
      {
        std::lock_guard<std::mutex> hold(failureLock_);
        if (!firstError_) firstError_ = e;
      }
      if (c.valid) c.work = restoreTrim(m, out_.trims[c.previous]);  // the last trim, without its State
      c.lastJ.resize(0, 0);
      return false;
    }
  }

  // One warm-started chain: trims in place on one State (no State copies).
  void runChain(const VehicleModel& m, Span& sp, bool downwards, bool lead) {
    Chain c;
    size_t k = 0;
    for (size_t i = 0; takeNext(sp, downwards, lead, i, k); ++i) {
      if (lead && i == plan_.leadDown && plan_.leadDown > 1) {  // turn: up from the lead's first trim
        if (c.turnValid) c.work = std::move(c.turn), c.lastJ = std::move(c.turnJ), c.previous = plan_.leadFirst, c.valid = true;
      }
      const bool neighbour = c.valid && (k == c.previous + 1 || k + 1 == c.previous);
      if (!trimAndLinearize(m, k, lead, c)) continue;
      if (neighbour) {  // the match costs of this step, for the tracking
        const size_t low = std::min(k, c.previous);
        costs_[low + 1] = calcMatchCosts(out_.models[low], out_.models[low + 1]);
      }
      updateGrouping(m, k, c.previous, c.trimmed == 1 && c.valid, c.work, c.lo, c.mirrorPending);
      updateTrimJacobian(m, k, c.previous, c.valid, c.work, c.lastJ);
      out_.trims[k] = makeTrimPoint(m, c.work);
      if (lead && i == 0 && plan_.leadDown > 1) c.turn = c.work, c.turnJ = c.lastJ, c.turnValid = true;  // one State copy
      c.previous = k, c.valid = true, ++c.trimmed;
    }
    if (lead) settleReference(std::make_exception_ptr(makeNoneTrimmedError("no speed of the sweep's first chain could be trimmed")));
  }

  // `what` (no speed of some set trimmed) with the sweep's first failure; without one (no speed was tried),
  // `what` alone at the lead's first speed.
  TrimError makeNoneTrimmedError(const std::string& what) {
    std::lock_guard<std::mutex> hold(failureLock_);
    if (firstError_) return TrimError(what, *firstError_);
    return TrimError(what, out_.speeds[plan_.leadFirst], opt_.trim.roll);
  }

  // A linearised model whose roots are not finite has no modes to track: no result (exit 3), at its speed.
  void checkFinite() const {
    for (size_t k = 0; k < out_.models.size(); ++k)
      if (!out_.models[k].eigenvalues.allFinite() || !out_.models[k].eigenvectors.allFinite())
        throw io::ResultError("the linearised model at " + io::formatNumber(out_.speeds[k], 6) +
                              " m/s has eigenvalues that are not finite (parameters far outside their physical "
                              "range make its state matrix numerically singular)");
  }

  // Leaves out the speeds that failed (listed in out_.failures); the match costs kept are those of
  // speeds that stay neighbours. Throws the first failure when no speed trimmed.
  void dropFailedSpeeds() {
    std::vector<size_t> kept;
    for (size_t k = 0; k < plan_.n; ++k) {
      if (failed_[k]) out_.failures.push_back(*failed_[k]);
      else kept.push_back(k);
    }
    if (out_.failures.empty()) return;
    if (kept.empty()) throw makeNoneTrimmedError("no speed of the sweep could be trimmed");
    SweepResult kept_;
    std::vector<Eigen::MatrixXd> costs;
    for (size_t j = 0; j < kept.size(); ++j) {
      kept_.speeds.push_back(out_.speeds[kept[j]]);
      kept_.trims.push_back(std::move(out_.trims[kept[j]]));
      kept_.models.push_back(std::move(out_.models[kept[j]]));
      costs.push_back(j > 0 && kept[j] == kept[j - 1] + 1 ? std::move(costs_[kept[j]]) : Eigen::MatrixXd());
    }
    kept_.failures = std::move(out_.failures);
    out_ = std::move(kept_);
    costs_ = std::move(costs);
  }

  const VehicleModel& model_;
  const SweepOptions& opt_;
  SweepOptions fixed_;
  SweepPlan plan_;
  SweepResult out_;
  std::vector<Eigen::MatrixXd> costs_;  // costs_[k]: calcMatchCosts(models[k - 1], models[k])
  std::vector<std::optional<FailedSpeed>> failed_;  // per speed (written by the chain that took it)
  std::vector<std::unique_ptr<VehicleModel>> replicas_;  // replicas_[w]: worker w's model (w > 0)
  std::optional<LinearModel> ownReference_;
  const LinearModel* ref_ = nullptr;
  std::promise<void> refPromise_;
  std::shared_future<void> refReady_;
  std::atomic<bool> refSettled_{false}, stopped_{false};
  std::mutex failureLock_;
  std::optional<TrimError> firstError_;  // the first trim failure of any chain (failed speeds kept)
};

// Every sign change of a root's real part between neighbouring speeds (neutral roots excepted; one
// member of a complex pair stands for both while it stays one, a pair splitting into two real roots
// having each go its own way), and every grid interval where the count of unstable roots changes with
// no such sign change (a root the tracking lost: found by the count alone, branch null).
struct Crossing {
  const ModeBranch* branch = nullptr;
  size_t k = 0;
  CriticalSpeed found;
  bool byCount = false;             ///< found (and more) by the count of unstable roots, named by the nearest root
  std::vector<CriticalSpeed> more;  ///< further crossings of the same grid interval (findCrossingByCount)
  bool isJump = false;              ///< the branch's sign change is a tracking jump, not a root crossing zero
};

std::vector<Crossing> listCrossings(const SweepResult& out) {
  std::vector<Crossing> crossings;
  std::vector<bool> seen(out.speeds.size(), false);
  for (const ModeBranch& br : out.branches)
    for (size_t k = 0; k + 1 < out.speeds.size(); ++k) {
      const double f0 = br.eigenvalue[k].real(), f1 = br.eigenvalue[k + 1].real();
      if (!(f0 * f1 < 0 || (f1 == 0 && f0 != 0))) continue;
      if (br.eigenvalue[k].imag() < 0 && br.eigenvalue[k + 1].imag() != 0) continue;
      if (br.labels[k] == ModeLabel::Neutral || br.labels[k + 1] == ModeLabel::Neutral) continue;
      Crossing& c = crossings.emplace_back();
      c.branch = &br, c.k = k;
      seen[k] = true;
    }
  std::vector<int> unstable(out.models.size());
  for (size_t k = 0; k < out.models.size(); ++k) unstable[k] = countUnstable(out.models[k]);
  for (size_t k = 0; k + 1 < out.speeds.size(); ++k)
    if (!seen[k] && unstable[k] != unstable[k + 1]) crossings.emplace_back().k = k;
  return crossings;
}

// Interior speeds at which the count of unstable roots is sampled between two grid speeds before
// bisecting it (findCrossingByCount): roots can cross several times there.
constexpr int kCountSamples = 8;

// The real root of lin nearest `near` (1/s), or NaN where lin has no real root.
double findNearestRealRoot(const LinearModel& lin, double near) {
  double best = std::nan("");
  for (const std::complex<double>& l : lin.eigenvalues)
    if (l.imag() == 0 && !(std::abs(l.real() - near) >= std::abs(best - near))) best = l.real();
  return best;
}

// A real root is counted once it is above the zero-root threshold z, so the count of unstable roots
// changes where the root passes +z, z / |d lambda/dv| past its zero. From lin at speed v (m/s), where
// the count changed, the speed where the real root at lambda ~ +z is zero, by the secant method within
// [lo, hi]: v itself where no real root is there (another root changed the count); none where the
// root's zero is not within [lo, hi] (a slow root entering or leaving the band below z, which the
// count of unstable roots ignores: no crossing).
std::optional<double> findRealRootZero(const VehicleModel& m, const SweepOptions& fixed, const SweepOptions& opt,
                                       const SweepResult& out, size_t k, const LinearModel& lin, double lo, double hi) {
  const double v = lin.speed, z = calcZeroRoot(lin);
  double fa = findNearestRealRoot(lin, z);
  if (!(std::abs(fa - z) < 0.5 * z)) return v;
  // Secant iterations on the root, each time the real root nearest its previous value.
  double va = v, vb = v - 1e-4 * (hi - lo);
  if (vb < lo) vb = v + 1e-4 * (hi - lo);
  double fb = findNearestRealRoot(linearizeFrom(m, out, k, vb, fixed, false), fa);
  for (int it = 0; it < 12; ++it) {
    if (!std::isfinite(fb) || fb == fa) return v;
    const double next = vb - fb * (vb - va) / (fb - fa);
    if (!(next >= lo && next <= hi)) return std::nullopt;
    va = vb, fa = fb, vb = next;
    fb = findNearestRealRoot(linearizeFrom(m, out, k, vb, fixed, false), fa);
    if (std::abs(vb - va) <= opt.criticalSpeedTolerance || fb == 0) return vb;
  }
  return std::abs(fb) < 0.01 * z ? vb : v;
}

// Whether the linear models at two speeds a tolerance apart belong to different equilibria (a jump
// between steady-turn branches of the trims, not a root crossing zero): A changes by more than 1e-6 of
// its largest entry, where a continuous branch changes it by about the tolerance times dA/dv.
bool isTrimJump(const LinearModel& a, const LinearModel& b) {
  return a.A.rows() != b.A.rows() || !((a.A - b.A).cwiseAbs().maxCoeff() <= 1e-6 * a.A.cwiseAbs().maxCoeff());
}

// The critical speed where the count of unstable roots goes from n0 at speed a to n1 != n0 at speed b
// (m/s), by bisection to the tolerance (moved to the zero of a real root counted there, findRealRootZero),
// named by the label of the root nearest the imaginary axis on the unstable side; none where the trims
// there jump between equilibria (isTrimJump) or a slow root only passes the zero-root threshold.
std::optional<CriticalSpeed> bisectCount(const VehicleModel& m, const SweepOptions& fixed, const SweepOptions& opt,
                                         const SweepResult& out, size_t k, double a, double b, int n0, int n1) {
  const double lo = a, hi = b;
  while (b - a > opt.criticalSpeedTolerance) {
    const double mid = 0.5 * (a + b);
    (countUnstable(linearizeFrom(m, out, k, mid, fixed, false)) == n0 ? a : b) = mid;
  }
  if (isTrimJump(linearizeFrom(m, out, k, a, fixed, false), linearizeFrom(m, out, k, b, fixed, false))) return std::nullopt;
  const double counted = 0.5 * (a + b);
  const LinearModel atCount = linearizeFrom(m, out, k, counted, fixed, false);
  const std::optional<double> atZero = findRealRootZero(m, fixed, opt, out, k, atCount, out.speeds[k], out.speeds[k + 1]);
  if (!atZero) return std::nullopt;
  CriticalSpeed found;
  found.speed = *atZero;
  found.stabilising = n1 < n0;
  // Named where the count changed, or as far again past the zero (a real root at about +2 z).
  const double named = std::clamp(2 * counted - found.speed, lo, hi);
  const LinearModel lin = linearizeFrom(m, out, k, named, fixed, true);
  const double zero = calcZeroRoot(lin);
  int best = -1;
  for (int e = 0; e < lin.eigenvalues.size(); ++e)
    if (std::abs(lin.eigenvalues[e]) >= zero && (best < 0 || std::abs(lin.eigenvalues[e].real()) < std::abs(lin.eigenvalues[best].real())))
      best = e;
  if (best >= 0) {
    found.mode = lin.labels[best];
    found.frequency = std::abs(lin.eigenvalues[best].imag()) / (2 * M_PI);
  }
  return found;
}

// Where the tracked root jumps from one eigenvalue to another between the grid speeds (across a double
// root: a complex pair splitting into two real roots, one of them then crossing zero), Brent's method
// ends at the jump, not at a zero. The crossings are then where the number of unstable roots changes:
// sampled at kCountSamples - 1 interior speeds (a real root crossing, then joining another into a pair
// that crosses back, changes it twice), each change bisected to the tolerance (bisectCount). The first
// is c.found, the others c.more; where the number never changes, or changes only where the trims jump
// between equilibria, no root crossed zero there: the sign change was the jump, no
// critical speed.
void findCrossingByCount(const VehicleModel& m, const SweepOptions& fixed, const SweepOptions& opt, const SweepResult& out,
                         Crossing& c) {
  const double lo = out.speeds[c.k], hi = out.speeds[c.k + 1];
  std::vector<double> v{lo};
  std::vector<int> n{countUnstable(out.models[c.k])};
  for (int i = 1; i < kCountSamples; ++i) {
    v.push_back(lo + (hi - lo) * i / kCountSamples);
    n.push_back(countUnstable(linearizeFrom(m, out, c.k, v.back(), fixed, false)));
  }
  v.push_back(hi);
  n.push_back(countUnstable(out.models[c.k + 1]));
  std::vector<CriticalSpeed> found;
  for (size_t i = 0; i + 1 < v.size(); ++i)
    if (n[i] != n[i + 1])
      if (auto f = bisectCount(m, fixed, opt, out, c.k, v[i], v[i + 1], n[i], n[i + 1])) found.push_back(*f);
  if (found.empty()) {
    c.isJump = true;
    return;
  }
  c.byCount = true;
  c.found = found.front();
  c.more.assign(found.begin() + 1, found.end());
}

// The crossing's speed by Brent's method to the tolerance, named by the root's label at both grid speeds
// when they agree, else by its label at the critical speed (where a double root, e.g. the capsize root
// meeting the zero forward-speed root, can leave the eigenvectors ill-defined). Where a speed in the
// interval does not trim (SweepOptions::keepFailedSpeeds), the linear interpolation of the
// real parts between the grid speeds, named by the grid label of the unstable side.
void refineCrossing(const VehicleModel& m, const SweepOptions& opt, const SweepOptions& fixed, const SweepResult& out,
                    Crossing& c) {
  if (!c.branch) return findCrossingByCount(m, fixed, opt, out, c);
  const ModeBranch& br = *c.branch;
  const double f0 = br.eigenvalue[c.k].real(), f1 = br.eigenvalue[c.k + 1].real();
  c.found.stabilising = f0 > 0;
  std::vector<std::pair<double, std::complex<double>>> seen;
  auto f = [&](double v) {
    seen.push_back({v, calcBranchRoot(m, out, br, c.k, v, fixed, false).lambda});
    return seen.back().second.real();
  };
  try {
    c.found.speed = findRoot(f, out.speeds[c.k], out.speeds[c.k + 1], f0, f1, opt.criticalSpeedTolerance);
    const bool sameLabel = br.labels[c.k] == br.labels[c.k + 1];
    auto at = std::find_if(seen.begin(), seen.end(), [&](const auto& e) { return e.first == c.found.speed; });
    // The label at the critical speed only where the grid labels differ (labelling costs a mass matrix).
    const RootAtSpeed root = at != seen.end() && sameLabel ? RootAtSpeed{at->second, br.labels[c.k]}
                                                           : calcBranchRoot(m, out, br, c.k, c.found.speed, fixed, !sameLabel);
    // At the crossing the root is near zero, where a drift-like eigenvector is named neutral: the label
    // of the unstable side's grid speed then.
    c.found.mode = sameLabel || *root.label == ModeLabel::Neutral ? br.labels[f0 > 0 ? c.k : c.k + 1] : *root.label;
    c.found.frequency = std::abs(root.lambda.imag()) / (2 * M_PI);
    if (std::abs(root.lambda.real()) > 1e-3 * std::max(std::abs(f0), std::abs(f1))) findCrossingByCount(m, fixed, opt, out, c);
  } catch (const TrimError&) {
    if (!opt.keepFailedSpeeds) throw;
    c.found.speed = out.speeds[c.k] + (out.speeds[c.k + 1] - out.speeds[c.k]) * f0 / (f0 - f1);
    c.found.mode = br.labels[f0 > 0 ? c.k : c.k + 1];
    c.found.frequency = std::abs((f0 > 0 ? br.eigenvalue[c.k] : br.eigenvalue[c.k + 1]).imag()) / (2 * M_PI);
    c.found.refined = false;
  }
}

// Every crossing refined; crossings are independent, so workers share them (each with its own model
// replica: the chains' where given, replicas[w] for worker w > 0, else a new one).
void findCriticalSpeeds(const VehicleModel& model, const SweepOptions& opt, const SweepOptions& fixed, SweepResult& out,
                        std::vector<std::unique_ptr<VehicleModel>>& replicas) {
  std::vector<Crossing> crossings = listCrossings(out);
  const size_t refiners = std::max<size_t>(1, std::min<size_t>(static_cast<size_t>(std::max(1, opt.threads)), crossings.size()));
  if (refiners == 1) {
    for (auto& c : crossings) refineCrossing(model, opt, fixed, out, c);
  } else {
    replicas.resize(std::max(replicas.size(), refiners));
    runWorkers(refiners, [&](size_t w) {
      if (w > 0 && !replicas[w]) replicas[w] = model.makeReplica();
      for (size_t i = w; i < crossings.size(); i += refiners) refineCrossing(w > 0 ? *replicas[w] : model, opt, fixed, out, crossings[i]);
    });
  }
  // Both members of a complex pair (or a pair forming at the crossing) cross together: one critical speed
  // per mode, direction and speed (within 1e-6 m/s). A crossing found by the count is named by the root
  // nearest the axis, less surely than one followed along its branch: it yields to any other there.
  std::vector<bool> named;  // out.criticalSpeeds[i] followed along its branch
  for (int pass = 0; pass < 2; ++pass)
    for (const auto& c : crossings) {
      if (c.isJump || c.byCount != (pass == 1)) continue;
      std::vector<CriticalSpeed> all{c.found};
      all.insert(all.end(), c.more.begin(), c.more.end());
      for (const CriticalSpeed& f : all) {
        bool duplicate = false;
        for (size_t i = 0; i < out.criticalSpeeds.size(); ++i) {
          const CriticalSpeed& e = out.criticalSpeeds[i];
          if ((e.mode == f.mode || (c.byCount && named[i])) && e.stabilising == f.stabilising && std::abs(e.speed - f.speed) < 1e-6)
            duplicate = true;
        }
        if (!duplicate) out.criticalSpeeds.push_back(f), named.push_back(!c.byCount);
      }
    }
  std::stable_sort(out.criticalSpeeds.begin(), out.criticalSpeeds.end(),
                   [](const CriticalSpeed& a, const CriticalSpeed& b) { return a.speed < b.speed; });
}

}  // namespace

SweepResult runSweep(const VehicleModel& model, const SweepOptions& opt) {
  return runSweep(model, makeSpeedGrid(opt.start, opt.stop, opt.step), opt);
}

SweepResult runSweep(const VehicleModel& model, const std::vector<double>& speeds, const SweepOptions& opt) {
  if (speeds.empty() || !std::is_sorted(speeds.begin(), speeds.end()) ||
      std::adjacent_find(speeds.begin(), speeds.end()) != speeds.end())
    throw std::logic_error("runSweep: the speeds must be sorted, unique and not empty");
  SweepRun run(model, speeds, opt);
  run.prepareReference();
  run.runChains();
  const SweepOptions fixed = run.getFixedOptions();
  SweepResult out = run.takeTrackedResult();
  if (opt.findCriticalSpeeds) findCriticalSpeeds(model, opt, fixed, out, run.updReplicas());
  return out;
}

void updateCriticalSpeeds(const VehicleModel& model, const SweepOptions& opt, SweepResult& sweep) {
  SweepOptions fixed = opt;
  if (!sweep.models.empty())
    fixed.linearize.removeYaw = sweep.models.front().findState(vehicle::StateRole::Yaw, vehicle::StateKind::Coordinate) < 0 ? 1 : 0;
  sweep.criticalSpeeds.clear();
  std::vector<std::unique_ptr<VehicleModel>> replicas;
  findCriticalSpeeds(model, opt, fixed, sweep, replicas);
}

namespace {

bool isStableAt(const SweepResult& sweep, size_t k) {
  for (const auto& b : sweep.branches)
    if (b.labels[k] != ModeLabel::Neutral && !(b.eigenvalue[k].real() < 0)) return false;
  return true;
}

// The critical speeds between two neighbouring grid speeds lo < hi (m/s), lo and hi excluded.
std::vector<double> findCriticalSpeedsBetween(const SweepResult& sweep, double lo, double hi) {
  std::vector<double> out;
  for (const auto& c : sweep.criticalSpeeds)
    if (c.speed > lo && c.speed < hi) out.push_back(c.speed);
  return out;
}

}  // namespace

namespace {

// Index runs [first, last] of consecutive stable grid speeds.
std::vector<std::pair<size_t, size_t>> findStableRuns(const SweepResult& sweep) {
  std::vector<std::pair<size_t, size_t>> runs;
  const size_t n = sweep.speeds.size();
  for (size_t i = 0; i < n; ++i) {
    if (!isStableAt(sweep, i)) continue;
    size_t j = i;
    while (j + 1 < n && isStableAt(sweep, j + 1)) ++j;
    runs.emplace_back(i, j);
    i = j;
  }
  return runs;
}

}  // namespace

std::vector<StableRange> calcStableGridRanges(const SweepResult& sweep) {
  std::vector<StableRange> ranges;
  for (const auto& [i, j] : findStableRuns(sweep)) ranges.push_back({sweep.speeds[i], sweep.speeds[j]});
  return ranges;
}

std::vector<StableRange> calcStableSpeedRanges(const SweepResult& sweep) {
  std::vector<StableRange> ranges;
  const size_t n = sweep.speeds.size();
  for (const auto& [i, j] : findStableRuns(sweep)) {
    StableRange r{sweep.speeds[i], sweep.speeds[j]};
    if (i > 0) {
      const auto below = findCriticalSpeedsBetween(sweep, sweep.speeds[i - 1], sweep.speeds[i]);
      if (!below.empty()) r.start = *std::max_element(below.begin(), below.end());
    }
    if (j + 1 < n) {
      const auto above = findCriticalSpeedsBetween(sweep, sweep.speeds[j], sweep.speeds[j + 1]);
      if (!above.empty()) r.stop = *std::min_element(above.begin(), above.end());
    }
    ranges.push_back(r);
  }
  return ranges;
}

}  // namespace motostab::analysis
