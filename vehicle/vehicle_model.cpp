#include "vehicle/vehicle_model.h"

#include "swingarm/compliance/swingarm_compliance.h"
#include "tyres/relaxation_linear.h"
#include "tyres/rolling_no_slip.h"
#include "vehicle/aerodynamics.h"
#include "vehicle/body_builder.h"
#include "vehicle/fork_compliance.h"
#include "vehicle/rider_lean.h"
#include "vehicle/steer_damper.h"

namespace motostab {

using SimTK::MobilizedBody;
using SimTK::Rotation;
using SimTK::Transform;
using SimTK::UnitVec3;
using SimTK::Vec3;

PluginRegistry makeBuiltinRegistry() {
  PluginRegistry registry;
  registerRollingNoSlip(registry);
  registerRelaxationLinear(registry);
  registerSwingarmModels(registry);
  return registry;
}

namespace {

SimTK::Body::Rigid makeWheel(const WheelSpec& w) {
  return SimTK::Body::Rigid(SimTK::MassProperties(
      w.mass, Vec3(0), SimTK::Inertia(w.diametralInertia, w.axialInertia, w.diametralInertia)));
}

// The rear suspension: a massless link on a pin about the design y axis through the pivot (at
// p_RP in the rear frame; q > 0 lifts the hub), its body frame parallel to the design frame at
// q = 0. The spring's free angle is set so that it carries the static pivot moment at q = 0.
MobilizedBody::Pin addSuspension(BuildContext& ctx, MobilizedBody& rearFrame, const Vec3& p_RP, const Scenario& s) {
  MobilizedBody::Pin link = addPinAtDesignPose(rearFrame, Transform(p_RP), SimTK::Body::Massless(), Vec3(0), Vec3(0, 1, 0));
  const SuspensionSpec& su = s.swingarm.suspension;
  const double freeAngle = -calcStaticPivotMoment(s) / su.stiffness;
  SimTK::Force::MobilityLinearSpring(ctx.forces, link, SimTK::MobilizerQIndex(0), su.stiffness, freeAngle);
  SimTK::Force::MobilityLinearDamper(ctx.forces, link, SimTK::MobilizerUIndex(0), su.damping);
  return link;
}

}  // namespace

VehicleModel::VehicleModel(const Scenario& scenario, PluginRegistry& registry,
                           const std::vector<ModelExtension>& extensions)
    : scenario_(scenario), matter_(system_), forces_(system_) {
  try {
    build(registry, extensions);
  } catch (const InputError& e) {  // e.g. a plugin parameter set by --set
    rethrowNamingOverride(e, scenario_.overrides);
  }
}

VehicleModel::VehicleModel(const Scenario& scenario) : scenario_(scenario), matter_(system_), forces_(system_) {
  PluginRegistry registry = makeBuiltinRegistry();
  try {
    build(registry, {});
  } catch (const InputError& e) {
    rethrowNamingOverride(e, scenario_.overrides);
  }
}

std::unique_ptr<VehicleModel> VehicleModel::makeReplica() const {
  PluginRegistry registry = registry_;
  return std::make_unique<VehicleModel>(scenario_, registry, extensions_);
}

void VehicleModel::build(PluginRegistry& registry, const std::vector<ModelExtension>& extensions) {
  const Scenario& s = scenario_;
  for (size_t i = 0; i < s.plugins.size(); ++i)
    registry.loadLibrary(s.plugins[i], {s.sourceFile, 0, 0, "plugins[" + std::to_string(i) + "]"});
  registry_ = registry;
  extensions_ = extensions;
  auto contact = registry.createContactModel(s.contact);

  const double w = s.geometry.wheelbase, c = s.geometry.trail, lambda = s.geometry.steerAxisTilt;
  const double rR = s.rearWheel.radius, rF = s.frontWheel.radius;
  const Vec3 pRearHub_D(0, 0, rR), pFrontHub_D(w, 0, rF);

  // Rear frame on a Bushing whose frames are permuted (F.x = G.z, F.y = G.x, F.z = G.y) so that
  // its body-fixed 1-2-3 angles are yaw, roll, pitch and its translations are height, x, y.
  const Rotation R_perm(SimTK::Mat33(0, 1, 0, 0, 0, 1, 1, 0, 0), true);
  // With a leaning rider the upper body is its own body and the rear frame keeps the rest.
  const BodySpec rearBody = s.hasRiderLean ? calcBodyRemainder(s.rearFrame, s.riderLean.body) : s.rearFrame;
  rearFrame_ = MobilizedBody::Bushing(matter_.Ground(), Transform(R_perm, Vec3(0)), makeBody(rearBody, pRearHub_D),
                                      Transform(R_perm, Vec3(0)));
  std::vector<std::pair<std::string, MobilizedBody>> extensionCoordinates;
  BuildContext ctx{system_, matter_, forces_, s.gravity};
  if (s.hasRiderLean) extensionCoordinates.push_back({"rider_lean", addRiderLean(ctx, rearFrame_, pRearHub_D, s.riderLean)});
  // Rear wheel: on the rear frame, or on the swingarm's hub carrier.
  std::vector<std::pair<std::string, MobilizedBody>> compliance;
  MobilizedBody suspension;
  if (s.hasSwingarm) {
    auto swingarmModel = registry.createSwingarmModel(s.swingarm);
    const SwingarmFrame f = calcSwingarmFrame(s);
    const Rotation R_RS(SimTK::Mat33(f.x[0], f.y[0], f.z[0], f.x[1], f.y[1], f.z[1], f.x[2], f.y[2], f.z[2]), true);
    BuildContext swingarmCtx{system_, matter_, forces_, s.gravity};
    // The swingarm hangs from the rear frame, or from the suspension link (compliance in series).
    MobilizedBody armParent = rearFrame_;
    Vec3 p_PS = toVec3(f.origin) - pRearHub_D;
    if (s.swingarm.hasSuspension) {
      suspension = armParent = addSuspension(swingarmCtx, rearFrame_, p_PS, s);
      p_PS = Vec3(0);
    }
    const SwingarmSite site{armParent, Transform(R_RS, p_PS), Vec3(f.length, 0, 0), makeBody(s.swingarm.body, Vec3(0))};
    const SwingarmAssembly arm = swingarmModel->addSwingarm(swingarmCtx, site);
    MobilizedBody carrier = arm.hubCarrier;
    rearWheel_ = addPinAtDesignPose(carrier, arm.X_CH, makeWheel(s.rearWheel), Vec3(0), Vec3(0, 1, 0));
    compliance = arm.coordinates;
    swingarm_ = std::move(swingarmModel);
  } else {
    rearWheel_ = addPinAtDesignPose(rearFrame_, Transform(), makeWheel(s.rearWheel), Vec3(0), Vec3(0, 1, 0));
  }
  // Steer axis through the ground point (w + c, 0, 0), tilted back by lambda.
  const Vec3 steerAxis(-std::sin(lambda), 0, std::cos(lambda));
  const Vec3 pSteer_D(w + c, 0, 0);
  const BodySpec frontBody = s.hasForkCompliance ? calcBodyRemainder(s.frontFrame, s.forkCompliance.carrier) : s.frontFrame;
  frontFrame_ = addPinAtDesignPose(rearFrame_, Transform(pFrontHub_D - pRearHub_D), makeBody(frontBody, pFrontHub_D),
                                   pSteer_D - pFrontHub_D, steerAxis);
  MobilizedBody frontCarrier = frontFrame_;
  if (s.hasForkCompliance) {
    const ForkAssembly fork = addForkCompliance(ctx, frontFrame_, pFrontHub_D, s);
    frontCarrier = fork.hubCarrier;
    for (const auto& c : fork.coordinates) extensionCoordinates.push_back(c);
  }
  frontWheel_ = addPinAtDesignPose(frontCarrier, Transform(), makeWheel(s.frontWheel), Vec3(0), Vec3(0, 1, 0));

  SimTK::Force::Gravity(forces_, matter_, -SimTK::ZAxis, s.gravity);
  inputs_ = SimTK::Force::DiscreteForces(forces_, matter_);

  const auto loads = calcStaticWheelLoads(s);
  const WheelSite rear{"rear_wheel", rearWheel_, rR, s.rearWheel.crownRadius, loads[0]};
  const WheelSite front{"front_wheel", frontWheel_, rF, s.frontWheel.crownRadius, loads[1]};
  wheelSites_ = {rear, front};
  for (const WheelSite* site : {&rear, &front}) {
    contact->addWheel(ctx, *site);
    for (const auto& n : contact->getStateNames(*site)) zNames_.push_back(n);
  }
  contacts_.push_back(std::move(contact));
  if (s.hasAerodynamics) addAerodynamicDrag(ctx, rearFrame_, s.aerodynamics, toVec3(s.aerodynamics.centreOfPressure) - pRearHub_D);
  if (s.hasSteerDamper) addSteerDamper(ctx, frontFrame_, s.steerDamper);
  for (const auto& extend : extensions)
    for (const auto& n : extend(ctx, *this)) zNames_.push_back(n);

  defaultState_ = system_.realizeTopology();
  system_.realizeModel(defaultState_);
  nq_ = defaultState_.getNQ();
  if (defaultState_.getNU() != nq_) throw std::logic_error("vehicle model: every mobilizer must have u = qdot");
  if (defaultState_.getNZ() != static_cast<int>(zNames_.size()))
    throw std::logic_error("vehicle model: contact plugins allocated z states they did not name");

  const int qR = rearFrame_.getFirstQIndex(defaultState_);
  idx_.yaw = qR;
  idx_.roll = qR + 1;
  idx_.pitch = qR + 2;
  idx_.height = qR + 3;
  idx_.x = qR + 4;
  idx_.y = qR + 5;
  idx_.steer = frontFrame_.getFirstQIndex(defaultState_);
  idx_.rearSpin = rearWheel_.getFirstQIndex(defaultState_);
  idx_.frontSpin = frontWheel_.getFirstQIndex(defaultState_);
  qNames_.assign(nq_, "");
  qNames_[idx_.yaw] = "yaw";
  qNames_[idx_.roll] = "roll";
  qNames_[idx_.pitch] = "pitch";
  qNames_[idx_.height] = "height";
  qNames_[idx_.x] = "x";
  qNames_[idx_.y] = "y";
  qNames_[idx_.steer] = "steer";
  qNames_[idx_.rearSpin] = "rear_wheel_angle";
  qNames_[idx_.frontSpin] = "front_wheel_angle";
  if (!suspension.isEmptyHandle()) {
    idx_.suspension = suspension.getFirstQIndex(defaultState_);
    qNames_[idx_.suspension] = "suspension_pitch";
  }
  for (const auto& [name, mobod] : compliance) {
    const int q = mobod.getFirstQIndex(defaultState_);
    qNames_[q] = name;
    idx_.compliance.push_back(q);
  }
  for (const auto& [name, mobod] : extensionCoordinates) {
    const int q = mobod.getFirstQIndex(defaultState_);
    qNames_[q] = name;
    idx_.extension.push_back(q);
  }
  for (const auto& n : qNames_) uNames_.push_back(n + "_rate");
  uNames_[idx_.x] = "vx";
  uNames_[idx_.y] = "vy";
  uNames_[idx_.height] = "vz";

  defaultState_.updQ()[idx_.height] = rR;
  system_.realize(defaultState_, SimTK::Stage::Instance);
}

bool VehicleModel::applyLateralRoadStep(SimTK::State& state, const std::string& wheel, double offset) const {
  for (const WheelSite& site : wheelSites_)
    if (site.name == wheel) return contacts_.front()->applyLateralRoadStep(state, site, offset);
  return false;
}

std::vector<std::string> VehicleModel::getContactOutputNames() const {
  std::vector<std::string> out;
  for (const WheelSite& site : wheelSites_)
    for (const auto& n : contacts_.front()->getOutputNames(site)) out.push_back(n);
  return out;
}

std::vector<double> VehicleModel::calcContactOutputs(const SimTK::State& state) const {
  std::vector<double> out;
  for (const WheelSite& site : wheelSites_)
    for (double v : contacts_.front()->calcOutputs(state, site)) out.push_back(v);
  return out;
}

void VehicleModel::setInput(SimTK::State& state, Input which, double value) const {
  switch (which) {
    case Input::SteerTorque:
      inputs_.setOneMobilityForce(state, frontFrame_, SimTK::MobilizerUIndex(0), value);
      break;
    case Input::DriveTorque:
      inputs_.setOneMobilityForce(state, rearWheel_, SimTK::MobilizerUIndex(0), value);
      break;
    case Input::RollTorque:
      inputs_.setOneBodyForce(state, rearFrame_, SimTK::SpatialVec(Vec3(value, 0, 0), Vec3(0)));
      break;
  }
}

double VehicleModel::getInput(const SimTK::State& state, Input which) const {
  switch (which) {
    case Input::SteerTorque: return inputs_.getOneMobilityForce(state, frontFrame_, SimTK::MobilizerUIndex(0));
    case Input::DriveTorque: return inputs_.getOneMobilityForce(state, rearWheel_, SimTK::MobilizerUIndex(0));
    case Input::RollTorque: return inputs_.getOneBodyForce(state, rearFrame_)[0][0];
  }
  return 0;
}

}  // namespace motostab
