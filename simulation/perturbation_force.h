#pragma once
// The force element of a simulation: perturbation pulses and the PI speed controller (Force::Custom).
#include <string>
#include <utility>
#include <vector>

#include "simulation/simulation.h"

namespace motostab::simulation::detail {

/// Rear wheel centre velocity along the heading (yaw) direction, m/s.
inline double calcHeadingSpeed(const vehicle::VehicleModel& model, const SimTK::State& s) {
  const vehicle::CoordinateIndices& ix = model.getIndices();
  const double yaw = s.getQ()[ix.yaw];
  return std::cos(yaw) * s.getU()[ix.x] + std::sin(yaw) * s.getU()[ix.y];
}

// Time-varying perturbation forces and the PI speed controller as one Force::Custom element.
// Pulses switch on and off only between integration segments (a discrete variable holds the
// segment index), so no integrator step straddles a discontinuity.
class PerturbationForce : public SimTK::Force::Custom::Implementation {
 public:
  PerturbationForce(SimTK::GeneralForceSubsystem& forces, const vehicle::VehicleModel& model, std::vector<Perturbation> pulses,
                    std::vector<double> segmentStarts, bool speedControl, double kp, double ki, double targetSpeed)
      : forces_(forces), model_(model), pulses_(std::move(pulses)), segmentStarts_(std::move(segmentStarts)),
        speedControl_(speedControl), kp_(kp), ki_(ki), targetSpeed_(targetSpeed) {}

  void realizeTopology(SimTK::State& s) const override {
    segmentIndex_ = forces_.allocateDiscreteVariable(s, SimTK::Stage::Dynamics, new SimTK::Value<int>(0));
    if (speedControl_) zIndex_ = forces_.allocateZ(s, SimTK::Vector(1, 0.0));
  }

  void setSegment(SimTK::State& s, int k) const {
    SimTK::Value<int>::updDowncast(forces_.updDiscreteVariable(s, segmentIndex_)) = k;
  }

  int getSegment(const SimTK::State& s) const {
    return SimTK::Value<int>::downcast(forces_.getDiscreteVariable(s, segmentIndex_));
  }

  /// Sum of the active pulses of `kind` (on `body` for lateral forces, "" = any body).
  double calcPulses(const SimTK::State& s, PerturbationKind kind, const std::string& body = "") const {
    const double t0 = segmentStarts_[getSegment(s)];  // pulses are constant in on/off state over a segment
    double sum = 0;
    for (const auto& p : pulses_)
      if (p.kind == kind && (body.empty() || p.body == body) && p.start <= t0 && t0 < p.start + p.duration)
        sum += p.calcPulseValue(s.getTime());
    return sum;
  }

  /// Controller part of the drive torque, N m (0 without speed control).
  double calcControlTorque(const SimTK::State& s) const {
    if (!speedControl_) return 0;
    return kp_ * (targetSpeed_ - calcHeadingSpeed(model_, s)) + ki_ * forces_.getZ(s)[zIndex_];
  }

  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces, SimTK::Vector_<SimTK::Vec3>&,
                 SimTK::Vector& mobilityForces) const override {
    const double tau = calcPulses(s, PerturbationKind::SteerTorque);
    if (tau != 0) model_.getFrontFrame().applyOneMobilityForce(s, 0, tau, mobilityForces);
    for (const char* name : {"rear_frame", "front_frame", "rear_wheel", "front_wheel"}) {
      const double f = calcPulses(s, PerturbationKind::LateralForce, name);
      if (f == 0) continue;
      const SimTK::MobilizedBody& b = getBody(name);
      b.applyForceToBodyPoint(s, b.getBodyMassCenterStation(s), SimTK::Vec3(0, f, 0), bodyForces);
    }
    if (speedControl_) {
      model_.getRearWheel().applyOneMobilityForce(s, 0, calcControlTorque(s), mobilityForces);
      forces_.updZDot(s)[zIndex_] = targetSpeed_ - calcHeadingSpeed(model_, s);
    }
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State&) const override { return 0; }

 private:
  const SimTK::MobilizedBody& getBody(const std::string& name) const {
    if (name == "rear_frame") return model_.getRearFrame();
    if (name == "front_frame") return model_.getFrontFrame();
    if (name == "rear_wheel") return model_.getRearWheel();
    return model_.getFrontWheel();
  }

  SimTK::GeneralForceSubsystem& forces_;
  const vehicle::VehicleModel& model_;  // complete by the time forces are evaluated
  std::vector<Perturbation> pulses_;
  std::vector<double> segmentStarts_;
  bool speedControl_;
  double kp_, ki_, targetSpeed_;
  mutable SimTK::DiscreteVariableIndex segmentIndex_;
  mutable SimTK::ZIndex zIndex_;
};

}  // namespace motostab::simulation::detail
