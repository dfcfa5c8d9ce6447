// Mode content (energy and participation shares by state role), labels at each operating point, and
// tracking across speed.
#include "analysis/modes.h"

#include "io/result_error.h"
#include "core/parallel.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>

namespace motostab::analysis {

using core::runParallel;
using vehicle::StateKind;
using vehicle::WheelSide;
using vehicle::isComplianceRole;

namespace {

constexpr const char* kLabelNames[kNumModeLabels] = {
    "neutral", "weave", "wobble", "capsize", "castor", "bounce", "pitch", "rear_hop", "front_tyre_relaxation",
    "rear_tyre_relaxation", "swingarm_bending", "swingarm_torsion", "swingarm_twist", "fork_bending", "fork_torsion",
    "rider_lean", "compliance", "controller", "longitudinal", "other"};

}  // namespace

const char* toString(ModeLabel label) { return kLabelNames[static_cast<int>(label)]; }

std::optional<ModeLabel> parseModeLabel(const std::string& name) {
  for (int i = 0; i < kNumModeLabels; ++i)
    if (name == kLabelNames[i]) return static_cast<ModeLabel>(i);
  return std::nullopt;
}

double ModeContent::calcRollYawLateral() const {
  return get(StateRole::Roll) + get(StateRole::Yaw) + get(StateRole::Lateral);
}
double ModeContent::calcInPlane() const {
  return get(StateRole::Pitch) + get(StateRole::Height) + get(StateRole::Suspension);
}
double ModeContent::calcLongitudinal() const { return get(StateRole::Forward) + get(StateRole::WheelSpin); }
double ModeContent::calcCompliance() const {
  double s = 0;
  for (int r = 0; r < kNumStateRoles; ++r)
    if (isComplianceRole(static_cast<StateRole>(r))) s += role[r];
  return s;
}
double ModeContent::calcAuxiliary() const {
  return get(StateRole::TyreLag) + get(StateRole::Controller) + get(StateRole::Other);
}

namespace {

bool isInPlaneRole(StateRole r) { return r == StateRole::Pitch || r == StateRole::Height || r == StateRole::Suspension; }

// A mechanical degree of freedom of a linear model: a rate state, the coordinate state of the same
// mobility (-1 if that coordinate is not a state), and the diagonal stiffness that weighs the latter.
struct MechanicalDof {
  int rate = -1, coordinate = -1;
  double stiffness = 0;  // |K_ii| (N/m, N m/rad)
  StateRole role = StateRole::Other;
};

// What every eigenvector of one model shares: the degrees of freedom (in the order of the rate states,
// that of lin.massMatrix), the mass matrix, and the auxiliary states.
struct ContentLayout {
  std::vector<MechanicalDof> dofs;
  Eigen::MatrixXd mass;        // over the rate states (identity without lin.massMatrix)
  // K = -M A_uq over the dofs: column b acts on dof b's coordinate (zero where it is not a state)
  Eigen::MatrixXd stiffness;
  std::vector<int> auxiliary;  // indices of the auxiliary (z) states
  // Straight running with the yaw angle and the ground-frame lateral velocity as states: the lateral
  // rate's dof and the yaw angle's state, to take the heading's turn out of the lateral velocity
  // (as the heading frame of a turn does).
  int lateralDof = -1, yaw = -1;
};

// The rate states with their coordinates, M, and |K_ii| with K = -M A_uq.
ContentLayout calcContentLayout(const LinearModel& lin) {
  ContentLayout layout;
  std::vector<int> rates;
  for (size_t i = 0; i < lin.states.size(); ++i) {
    if (lin.states[i].entry.slot == Slot::U) rates.push_back(static_cast<int>(i));
    if (lin.states[i].entry.slot == Slot::Z) layout.auxiliary.push_back(static_cast<int>(i));
  }
  const Eigen::Index nr = static_cast<Eigen::Index>(rates.size());
  const bool hasMass = lin.massMatrix.rows() == nr && lin.massMatrix.cols() == nr;
  layout.mass = hasMass ? lin.massMatrix : Eigen::MatrixXd::Identity(nr, nr);
  for (Eigen::Index a = 0; a < nr; ++a) {
    MechanicalDof d;
    d.rate = rates[a];
    d.role = lin.states[d.rate].role;
    for (size_t j = 0; j < lin.states.size(); ++j)
      if (lin.states[j].entry.slot == Slot::Q && lin.states[j].entry.index == lin.states[d.rate].entry.index)
        d.coordinate = static_cast<int>(j);
    if (d.role == StateRole::Lateral && !lin.headingFrame) layout.lateralDof = static_cast<int>(layout.dofs.size());
    layout.dofs.push_back(d);
  }
  layout.stiffness = Eigen::MatrixXd::Zero(nr, nr);
  for (Eigen::Index b = 0; b < nr; ++b) {
    const int q = layout.dofs[b].coordinate;
    if (q < 0) continue;
    Eigen::VectorXd aq(nr);  // A_uq's column of this coordinate
    for (Eigen::Index c = 0; c < nr; ++c) aq[c] = lin.A(rates[c], q);
    layout.stiffness.col(b) = -(layout.mass * aq);
  }
  for (Eigen::Index a = 0; a < nr; ++a) layout.dofs[a].stiffness = std::abs(layout.stiffness(a, a));
  layout.yaw = lin.findState(StateRole::Yaw, StateKind::Coordinate);
  return layout;
}

// Participation factors |l_kj v_jk| of the auxiliary states j in each eigenvalue k, normalised by the sum
// over all states (Perez-Arriaga, Verghese & Schweppe 1982, IEEE Trans. PAS 101(9):3117): rows follow
// layout.auxiliary; L = V^-1 (calcLeftEigenvectors). Empty without auxiliary states or a finite L.
Eigen::MatrixXd calcAuxiliaryParticipation(const LinearModel& lin, const ContentLayout& layout, const Eigen::MatrixXcd& L) {
  const Eigen::Index n = lin.eigenvectors.cols();
  if (layout.auxiliary.empty() || n == 0 || L.rows() != n || !L.allFinite()) return {};
  Eigen::MatrixXd p(layout.auxiliary.size(), n);
  for (Eigen::Index k = 0; k < n; ++k) {
    double total = 0;
    for (Eigen::Index i = 0; i < n; ++i) total += std::abs(L(k, i) * lin.eigenvectors(i, k));
    for (size_t a = 0; a < layout.auxiliary.size(); ++a) {
      const int i = layout.auxiliary[a];
      p(a, k) = total > 0 ? std::abs(L(k, i) * lin.eigenvectors(i, k)) / total : 0.0;
    }
  }
  return p;
}

// The left eigenvectors as the rows of V^-1 (empty without eigenvectors).
Eigen::MatrixXcd calcLeftEigenvectors(const LinearModel& lin) {
  if (lin.eigenvectors.cols() == 0) return {};
  return Eigen::PartialPivLU<Eigen::MatrixXcd>(lin.eigenvectors).inverse();
}

ModeContent calcContent(const LinearModel& lin, const ContentLayout& layout, const Eigen::MatrixXd& participation, int k) {
  ModeContent c;
  double auxiliary = 0;
  for (size_t a = 0; a < layout.auxiliary.size() && participation.rows() > 0; ++a) {
    const double p = participation(a, k);
    const LinearState& st = lin.states[layout.auxiliary[a]];
    c.role[static_cast<int>(st.role)] += p;
    if (st.role == StateRole::TyreLag) (st.wheel == WheelSide::Front ? c.frontLag : c.rearLag) += p;
    auxiliary += p;
  }
  // Kinetic energy by degree of freedom, Re(conj(u_i) (M u)_i) (summing to u^H M u), and potential
  // energy |K_ii| |q_i|^2; summed by role, a role's negative total (coupling) counts as none.
  const Eigen::Index nr = static_cast<Eigen::Index>(layout.dofs.size());
  Eigen::VectorXcd u(nr);
  for (Eigen::Index i = 0; i < nr; ++i) u[i] = lin.eigenvectors(layout.dofs[i].rate, k);
  // The velocity across the heading: a yaw of the ground-frame velocity (lin.speed along x) is no sideslip.
  if (layout.lateralDof >= 0 && layout.yaw >= 0) u[layout.lateralDof] -= lin.speed * lin.eigenvectors(layout.yaw, k);
  const Eigen::VectorXcd Mu = layout.mass * u;
  Eigen::VectorXcd q = Eigen::VectorXcd::Zero(nr);
  for (Eigen::Index i = 0; i < nr; ++i)
    if (layout.dofs[i].coordinate >= 0) q[i] = lin.eigenvectors(layout.dofs[i].coordinate, k);
  const Eigen::VectorXcd Kq = layout.stiffness * q;
  std::array<double, kNumStateRoles> energy{};
  for (Eigen::Index i = 0; i < nr; ++i) {
    const MechanicalDof& d = layout.dofs[i];
    double e = (std::conj(u[i]) * Mu[i]).real();
    if (d.coordinate >= 0)
      e += isInPlaneRole(d.role) ? std::abs((std::conj(q[i]) * Kq[i]).real()) : d.stiffness * std::norm(q[i]);
    energy[static_cast<int>(d.role)] += e;
  }
  double total = 0;
  for (double& e : energy) total += (e = std::max(e, 0.0));
  const double mechanical = std::max(0.0, 1.0 - auxiliary);
  for (int r = 0; r < kNumStateRoles && total > 0; ++r) c.role[r] += mechanical * energy[r] / total;
  double sum = 0;
  for (double s : c.role) sum += s;
  if (sum > 0) {
    for (double& s : c.role) s /= sum;
    c.frontLag /= sum, c.rearLag /= sum;
  }
  return c;
}

// The content of every eigenvector, with L = V^-1.
std::vector<ModeContent> calcContents(const LinearModel& lin, const ContentLayout& layout, const Eigen::MatrixXcd& L) {
  const Eigen::MatrixXd participation = calcAuxiliaryParticipation(lin, layout, L);
  std::vector<ModeContent> out;
  for (Eigen::Index k = 0; k < lin.eigenvalues.size(); ++k) out.push_back(calcContent(lin, layout, participation, static_cast<int>(k)));
  return out;
}

}  // namespace

std::vector<ModeContent> calcModeContents(const LinearModel& lin) {
  return calcContents(lin, calcContentLayout(lin), calcLeftEigenvectors(lin));
}

ModeContent calcModeContent(const LinearModel& lin, int k) {
  const ContentLayout layout = calcContentLayout(lin);
  return calcContent(lin, layout, calcAuxiliaryParticipation(lin, layout, calcLeftEigenvectors(lin)), k);
}

namespace {

// A root to label: a real eigenvalue, or the upper member of a complex pair with its conjugate.
struct Root {
  int k = -1, conjugate = -1;
  std::complex<double> lambda;
  bool oscillatory = false;
  ModeContent c;
  double rollYawLateral = 0, steer = 0, inPlane = 0, longitudinal = 0, compliance = 0, auxiliary = 0;
  StateRole topCompliance = StateRole::Compliance;  // the compliance role with the largest share
  std::optional<double> steerDamping;  // Re(d lambda / d c) of a steering damper c, 1/s per N m s/rad
  std::optional<ModeLabel> label;
  int size() const { return conjugate >= 0 ? 2 : 1; }
};

// Mode labels of the compliance roles.
ModeLabel getComplianceLabel(StateRole r) {
  switch (r) {
    case StateRole::SwingarmBending: return ModeLabel::SwingarmBending;
    case StateRole::SwingarmTorsion: return ModeLabel::SwingarmTorsion;
    case StateRole::SwingarmTwist: return ModeLabel::SwingarmTwist;
    case StateRole::ForkBending: return ModeLabel::ForkBending;
    case StateRole::ForkTorsion: return ModeLabel::ForkTorsion;
    case StateRole::RiderLean: return ModeLabel::RiderLean;
    default: return ModeLabel::Compliance;
  }
}

// First-order sensitivity Re(d lambda_k / d c) (1/s per N m s/rad) of every eigenvalue to a steering
// damper c about the steer axis: the damper adds -c M^-1 e_s delta' to the rates' derivatives, so
// d lambda_k / d c = -(l_k . M^-1 e_s) v_sk with l_k row k of V^-1 (Wilkinson 1965, The Algebraic
// Eigenvalue Problem, ch. 2); L = V^-1. Empty without a steer rate state, the mass matrix, or a finite L.
Eigen::VectorXd calcSteerDampingSensitivity(const LinearModel& lin, const ContentLayout& layout, const Eigen::MatrixXcd& L) {
  const int steerRate = lin.findState(StateRole::Steer, StateKind::Rate);
  const Eigen::Index nr = static_cast<Eigen::Index>(layout.dofs.size()), n = lin.eigenvectors.cols();
  if (steerRate < 0 || n == 0 || lin.massMatrix.rows() != nr || lin.massMatrix.cols() != nr || L.rows() != n) return {};
  const auto s = std::find_if(layout.dofs.begin(), layout.dofs.end(), [&](const MechanicalDof& d) { return d.rate == steerRate; }) -
                 layout.dofs.begin();
  const Eigen::VectorXd column = layout.mass.ldlt().solve(Eigen::VectorXd::Unit(nr, s));
  Eigen::VectorXcd d = Eigen::VectorXcd::Zero(lin.eigenvectors.rows());
  for (Eigen::Index a = 0; a < nr; ++a) d[layout.dofs[a].rate] = column[a];
  if (!L.allFinite() || !column.allFinite()) return {};
  const Eigen::VectorXcd ld = L * d;
  Eigen::VectorXd out(n);
  for (Eigen::Index k = 0; k < n; ++k) out[k] = -(ld[k] * lin.eigenvectors(steerRate, k)).real();
  return out;
}

// Roots of lin with their content: each complex pair once (the member with the positive imaginary part).
std::vector<Root> collectRoots(const LinearModel& lin) {
  // One layout and one V^-1 for the contents and the damper sensitivity.
  const ContentLayout layout = calcContentLayout(lin);
  const Eigen::MatrixXcd L = calcLeftEigenvectors(lin);
  const std::vector<ModeContent> contents = calcContents(lin, layout, L);
  const Eigen::VectorXd steerDamping = calcSteerDampingSensitivity(lin, layout, L);
  const Eigen::Index n = lin.eigenvalues.size();
  std::vector<bool> used(n, false);
  std::vector<Root> roots;
  for (Eigen::Index k = 0; k < n; ++k) {
    if (used[k]) continue;
    const std::complex<double> l = lin.eigenvalues[k];
    Root r;
    r.k = static_cast<int>(k);
    r.lambda = l;
    r.oscillatory = std::abs(l.imag()) > 1e-9 * std::max(1.0, std::abs(l));
    used[k] = true;
    if (r.oscillatory) {  // the conjugate: the nearest unused eigenvalue to conj(l)
      double best = INFINITY;
      for (Eigen::Index j = 0; j < n; ++j)
        if (!used[j] && std::abs(lin.eigenvalues[j] - std::conj(l)) < best) best = std::abs(lin.eigenvalues[j] - std::conj(l)), r.conjugate = static_cast<int>(j);
      if (r.conjugate >= 0 && best <= 1e-6 * std::max(1.0, std::abs(l))) used[r.conjugate] = true;
      else r.conjugate = -1;
      if (r.conjugate >= 0 && l.imag() < 0) std::swap(r.k, r.conjugate), r.lambda = std::conj(l);
    }
    r.c = contents[r.k];
    if (steerDamping.size() > 0) r.steerDamping = steerDamping[r.k];
    r.rollYawLateral = r.c.calcRollYawLateral();
    r.steer = r.c.get(StateRole::Steer);
    r.inPlane = r.c.calcInPlane();
    r.longitudinal = r.c.calcLongitudinal();
    r.compliance = r.c.calcCompliance();
    r.auxiliary = r.c.calcAuxiliary();
    double top = -1;
    for (int s = 0; s < kNumStateRoles; ++s)
      if (isComplianceRole(static_cast<StateRole>(s)) && r.c.role[s] > top) top = r.c.role[s], r.topCompliance = static_cast<StateRole>(s);
    roots.push_back(r);
  }
  return roots;
}

// Labels with a limited number of roots per operating point (eigenvalues: a complex pair counts two).
class Capacity {
 public:
  Capacity() {
    left_.fill(2);
    left_[static_cast<int>(ModeLabel::Castor)] = 1;  // capsize: a real root, or a slow pair in a turn
    for (ModeLabel unlimited : {ModeLabel::Neutral, ModeLabel::Controller, ModeLabel::Longitudinal, ModeLabel::Other})
      left_[static_cast<int>(unlimited)] = std::numeric_limits<int>::max();
  }
  bool take(Root& r, ModeLabel l) {
    int& left = left_[static_cast<int>(l)];
    if (r.label || left < r.size()) return false;
    left -= r.size();
    r.label = l;
    return true;
  }
  bool isFree(ModeLabel l) const { return left_[static_cast<int>(l)] > 0; }

