#include "analysis/sweep.h"

#include "analysis/parallel.h"

#include <cmath>
#include <functional>
#include <algorithm>
#include <atomic>
#include <future>
#include <memory>
#include <mutex>
#include <optional>

namespace motostab {

std::vector<double> makeSpeedGrid(double start, double stop, double step) {
  std::vector<double> v;
  const long n = static_cast<long>(std::floor((stop - start) / step + 1e-9));
  for (long i = 0; i <= n; ++i) v.push_back(start + i * step);
  return v;
}

double calcBranchRealPart(const VehicleModel& model, const SweepResult& sweep, const ModeBranch& branch, size_t k,
                          double v, const SweepOptions& opt) {
  TrimResult trim = restoreTrim(model, sweep.trims[k]);
  updTrim(model, v, opt.trim, trim);
  const LinearModel lin = linearizeInPlace(model, trim, opt.linearize);
  return lin.eigenvalues[findBestMatch(sweep.models[k], branch.index[k], lin)].real();
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

}  // namespace

SweepResult runSweep(const VehicleModel& model, const SweepOptions& opt) {
  SweepResult out;
  out.speeds = makeSpeedGrid(opt.start, opt.stop, opt.step);
  // The states must not change with speed: decide on yaw once, from a reference linearisation away
  // from standstill (every speed-dependent coupling present; also a sample of the column pattern).
  // It is the lead chain's first: worker 0 starts at the first speed of at least 1 m/s, sweeps down
  // to its span's bottom, then turns and goes up; the other workers make their first, cold trim
  // meanwhile (its partner's, at the top speed, is the slowest) and take the reference before
  // linearising it.
  const size_t n = out.speeds.size();
  const size_t workers = std::max<size_t>(1, std::min<size_t>(static_cast<size_t>(std::max(1, opt.threads)), n));
  struct Span {
    std::mutex lock;
    size_t lo = 0, hi = 0;  // speeds [lo, hi) not yet taken
  };
  const size_t spans = (workers + 1) / 2;
  std::vector<Span> span(spans);
  for (size_t p = 0; p < spans; ++p)  // shares of the speeds: two per two-worker span
    span[p].lo = n * std::min(2 * p, workers) / workers, span[p].hi = n * std::min(2 * p + 2, workers) / workers;
  const size_t leadFirst = static_cast<size_t>(
      std::find_if(out.speeds.begin(), out.speeds.end(), [](double v) { return v >= 1.0; }) - out.speeds.begin());
  const bool leadTurns = leadFirst < span[0].hi;  // else worker 0 just goes up from 0
  const size_t leadDown = leadTurns ? leadFirst + 1 : 0;  // speeds leadFirst, ..., 0 before the turn
  if (leadTurns) span[0].lo = leadFirst + 1;
  SweepOptions fixed = opt;
  const bool decideYaw = fixed.linearize.removeYaw < 0;
  std::optional<LinearModel> ownReference;
  const LinearModel* ref = nullptr;
  std::promise<void> refPromise;
  std::shared_future<void> refReady;
  std::atomic<bool> refSettled{false}, failed{false};
  auto settleReference = [&](std::exception_ptr e) {  // once: the value, or the failure that stops the sweep
    if (!refReady.valid() || refSettled.exchange(true)) return;
    if (e) refPromise.set_exception(e);
    else refPromise.set_value();
  };
  if (decideYaw && leadTurns) {
    refReady = refPromise.get_future().share();
  } else if (decideYaw) {  // no speed of 1 m/s or more in the lead's span: a separate reference
    TrimResult top = calcTrim(model, std::max(1.0, opt.stop), opt.trim);
    ownReference = linearizeInPlace(model, top, opt.linearize);
    ref = &*ownReference;
    fixed.linearize.removeYaw = ref->findState("yaw") < 0 ? 1 : 0;  // the sweep's states are ref's
  }
  out.trims.resize(n);
  out.models.resize(n);
  std::vector<Eigen::MatrixXd> costs(n);  // costs[k]: calcMatchCosts(models[k - 1], models[k])
  // Warm-started chains of speeds: on a span shared by two workers one goes up and the other down
  // from its top, each taking the next speed until they meet, so that within a span neither waits
  // for the other whatever the cost per speed (where they meet depends on timing: threaded results
  // agree with the serial sweep to the trim tolerance, not to the bit). Each chain trims in place
  // on one State (no State copies). Without constraints the next speed's trim Jacobian is read off
  // this speed's A, keeping the input columns of the one this trim used (a differentiated one costs
  // two realizations per unknown), and extrapolated along speed.
  auto runChain = [&](const VehicleModel& m, Span& sp, bool downwards, bool lead) {
    auto take = [&](size_t& k) {
      std::lock_guard<std::mutex> guard(sp.lock);
      if (sp.lo == sp.hi || failed) return false;
      k = downwards ? --sp.hi : sp.lo++;
      return true;
    };
    LinearizeOptions lo;
    TrimResult work, turn;  // turn: the lead's first trim, from which it goes up
    Eigen::MatrixXd lastJ, turnJ;  // the previous speed's trim Jacobian read off its A
    size_t k = 0, previous = 0;
    for (size_t i = 0;; ++i, previous = k) {
      if (lead && i < leadDown) {
        if (failed) break;
        k = leadFirst - i;
      } else if (!take(k)) {
        break;
      } else if (lead && i == leadDown && leadDown > 1) {
        work = std::move(turn), lastJ = std::move(turnJ), previous = leadFirst;
      }
      if (i == 0) {
        work = calcTrim(m, out.speeds[k], opt.trim);
        const bool isReference = lead && refReady.valid();  // removeYaw automatic
        if (refReady.valid() && !isReference) refReady.get();
        out.models[k] = linearizeInPlace(m, work, isReference ? opt.linearize : fixed.linearize);
        if (isReference) {
          ref = &out.models[k];
          fixed.linearize.removeYaw = ref->findState("yaw") < 0 ? 1 : 0;
          settleReference(nullptr);  // a failure reaches the waiting workers through onFirstFailure
        }
        lo = fixed.linearize;
      } else {
        updTrim(m, out.speeds[k], opt.trim, work);
        out.models[k] = linearizeInPlace(m, work, lo);
      }
      if (i > 0) {  // the match costs of this step, for the tracking
        const size_t low = std::min(k, previous);
        costs[low + 1] = calcMatchCosts(out.models[low], out.models[low + 1]);
      }
      if (opt.groupColumns && i == 1) {
        std::vector<const LinearModel*> samples{&out.models[previous], &out.models[k]};
        if (ref) samples.push_back(ref);
        lo.grouping = calcColumnGrouping(samples);
      }
      Eigen::MatrixXd J = calcTrimJacobian(m, out.models[k], work.jacobian);
      if (J.size() > 0) {
        if (i > 0 && lastJ.rows() == J.rows() && lastJ.cols() == J.cols())
          work.jacobianPerSpeed = (J - lastJ) / (out.speeds[k] - out.speeds[previous]);
        lastJ = J;
        work.jacobian = std::move(J);
      }
      out.trims[k] = makeTrimPoint(m, work);
      if (lead && i == 0 && leadDown > 1) turn = work, turnJ = lastJ;  // one State copy
    }
  };
  if (workers == 1) {
    runChain(model, span[0], false, true);
  } else {
    // Each worker builds its own model (no shared Simbody caches); a failure stops the others at
    // their next speed and releases any wait for the reference. The lead's partner takes at
    // least its first speed; the lead computes the reference before taking any shared speed.
    runWorkers(
        workers,
        [&](size_t w) {
          std::unique_ptr<VehicleModel> own;
          if (w > 0) own = model.makeReplica();
          runChain(w > 0 ? *own : model, span[w / 2], w % 2 == 1, w == 0);
        },
        [&]() {
          failed = true;
          settleReference(std::make_exception_ptr(std::runtime_error("sweep stopped: another worker failed")));
        });
  }
  out.branches = trackModes(out.models, model.getScenario().geometry.wheelbase, opt.threads, std::move(costs));

  // Every sign change of a labelled mode's real part, refined by Brent's method; crossings are
  // independent, so workers share them (each with its own model).
  struct Crossing {
    const ModeBranch* branch;
    size_t k;
    double speed = 0;
  };
  std::vector<Crossing> crossings;
  for (const ModeBranch& br : out.branches) {
    if (br.label == "neutral" || br.label == "other") continue;
    for (size_t k = 0; k + 1 < n; ++k) {
      const double f0 = br.eigenvalue[k].real(), f1 = br.eigenvalue[k + 1].real();
      // One member of a complex pair stands for both.
      if ((f0 * f1 < 0 || (f1 == 0 && f0 != 0)) && br.eigenvalue[k].imag() >= 0) crossings.push_back({&br, k});
    }
  }
  auto refine = [&](const VehicleModel& m, Crossing& c) {
    const double f0 = c.branch->eigenvalue[c.k].real(), f1 = c.branch->eigenvalue[c.k + 1].real();
    auto f = [&](double v) { return calcBranchRealPart(m, out, *c.branch, c.k, v, fixed); };
    c.speed = findRoot(f, out.speeds[c.k], out.speeds[c.k + 1], f0, f1, opt.criticalSpeedTolerance);
  };
  const size_t refiners = std::max<size_t>(1, std::min<size_t>(static_cast<size_t>(std::max(1, opt.threads)), crossings.size()));
  if (refiners == 1) {
    for (auto& c : crossings) refine(model, c);
  } else {
    runWorkers(refiners, [&](size_t w) {
      std::unique_ptr<VehicleModel> own;
      if (w > 0) own = model.makeReplica();
      for (size_t i = w; i < crossings.size(); i += refiners) refine(w > 0 ? *own : model, crossings[i]);
    });
  }
  for (const auto& c : crossings) {
    bool duplicate = false;  // both members of a complex pair cross together
    for (const auto& e : out.criticalSpeeds)
      if (e.mode == c.branch->label && std::abs(e.speed - c.speed) < 1e-6) duplicate = true;
    if (!duplicate) out.criticalSpeeds.push_back({c.branch->label, c.speed, c.branch->eigenvalue[c.k].real() > 0});
  }
  return out;
}

}  // namespace motostab
