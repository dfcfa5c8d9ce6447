#include "vehicle/steer_controller.h"

#include <algorithm>
#include <cmath>

namespace motostab::vehicle {

using plugins::BuildContext;
using scenario::SteerControllerSpec;

namespace {

using SimTK::MobilizerQIndex;
using SimTK::MobilizerUIndex;

// The Bushing's q/u slots (vehicle/vehicle_model.cpp: frames permuted to yaw, roll, pitch, height, x, y).
constexpr int kYaw = 0, kRoll = 1, kX = 4, kY = 5;

class SteerControllerForce : public SimTK::Force::Custom::Implementation {
 public:
  explicit SteerControllerForce(std::shared_ptr<const SteerController> c) : c_(std::move(c)) {}
  void realizeTopology(SimTK::State& s) const override { c_->allocateState(s); }
  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>&, SimTK::Vector_<SimTK::Vec3>&,
                 SimTK::Vector& mobilityForces) const override {
    c_->apply(s, mobilityForces);
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }

 private:
  std::shared_ptr<const SteerController> c_;
};

}  // namespace

double calcScheduleFactor(const SteerControllerSpec& spec, double v) {
  switch (spec.schedule) {
    case SteerControllerSpec::Schedule::None: return 1;
    case SteerControllerSpec::Schedule::Below: return std::max(spec.scheduleBelow - v, 0.0);
    case SteerControllerSpec::Schedule::Table: break;
  }
  const auto& t = spec.scheduleTable;
  if (v <= t.front()[0]) return t.front()[1];
  if (v >= t.back()[0]) return t.back()[1];
  const auto hi = std::upper_bound(t.begin(), t.end(), v, [](double x, const std::array<double, 2>& r) { return x < r[0]; });
  const auto lo = hi - 1;
  const double a = (v - (*lo)[0]) / ((*hi)[0] - (*lo)[0]);
  return (1 - a) * (*lo)[1] + a * (*hi)[1];
}

double calcSteerControllerCommand(const SteerControllerSpec& c, const SteerControllerInputs& x) {
  const double law = c.rollAngleGain * x.roll + c.rollRateGain * x.rollRate + c.steerAngleGain * x.steer +
                     c.steerRateGain * x.steerRate;
  return calcScheduleFactor(c, x.speed) * c.gainFactor * law;
}

double calcSaturatedTorque(const SteerControllerSpec& c, double y) {
  return c.torqueLimit > 0 ? std::clamp(y, -c.torqueLimit, c.torqueLimit) : y;
}

SteerController::SteerController(SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& rearFrame,
                                 const SimTK::MobilizedBody& frontFrame, const SteerControllerSpec& spec)
    : forces_(forces), rear_(rearFrame), front_(frontFrame), spec_(spec) {}

void SteerController::allocateState(SimTK::State& s) const {
  if (spec_.delay > 0) zIndex_ = forces_.allocateZ(s, SimTK::Vector(1, 0.0));
}

std::vector<plugins::AuxiliaryState> SteerController::getStates() const {
  if (spec_.delay > 0) return {{"steer_controller_delay", plugins::StateRole::Controller, plugins::WheelSide::None}};
  return {};
}

SteerControllerInputs SteerController::getInputs(const SimTK::State& s) const {
  SteerControllerInputs x;
  x.roll = rear_.getOneQ(s, MobilizerQIndex(kRoll));
  x.rollRate = rear_.getOneU(s, MobilizerUIndex(kRoll));
  x.steer = front_.getOneQ(s, MobilizerQIndex(0));
  x.steerRate = front_.getOneU(s, MobilizerUIndex(0));
  const double yaw = rear_.getOneQ(s, MobilizerQIndex(kYaw));
  x.speed = std::cos(yaw) * rear_.getOneU(s, MobilizerUIndex(kX)) + std::sin(yaw) * rear_.getOneU(s, MobilizerUIndex(kY));
  return x;
}

double SteerController::calcDelayedCommand(const SimTK::State& s, double u) const {
  if (!zIndex_.isValid()) return u;
  return forces_.getZ(s)[zIndex_] - u;  // y = z - u
}

double SteerController::calcTorque(const SimTK::State& s) const {
  return calcSaturatedTorque(spec_, calcDelayedCommand(s, calcSteerControllerCommand(spec_, getInputs(s))));
}

void SteerController::apply(const SimTK::State& s, SimTK::Vector& mobilityForces) const {
  const double u = calcSteerControllerCommand(spec_, getInputs(s));
  if (zIndex_.isValid()) forces_.updZDot(s)[zIndex_] = 2 / spec_.delay * (2 * u - forces_.getZ(s)[zIndex_]);
  front_.applyOneMobilityForce(s, MobilizerUIndex(0), calcSaturatedTorque(spec_, calcDelayedCommand(s, u)), mobilityForces);
}

std::shared_ptr<const SteerController> addSteerController(BuildContext& ctx, const SimTK::MobilizedBody& rearFrame,
                                                          const SimTK::MobilizedBody& frontFrame,
                                                          const SteerControllerSpec& spec) {
  auto c = std::make_shared<const SteerController>(ctx.forces, rearFrame, frontFrame, spec);
  SimTK::Force::Custom(ctx.forces, new SteerControllerForce(c));
  return c;
}

}  // namespace motostab::vehicle