 private:
  std::array<int, kNumModeLabels> left_;
};

// Zero roots of heading, lateral or forward drift: |lambda| at the linearisation's noise, max(1e-6 1/s,
// 1e-9 |A|_inf) (a 4e8 N m/rad fork on the enduro: the zero root at 2.7e-11 |A|_inf, the weave at 8e-9), and most of the content in yaw, lateral, forward motion and wheel spin. The eigenvector
// of such a root is A's null vector only to that noise, and its energy shares weigh rates u = lambda q
// of about that size: which motion leads is robust, a share near 1 is not (a lateral drift root of the
// Whipple bicycle on tyres has 0.985-0.999).
bool isNeutral(const Root& r, double zero) {
  const double drift = r.c.get(StateRole::Yaw) + r.c.get(StateRole::Lateral) + r.longitudinal;
  return std::abs(r.lambda) < zero && drift > 0.5;
}

// The mechanical group that leads a root: a compliance role leads when it has more than the lateral
// rigid-body motion, the in-plane and the longitudinal motion.
enum class Family { Lateral, InPlane, Longitudinal, Compliance, Auxiliary };
Family findFamily(const Root& r) {
  const double lateral = r.rollYawLateral + r.steer;
  if (r.auxiliary > 0.5) return Family::Auxiliary;
  if (r.compliance > std::max({lateral, r.inPlane, r.longitudinal})) return Family::Compliance;
  if (r.longitudinal > std::max(lateral, r.inPlane)) return Family::Longitudinal;
  if (r.inPlane > lateral) return Family::InPlane;
  return Family::Lateral;
}

// The unlabelled root `eligible` accepts that is `better` than every other such root; nullptr if none.
template <class Eligible, class Better>
Root* pickBest(std::vector<Root>& roots, Eligible eligible, Better better) {
  Root* best = nullptr;
  for (Root& r : roots)
    if (!r.label && eligible(r) && (!best || better(r, *best))) best = &r;
  return best;
}

// The steer share below which an oscillation is not a wobble.
constexpr double kWobbleSteer = 0.02;
// The in-plane share with which a lateral oscillation left without a label is named by its in-plane motion.
constexpr double kInPlaneNamed = 0.25;
// A wobble coupled with the in-plane motion: a steering damper damps it at least this fraction as fast
// as the wobble (Re d lambda / d c).
constexpr double kCoupledWobbleDamping = 0.25;
// ... and its frequency at least this fraction of the wobble's (a 1 Hz bounce the damper damps is none).
constexpr double kCoupledWobbleFrequency = 0.25;

// Whether `r` is the wobble coupled with the in-plane motion in a turn beside `wobble` (the oscillation a
// steering damper damps most): led by the lateral or in-plane motion, steer at least its largest
// compliance role's share, at least kCoupledWobbleFrequency of the wobble's frequency, and
// damped by the damper at least kCoupledWobbleDamping as fast.
bool isCoupledWobble(const Root& r, const Root& wobble) {
  const Family family = findFamily(r);
  return r.oscillatory && (family == Family::Lateral || family == Family::InPlane) && r.steer >= r.c.get(r.topCompliance) &&
         std::abs(r.lambda.imag()) >= kCoupledWobbleFrequency * std::abs(wobble.lambda.imag()) && wobble.steerDamping &&
         *wobble.steerDamping < 0 && r.steerDamping && *r.steerDamping <= kCoupledWobbleDamping * *wobble.steerDamping;
}

// The lateral rigid-body modes (docs/methods.md): capsize (slowest roll-led real root), castor (most
// negative steer-led real root), weave (of the lateral oscillations the one with the most roll, or the
// pair of real roots it splits into at low speed), wobble (the oscillation with the most steer energy);
// in a turn, a slow pair for a capsize joined with another root, and the wobble coupled with the
// in-plane motion (`inTurn`).
void labelLateralModes(std::vector<Root>& roots, Capacity& cap, double zero, bool inTurn) {
  auto roll = [](const Root& r) { return r.c.get(StateRole::Roll); };
  auto moreRoll = [&](const Root& a, const Root& b) { return roll(a) > roll(b); };
  // Roll among the mechanical motion: a root that the tyre lags carry counts less.
  auto moreMechanicalRoll = [&](const Root& a, const Root& b) {
    return roll(a) * (1 - a.auxiliary) > roll(b) * (1 - b.auxiliary);
  };
  auto lateralFamily = [](const Root& r) { return findFamily(r) == Family::Lateral; };
  auto rollLed = [&](const Root& r) { return roll(r) >= r.steer && roll(r) >= 0.1 * (r.rollYawLateral + r.steer); };
  // The slowest; of equal magnitudes (to 1e-6 relative: the +-lambda pairs at standstill) the lower real part.
  auto slower = [&](const Root& a, const Root& b) {
    const double x = std::abs(a.lambda), y = std::abs(b.lambda);
    if ((x < zero) != (y < zero)) return y < zero;
    if (std::abs(x - y) > 1e-6 * std::max(x, y)) return x < y;
    return a.lambda.real() < b.lambda.real();
  };
  // Where no lateral oscillation exists, the weave is split into two real roots (unstable, as the
  // bicycle's at standstill or below the speed where they join in a tight turn): the two unstable real
  // lateral roots with the most roll, named before the capsize so that it cannot take one of them.
  // A lateral oscillation that roll does not lead is not the weave they split from; nor is a stable one
  // faster than both where a third, slower roll-led real root (the capsize) is there too (a bicycle on
  // tyres at walking pace, with roll-led tyre and frame modes at 15-20 Hz).
  auto splitRoot = [&](const Root& r) { return !r.oscillatory && lateralFamily(r) && r.lambda.real() > 0; };
  Root* split1 = pickBest(roots, splitRoot, moreRoll);
  Root* split2 = pickBest(roots, [&](const Root& r) { return splitRoot(r) && &r != split1; }, moreRoll);
  if (split2) {
    const double slow = std::min(std::abs(split1->lambda), std::abs(split2->lambda));
    const double fast = std::max(std::abs(split1->lambda), std::abs(split2->lambda));
    const bool slowerRoot = std::any_of(roots.begin(), roots.end(), [&](const Root& r) {
      return &r != split1 && &r != split2 && !r.oscillatory && lateralFamily(r) && rollLed(r) && std::abs(r.lambda) <= slow;
    });
    const bool weaveLeft = std::any_of(roots.begin(), roots.end(), [&](const Root& r) {
      return !r.label && r.oscillatory && lateralFamily(r) && rollLed(r) &&
             !(slowerRoot && r.lambda.real() < 0 && std::abs(r.lambda) > fast);
    });
    if (!weaveLeft) cap.take(*split1, ModeLabel::Weave), cap.take(*split2, ModeLabel::Weave);
  }
  // In a turn at a fixed roll the speed is tied to the lean: a root that the forward motion leads but
  // with a lateral share of at least 0.2 can be the capsize.
  auto lateralOrWithSpeed = [&](const Root& r) {
    return lateralFamily(r) || (findFamily(r) == Family::Longitudinal && r.rollYawLateral + r.steer >= 0.2);
  };
  auto capsizeRoot = [&](const Root& r) { return !r.oscillatory && lateralOrWithSpeed(r) && rollLed(r); };
  // The capsize is a slow motion. A real roll-led root faster than the weave (the lateral oscillation
  // with the most roll) is not it where a roll-led pair at most half as fast as both exists: the capsize
  // joined with another root in a turn (named below, once the weave is known).
  const Root* firstWeave = pickBest(roots, [&](const Root& r) { return r.oscillatory && lateralFamily(r); }, moreMechanicalRoll);
  auto slowPair = [&](const Root& r, double bound) {
    return r.oscillatory && lateralOrWithSpeed(r) && rollLed(r) && &r != firstWeave && std::abs(r.lambda) < 0.5 * bound;
  };
  auto slowEnough = [&](const Root& c) {
    if (!firstWeave || std::abs(c.lambda) <= std::abs(firstWeave->lambda)) return true;
    const double bound = std::min(std::abs(c.lambda), std::abs(firstWeave->lambda));
    return !std::any_of(roots.begin(), roots.end(), [&](const Root& r) { return !r.label && slowPair(r, bound); });
  };
  if (Root* c = pickBest(roots, capsizeRoot, slower); c && slowEnough(*c)) cap.take(*c, ModeLabel::Capsize);
  // A second roll-led real root that diverges is the vehicle falling over as well (in a tight turn at
  // walking pace, beside a slower decaying one): a capsize too.
  if (Root* c = pickBest(roots, [&](const Root& r) { return capsizeRoot(r) && r.lambda.real() > 0; }, slower))
    cap.take(*c, ModeLabel::Capsize);
  if (Root* c = pickBest(roots, [&](const Root& r) { return !r.oscillatory && lateralFamily(r) && r.steer > r.rollYawLateral; },
                         [](const Root& a, const Root& b) { return a.lambda.real() < b.lambda.real(); }))
    cap.take(*c, ModeLabel::Castor);
  // Weave and wobble. A weave candidate is a lateral oscillation; a wobble candidate an oscillation with
  // a steer energy share of at least 0.02, above every compliance role's, not led by tyre lags. Where two
  // or more oscillations are candidates, the wobble is named first: the oscillation a steering damper
  // damps most (first-order sensitivity; in a turn the steer share alone can point at another root), else
  // the one with the largest steer share, in-plane-led roots last; the weave is then the remaining
  // lateral oscillation with the most roll times (1 - auxiliary share). Where only one oscillation is a
  // candidate, it is the weave if lateral, else the wobble if its steer exceeds its roll.
  auto weaveCandidate = [&](const Root& r) { return r.oscillatory && lateralFamily(r); };
  auto wobbleCandidate = [&](const Root& r) {
    return r.oscillatory && r.auxiliary <= 0.5 && r.steer >= kWobbleSteer && r.steer >= r.c.get(r.topCompliance);
  };
  // More steer energy; a root the in-plane motion leads (a pitch that turns the bars in a turn) only
  // where no other candidate is left.
  auto moreSteer = [](const Root& a, const Root& b) {
    const bool inPlaneA = findFamily(a) == Family::InPlane, inPlaneB = findFamily(b) == Family::InPlane;
    if (inPlaneA != inPlaneB) return inPlaneB;
    return a.steer > b.steer;
  };
  const auto candidates = std::count_if(roots.begin(), roots.end(), [&](const Root& r) {
    return !r.label && (weaveCandidate(r) || wobbleCandidate(r));
  });
  // The root a steering damper damps most, where the damper damps some candidate (sensitivities known).
  auto dampedBySteerDamper = [&](const Root& r) {
    return r.oscillatory && r.auxiliary <= 0.5 && r.steer >= r.c.get(r.topCompliance) && r.steerDamping && *r.steerDamping < 0;
  };
  auto moreDampedBySteerDamper = [](const Root& a, const Root& b) { return *a.steerDamping < *b.steerDamping; };
  if (candidates >= 2) {
    Root* w = pickBest(roots, dampedBySteerDamper, moreDampedBySteerDamper);
    if (!w) w = pickBest(roots, wobbleCandidate, moreSteer);
    if (w) cap.take(*w, ModeLabel::Wobble);
    // In a turn preferably not a root the damper damps alike (the wobble coupled with the in-plane
    // motion: the damper destabilises the high-speed weave); of such roots only, the one it damps least.
    auto coupled = [&](const Root& r) { return inTurn && w && isCoupledWobble(r, *w); };
    Root* osc = pickBest(roots, weaveCandidate, [&](const Root& a, const Root& b) {
      if (coupled(a) != coupled(b)) return coupled(b);
      return coupled(a) ? *a.steerDamping > *b.steerDamping : moreMechanicalRoll(a, b);
    });
    if (osc) cap.take(*osc, ModeLabel::Weave);
    // The wobble is the faster of the two: where the damper's root is the weave's frequency or less by
    // half (a bicycle's weave at walking pace, which a steer damper damps most), they change names.
    if (w && osc && std::abs(w->lambda.imag()) < 0.5 * std::abs(osc->lambda.imag())) w->label = ModeLabel::Weave, osc->label = ModeLabel::Wobble;
  } else if (Root* osc = pickBest(roots, weaveCandidate, moreMechanicalRoll)) {
    // In a turn the weave may have joined the in-plane motion (led by the height): a lone candidate
    // that the damper damps and that steers more than it rolls is then the wobble.
    const bool wobbleLike = inTurn && osc->steerDamping && *osc->steerDamping < 0 && osc->steer > roll(*osc);
    cap.take(*osc, wobbleLike ? ModeLabel::Wobble : ModeLabel::Weave);
  } else if (Root* w = pickBest(roots, [&](const Root& r) { return wobbleCandidate(r) && r.steer > roll(r); }, moreSteer)) {
    cap.take(*w, ModeLabel::Wobble);
  }
  // In a turn the capsize root may join another into a slow pair: at most half the weave's |lambda|, or
  // diverging (a tight turn's fall, as the diverging second real root above). Joined with the speed
  // root (a turn at a fixed roll ties the speed to the lean) the forward motion may lead it: a slow pair
  // with a lateral share of at least 0.2 is then a capsize too.
  const Root *weave = nullptr, *wobble = nullptr;
  for (const Root& r : roots) {
    if (r.label == ModeLabel::Weave) weave = &r;
    if (r.label == ModeLabel::Wobble) wobble = &r;
  }
  if (!std::any_of(roots.begin(), roots.end(), [](const Root& r) { return r.label == ModeLabel::Capsize; }))
    if (Root* c = pickBest(roots, [&](const Root& r) {
          return r.oscillatory && lateralOrWithSpeed(r) && rollLed(r) && !(inTurn && wobble && isCoupledWobble(r, *wobble)) &&
                 (!weave || std::abs(r.lambda) < 0.5 * std::abs(weave->lambda) || r.lambda.real() > 0);
        }, slower))
      cap.take(*c, ModeLabel::Capsize);
  // In a turn the wobble couples with the in-plane motion (the roll tilts the steer motion into the
  // plane of the pitch and bounce): where their frequencies meet, oscillations share the steer, lateral
  // and in-plane motion, and a steering damper damps them alike. Those isCoupledWobble accepts are
  // wobbles too, beyond the label's one pair (upright the lateral and in-plane motions do not couple).
  if (inTurn && wobble)
    for (Root& r : roots)
      if (!r.label && isCoupledWobble(r, *wobble)) r.label = ModeLabel::Wobble;
}

// In-plane, compliance, auxiliary and longitudinal roots by their family, largest share first; a root
// whose label is taken keeps looking (`fallback`).
void labelOtherModes(std::vector<Root>& roots, Capacity& cap) {
  auto inPlaneLabel = [](const Root& r) {
    if (r.c.get(StateRole::Suspension) > 0.9 * r.inPlane) return ModeLabel::RearHop;
    return r.c.get(StateRole::Height) >= r.c.get(StateRole::Pitch) ? ModeLabel::Bounce : ModeLabel::Pitch;
  };
  // An in-plane label taken: the others, largest share first (rear_hop only with a suspension share).
  auto takeInPlane = [&](Root& r) {
    if (cap.take(r, inPlaneLabel(r))) return;
    const bool bounceFirst = r.c.get(StateRole::Height) >= r.c.get(StateRole::Pitch);
    for (ModeLabel l : {bounceFirst ? ModeLabel::Bounce : ModeLabel::Pitch, bounceFirst ? ModeLabel::Pitch : ModeLabel::Bounce})
      cap.take(r, l);
    if (r.c.get(StateRole::Suspension) > 0) cap.take(r, ModeLabel::RearHop);
  };
  auto auxiliaryLabel = [](const Root& r) {
    const double lag = r.c.frontLag + r.c.rearLag, controller = r.c.get(StateRole::Controller);
    if (lag >= controller && lag >= r.c.get(StateRole::Other))
      return r.c.frontLag >= r.c.rearLag ? ModeLabel::FrontTyreRelaxation : ModeLabel::RearTyreRelaxation;
    return controller >= r.c.get(StateRole::Other) ? ModeLabel::Controller : ModeLabel::Other;
  };
  // Largest leading share first, so that the clearest root of each label takes it.
  std::vector<Root*> order;
  for (Root& r : roots)
    if (!r.label) order.push_back(&r);
  auto lead = [](const Root& r) {
    return std::max({r.rollYawLateral + r.steer, r.inPlane, r.longitudinal, r.compliance, r.auxiliary});
  };
  std::stable_sort(order.begin(), order.end(), [&](const Root* a, const Root* b) { return lead(*a) > lead(*b); });
  for (Root* r : order) {
    switch (findFamily(*r)) {
      case Family::InPlane: takeInPlane(*r); break;
      case Family::Compliance: cap.take(*r, getComplianceLabel(r->topCompliance)); break;
      case Family::Auxiliary: cap.take(*r, auxiliaryLabel(*r)); break;
      case Family::Longitudinal: cap.take(*r, ModeLabel::Longitudinal); break;
      case Family::Lateral: break;
    }
  }
  // What is left (e.g. a second lateral oscillation in a turn): the free label of its largest other
  // share of at least 0.05 (in-plane, compliance, tyre lag); a lateral or in-plane oscillation with an
  // in-plane share of at least kInPlaneNamed whose labels are all taken (overdamped in-plane roots and,
  // in a turn, oscillations coupling the lateral and in-plane motion can outnumber them) keeps its
  // in-plane label, a second pair; else other.
  for (Root& r : roots) {
    if (r.label) continue;
    std::vector<std::pair<double, int>> shares{{r.inPlane, 0}, {r.compliance, 1}, {r.auxiliary, 2}};
    std::sort(shares.begin(), shares.end(), std::greater<>());
    for (const auto& [share, kind] : shares) {
      if (share < 0.05) break;
      if (kind == 0) takeInPlane(r);
      if (kind == 1) cap.take(r, getComplianceLabel(r.topCompliance));
      if (kind == 2) cap.take(r, auxiliaryLabel(r));
    }
    const Family family = findFamily(r);
    if (!r.label && r.oscillatory && (family == Family::InPlane || family == Family::Lateral) && r.inPlane >= kInPlaneNamed)
      r.label = inPlaneLabel(r);
    cap.take(r, ModeLabel::Other);
  }
}

}  // namespace

std::vector<ModeLabel> labelModes(const LinearModel& lin) {
  std::vector<Root> roots = collectRoots(lin);
  Capacity cap;
  const double zero = std::max(1e-6, 1e-9 * lin.A.cwiseAbs().rowwise().sum().maxCoeff());
  for (Root& r : roots)
    if (isNeutral(r, zero)) cap.take(r, ModeLabel::Neutral);
  const bool inTurn = lin.headingFrame && lin.roll != 0;  // a turn, not straight running in the heading frame
  labelLateralModes(roots, cap, zero, inTurn);
  // A zero root the drift does not lead (its eigenvector mixed with a slow root's near a double root).
  for (Root& r : roots)
    if (std::abs(r.lambda) < zero) cap.take(r, ModeLabel::Neutral);
  labelOtherModes(roots, cap);
  std::vector<ModeLabel> out(lin.eigenvalues.size(), ModeLabel::Other);
  for (const Root& r : roots) {
    out[r.k] = *r.label;
    if (r.conjugate >= 0) out[r.conjugate] = *r.label;
  }
  return out;
}

namespace {

bool hasSameStates(const LinearModel& a, const LinearModel& b) {
  if (a.states.size() != b.states.size()) return false;
  for (size_t i = 0; i < a.states.size(); ++i)
    if (a.states[i].name != b.states[i].name) return false;
  return true;
}

}  // namespace

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

void labelBranches(const std::vector<std::vector<ModeLabel>>& labels, std::vector<ModeBranch>& branches) {
  for (ModeBranch& br : branches) {
    br.labels.assign(labels.size(), ModeLabel::Other);
    std::array<int, kNumModeLabels> count{};
    for (size_t s = 0; s < labels.size() && s < br.index.size(); ++s) {
      const int k = br.index[s];
      if (k >= 0 && static_cast<size_t>(k) < labels[s].size()) br.labels[s] = labels[s][k];
      ++count[static_cast<int>(br.labels[s])];
    }
    int best = -1;  // the most frequent; of a tie, the first met along the speeds
    for (ModeLabel l : br.labels)
      if (best < 0 || count[static_cast<int>(l)] > count[best]) best = static_cast<int>(l);
    br.label = best < 0 ? ModeLabel::Other : static_cast<ModeLabel>(best);
  }
}

const ModeBranch* findLabelledBranch(const std::vector<ModeBranch>& branches, ModeLabel label, size_t k) {
  const ModeBranch* best = nullptr;
  auto better = [k](const ModeBranch& b, const ModeBranch& than) {
    const std::complex<double> l = b.eigenvalue[k], t = than.eigenvalue[k];
    if ((l.imag() > 0) != (t.imag() > 0)) return l.imag() > t.imag();  // the upper member of a pair
    return l.imag() > 0 && l.real() > t.real();                         // of two pairs, the less damped
  };
  for (const ModeBranch& b : branches)
    if (k < b.labels.size() && b.labels[k] == label && (!best || better(b, *best))) best = &b;
  return best;
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

namespace {

// Branch b's next eigenvalue index for every branch, greedy on ascending cost; when every branch's
// cheapest match is distinct, greedy takes exactly those.
std::vector<int> assignNext(const std::vector<ModeBranch>& branches, const Eigen::MatrixXd& cost, size_t s) {
  const int n = static_cast<int>(branches.size());
  std::vector<int> assigned(n, -1);
  std::vector<bool> taken(n, false);
  bool distinct = true;
  for (int b = 0; b < n; ++b) {
    const int kp = branches[b].index.back();
    double best = std::numeric_limits<double>::infinity();
    bool finite = true;  // NaN must not reach the sort below
    for (int k = 0; k < n; ++k) {
      finite = finite && std::isfinite(cost(kp, k));
      if (cost(kp, k) < best) best = cost(kp, k), assigned[b] = k;
    }
    if (!finite || assigned[b] < 0)
      throw io::ResultError("mode tracking: non-finite eigenvalues or eigenvectors at speed index " + std::to_string(s) +
                            " (a linearisation that diverged there)");
    distinct = distinct && !taken[assigned[b]];
    taken[assigned[b]] = true;
  }
  if (distinct) return assigned;
  std::vector<std::tuple<double, int, int>> pairs;
  pairs.reserve(n * n);
  for (int b = 0; b < n; ++b)
    for (int k = 0; k < n; ++k) pairs.emplace_back(cost(branches[b].index.back(), k), b, k);
  std::sort(pairs.begin(), pairs.end());
  std::fill(assigned.begin(), assigned.end(), -1);
  std::fill(taken.begin(), taken.end(), false);
  for (const auto& [c, b, k] : pairs)
    if (assigned[b] < 0 && !taken[k]) assigned[b] = k, taken[k] = true;
  return assigned;
}

}  // namespace

std::vector<ModeBranch> trackModes(const std::vector<LinearModel>& models, int threads, std::vector<Eigen::MatrixXd> costs) {
  std::vector<ModeBranch> branches;
  if (models.empty()) return branches;
  const int n = static_cast<int>(models[0].eigenvalues.size());
  for (const auto& m : models)
    if (m.eigenvalues.size() != n) throw std::logic_error("trackModes: model size changed with speed");
  // Match costs between every pair of consecutive speeds not given, and the labels of models that
  // have none, independent of the assignment: in parallel.
  costs.resize(models.size());
  std::vector<std::vector<ModeLabel>> labels(models.size());
  runParallel(models.size(), threads, [&](size_t i) {
    if (i + 1 < models.size() && (costs[i + 1].rows() != n || costs[i + 1].cols() != n))
      costs[i + 1] = calcMatchCosts(models[i], models[i + 1]);
    labels[i] = models[i].labels.size() == static_cast<size_t>(n) ? models[i].labels : labelModes(models[i]);
  });
  branches.resize(n);
  for (int k = 0; k < n; ++k) {
    branches[k].index.push_back(k);
    branches[k].eigenvalue.push_back(models[0].eigenvalues[k]);
  }
  for (size_t s = 1; s < models.size(); ++s) {
    const std::vector<int> assigned = assignNext(branches, costs[s], s);
    for (int b = 0; b < n; ++b) {
      branches[b].index.push_back(assigned[b]);
      branches[b].eigenvalue.push_back(models[s].eigenvalues[assigned[b]]);
    }
  }
  labelBranches(labels, branches);
  return branches;
}

}  // namespace motostab::analysis
