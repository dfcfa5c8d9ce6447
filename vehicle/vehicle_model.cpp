#include "vehicle/vehicle_model.h"

#include "multibody/pin_joint.h"
#include "plugins/builtin.h"
#include "plugins/rigid_body.h"
#include "scenario/whole_vehicle.h"

namespace motostab::vehicle {

using io::InputError;
using multibody::addPinAtDesignPose;
using plugins::BuildContext;
using plugins::ExtensionBody;
using plugins::ExtensionModel;
using plugins::FrameMasses;
using plugins::BodyCarrier;
using plugins::VehicleFrames;
using plugins::PluginRegistry;
using plugins::SwingarmAssembly;
using plugins::SwingarmModel;
using plugins::SwingarmSite;
using plugins::WheelSite;
using plugins::makeBuiltinRegistry;
using plugins::makeScenarioRegistry;
using plugins::makeRigidBody;
using plugins::toVec3;
using scenario::BodySpec;
using scenario::NamedBody;
using scenario::Scenario;
using scenario::SwingarmFrame;
using scenario::WheelSpec;
using scenario::calcStaticWheelLoads;
using scenario::calcSwingarmFrame;
using scenario::rethrowNamingOverride;


using SimTK::MobilizedBody;
using SimTK::Rotation;
using SimTK::Transform;
using SimTK::Vec3;

namespace {

SimTK::Body::Rigid makeWheel(const WheelSpec& w) {
  return SimTK::Body::Rigid(SimTK::MassProperties(
      w.mass, Vec3(0), SimTK::Inertia(w.diametralInertia, w.axialInertia, w.diametralInertia)));
}

// What addRearAssembly and addFrontAssembly built: the mobilizers, the swingarm model, and the
// named one-DOF mobilizers with their roles (swingarm compliance; extension coordinates such as
// rider_lean, suspension_pitch, fork_bending, fork_torsion).
using NamedMobilizers = std::vector<NamedMobilizer>;
using Extensions = std::vector<std::unique_ptr<ExtensionModel>>;
struct RearAssembly {
  MobilizedBody rearFrame, rearWheel;
  std::unique_ptr<SwingarmModel> swingarm;
  NamedMobilizers compliance, extension;
};
struct FrontAssembly {
  MobilizedBody frontFrame, frontWheel;
  NamedMobilizers extension;
};
struct CoordinateNames {
  CoordinateIndices idx;
  std::vector<StateInfo> q, u;
};

// Hub positions in D: the rear and front frames' body origins.
Vec3 getRearHub(const Scenario& s) { return Vec3(0, 0, s.rearWheel.radius); }
Vec3 getFrontHub(const Scenario& s) { return Vec3(s.geometry.wheelbase, 0, s.frontWheel.radius); }

// The frames' mass properties after every extension took or moved its share (adjustFrames, in order);
// each must remain a body (each extension checks its own share; together they may take too much).
FrameMasses calcFrameMasses(const Scenario& s, const Extensions& extensions) {
  FrameMasses frames{s.rearFrame, s.frontFrame};
  for (const auto& e : extensions) e->adjustFrames(frames);
  for (const auto& [name, b] : {std::pair{"rear_frame", frames.rearFrame}, std::pair{"front_frame", frames.frontFrame}}) {
    const std::string why = b.mass > 0 ? scenario::checkInertia(b.inertia) : "no mass left";
    if (!why.empty())
      throw InputError({s.sourceFile, 0, 0, name}, std::string("the model extensions together take more than the ") + name +
                                                       " has: what remains of it is no body (" + why + ")");
  }
  return frames;
}

// The bodies of the model of `s` with `extensions` (listModelBodies).
std::vector<NamedBody> listBodiesWith(const Scenario& s, const Extensions& extensions) {
  const FrameMasses frames = calcFrameMasses(s, extensions);
  std::vector<NamedBody> out{{"rear_frame", frames.rearFrame}};
  auto addTakenFrom = [&](ExtensionBody::Frame frame) {
    for (const auto& e : extensions)
      for (const ExtensionBody& b : e->getBodies())
        if (b.takenFrom == frame) out.push_back(b.body);
  };
  addTakenFrom(ExtensionBody::Frame::Rear);
  for (NamedBody& b : scenario::listOtherBodies(s)) {
    if (b.name == "front_frame") {
      out.push_back({"front_frame", frames.frontFrame});
      addTakenFrom(ExtensionBody::Frame::Front);
    } else {
      out.push_back(std::move(b));
    }
  }
  return out;
}

// The carrier the extensions put in series between two parts (`between` names them): at most one.
BodyCarrier addCarrier(const Scenario& s, const std::string& between, const Extensions& extensions,
                       const std::function<BodyCarrier(ExtensionModel&)>& stage) {
  BodyCarrier out;
  for (const auto& e : extensions) {
    BodyCarrier c = stage(*e);
    if (c.carrier.isEmptyHandle()) continue;
    if (!out.carrier.isEmptyHandle())
      throw InputError({s.sourceFile, 0, 0, ""}, "two model extensions each put a carrier between " + between);
    out = std::move(c);
  }
  return out;
}

// Rear frame on a Bushing whose frames are permuted (F.x = G.z, F.y = G.x, F.z = G.y) so that its
// body-fixed 1-2-3 angles are yaw, roll, pitch and its translations are height, x, y; the extensions'
// rear bodies (a leaning rider's upper body) hang from it. The rear wheel hangs from the rear frame,
// or from the swingarm's hub carrier.
RearAssembly addRearAssembly(const Scenario& s, const BodySpec& rearBody, PluginRegistry& registry, BuildContext& ctx,
                             const Extensions& extensions) {
  RearAssembly out;
  const Vec3 pRearHub_D = getRearHub(s);
  const Rotation R_perm(SimTK::Mat33(0, 1, 0, 0, 0, 1, 1, 0, 0), true);
  out.rearFrame = MobilizedBody::Bushing(ctx.matter.Ground(), Transform(R_perm, Vec3(0)), makeRigidBody(rearBody, pRearHub_D),
                                         Transform(R_perm, Vec3(0)));
  const VehicleFrames frames{out.rearFrame, MobilizedBody(), pRearHub_D, getFrontHub(s)};
  for (const auto& e : extensions)
    for (NamedMobilizer& m : e->addRearBodies(ctx, frames)) out.extension.push_back(std::move(m));
  if (!s.hasSwingarm) {
    out.rearWheel = addPinAtDesignPose(out.rearFrame, Transform(), makeWheel(s.rearWheel), Vec3(0), Vec3(0, 1, 0));
    return out;
  }
  out.swingarm = registry.createSwingarmModel(s.swingarm, s.inputs);
  const SwingarmFrame f = calcSwingarmFrame(s);
  const Rotation R_RS(SimTK::Mat33(f.x[0], f.y[0], f.z[0], f.x[1], f.y[1], f.z[1], f.x[2], f.y[2], f.z[2]), true);
  // The swingarm hangs from the rear frame, or from the carrier an extension puts at the pivot (the
  // rear suspension's link: compliance in series).
  MobilizedBody armParent = out.rearFrame;
  Vec3 p_PS = toVec3(f.origin) - pRearHub_D;
  const BodyCarrier carrier = addCarrier(s, "the rear frame and the swingarm", extensions, [&](ExtensionModel& e) {
    return e.addSwingarmCarrier(ctx, frames, toVec3(f.origin));
  });
  if (!carrier.carrier.isEmptyHandle()) {
    armParent = carrier.carrier;
    p_PS = Vec3(0);
    for (const NamedMobilizer& m : carrier.coordinates) out.extension.push_back(m);
  }
  const SwingarmSite site{armParent, Transform(R_RS, p_PS), Vec3(f.length, 0, 0), makeRigidBody(s.swingarm.body, Vec3(0))};
  const SwingarmAssembly arm = out.swingarm->addSwingarm(ctx, site);
  MobilizedBody hubCarrier = arm.hubCarrier;
  out.rearWheel = addPinAtDesignPose(hubCarrier, arm.X_CH, makeWheel(s.rearWheel), Vec3(0), Vec3(0, 1, 0));
  out.compliance = arm.coordinates;
  return out;
}

// Front frame on the steer axis through the ground point (w + c, 0, 0), tilted back by lambda; the
// front wheel on it, or on the hub carrier an extension puts between them (fork_compliance).
FrontAssembly addFrontAssembly(const Scenario& s, const BodySpec& frontBody, BuildContext& ctx, MobilizedBody& rearFrame,
                               const Extensions& extensions) {
  FrontAssembly out;
  const double w = s.geometry.wheelbase, lambda = s.geometry.steerAxisTilt;
  const Vec3 pRearHub_D = getRearHub(s), pFrontHub_D = getFrontHub(s);
  const Vec3 steerAxis(-std::sin(lambda), 0, std::cos(lambda));
  const Vec3 pSteer_D(w + s.geometry.trail, 0, 0);
  out.frontFrame = addPinAtDesignPose(rearFrame, Transform(pFrontHub_D - pRearHub_D), makeRigidBody(frontBody, pFrontHub_D),
                                      pSteer_D - pFrontHub_D, steerAxis);
  const VehicleFrames frames{rearFrame, out.frontFrame, pRearHub_D, pFrontHub_D};
  BodyCarrier c = addCarrier(s, "the front frame and the front wheel", extensions,
                             [&](ExtensionModel& e) { return e.addFrontHubCarrier(ctx, frames); });
  MobilizedBody carrier = c.carrier.isEmptyHandle() ? out.frontFrame : c.carrier;
  out.extension = std::move(c.coordinates);
  out.frontWheel = addPinAtDesignPose(carrier, Transform(), makeWheel(s.frontWheel), Vec3(0), Vec3(0, 1, 0));
  return out;
}

// Indices, names and roles of the coordinates (q) and speeds (u) of a realized-to-Model state.
CoordinateNames nameCoordinates(const SimTK::State& state, const RearAssembly& rear, const FrontAssembly& front) {
  CoordinateNames out;
  CoordinateIndices& idx = out.idx;
  std::vector<StateInfo>& names = out.q;
  const int qR = rear.rearFrame.getFirstQIndex(state);
  idx.yaw = qR;
  idx.roll = qR + 1;
  idx.pitch = qR + 2;
  idx.height = qR + 3;
  idx.x = qR + 4;
  idx.y = qR + 5;
  idx.steer = front.frontFrame.getFirstQIndex(state);
  idx.rearSpin = rear.rearWheel.getFirstQIndex(state);
  idx.frontSpin = front.frontWheel.getFirstQIndex(state);
  names.assign(state.getNQ(), StateInfo{});
  const std::pair<int, StateInfo> fixed[] = {
      {idx.yaw, {"yaw", StateRole::Yaw}},         {idx.roll, {"roll", StateRole::Roll}},
      {idx.pitch, {"pitch", StateRole::Pitch}},   {idx.height, {"height", StateRole::Height}},
      {idx.x, {"x", StateRole::Forward}},         {idx.y, {"y", StateRole::Lateral}},
      {idx.steer, {"steer", StateRole::Steer}},
      {idx.rearSpin, {"rear_wheel_angle", StateRole::WheelSpin, StateKind::Coordinate, WheelSide::Rear}},
      {idx.frontSpin, {"front_wheel_angle", StateRole::WheelSpin, StateKind::Coordinate, WheelSide::Front}}};
  for (const auto& [q, info] : fixed) names[q] = info;
  auto addNames = [&](const NamedMobilizers& list, std::vector<int>& indices) {
    for (const NamedMobilizer& m : list) {
      const int q = m.mobilizer.getFirstQIndex(state);
      names[q] = {m.name, m.role};
      indices.push_back(q);
    }
  };
  addNames(rear.compliance, idx.compliance);
  addNames(rear.extension, idx.extension);
  addNames(front.extension, idx.extension);
  for (StateInfo n : names) {
    n.name += "_rate";
    n.kind = StateKind::Rate;
    out.u.push_back(n);
  }
  out.u[idx.x].name = "vx";
  out.u[idx.y].name = "vy";
  out.u[idx.height].name = "vz";
  return out;
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
  registry.loadScenarioLibraries(s);
  registry_ = registry;
  extensions_ = extensions;
  auto contact = registry.createContactModel(s.contact, s.inputs);
  extensionModels_ = registry.createExtensionModels(s, s.inputs);
  BuildContext ctx{system_, matter_, forces_, s.gravity};

  const FrameMasses frames = calcFrameMasses(s, extensionModels_);
  RearAssembly rear = addRearAssembly(s, frames.rearFrame, registry, ctx, extensionModels_);
  rearFrame_ = rear.rearFrame;
  rearWheel_ = rear.rearWheel;
  swingarm_ = std::move(rear.swingarm);
  const FrontAssembly front = addFrontAssembly(s, frames.frontFrame, ctx, rearFrame_, extensionModels_);
  frontFrame_ = front.frontFrame;
  frontWheel_ = front.frontWheel;

  SimTK::Force::Gravity(forces_, matter_, -SimTK::ZAxis, s.gravity);
  inputs_ = SimTK::Force::DiscreteForces(forces_, matter_);
  const auto loads = calcStaticWheelLoads(s);
  const WheelSite rearSite{"rear_wheel", WheelSide::Rear, rearWheel_, s.rearWheel.radius, s.rearWheel.crownRadius, loads[0]};
  const WheelSite frontSite{"front_wheel", WheelSide::Front, frontWheel_, s.frontWheel.radius, s.frontWheel.crownRadius,
                            loads[1]};
  wheelSites_ = {rearSite, frontSite};
  auto addZ = [&](const std::vector<AuxiliaryState>& states) {
    for (const AuxiliaryState& z : states) zStates_.push_back({z.name, z.role, StateKind::Auxiliary, z.wheel});
  };
  for (const WheelSite* site : {&rearSite, &frontSite}) {
    contact->addWheel(ctx, *site);
    addZ(contact->getStates(*site));
  }
  contacts_.push_back(std::move(contact));
  const VehicleFrames vehicleFrames{rearFrame_, frontFrame_, getRearHub(s), getFrontHub(s)};
  for (const auto& e : extensionModels_) {
    e->addForces(ctx, vehicleFrames);
    addZ(e->getStates());
  }
  for (const auto& extend : extensions) addZ(extend(ctx, *this));
  for (const StateInfo& z : zStates_) zNames_.push_back(z.name);

  defaultState_ = system_.realizeTopology();
  system_.realizeModel(defaultState_);
  nq_ = defaultState_.getNQ();
  if (defaultState_.getNU() != nq_) throw std::logic_error("vehicle model: every mobilizer must have u = qdot");
  if (defaultState_.getNZ() != static_cast<int>(zNames_.size()))
    throw std::logic_error("vehicle model: contact plugins allocated z states they did not name");
  CoordinateNames names = nameCoordinates(defaultState_, rear, front);
  idx_ = names.idx;
  qStates_ = std::move(names.q);
  uStates_ = std::move(names.u);
  for (const StateInfo& q : qStates_) qNames_.push_back(q.name);
  for (const StateInfo& u : uStates_) uNames_.push_back(u.name);
  defaultState_.updQ()[idx_.height] = s.rearWheel.radius;
  system_.realize(defaultState_, SimTK::Stage::Instance);
}

std::vector<std::string> VehicleModel::getExtensionOutputNames() const {
  std::vector<std::string> out;
  for (const auto& e : extensionModels_)
    for (const auto& n : e->getOutputNames()) out.push_back(n);
  return out;
}

std::vector<double> VehicleModel::calcExtensionOutputs(const SimTK::State& state) const {
  std::vector<double> out;
  for (const auto& e : extensionModels_)
    for (double v : e->calcOutputs(state)) out.push_back(v);
  return out;
}

void VehicleModel::describeExtensions(std::ostream& out) const {
  for (const auto& e : extensionModels_) e->describe(out);
}

std::vector<NamedBody> VehicleModel::listBodies() const { return listBodiesWith(scenario_, extensionModels_); }

std::vector<NamedBody> listModelBodies(const Scenario& s) {
  const PluginRegistry registry = makeScenarioRegistry(s);
  try {
    return listBodiesWith(s, registry.createExtensionModels(s, s.inputs));
  } catch (const InputError& e) {
    rethrowNamingOverride(e, s.overrides);
  }
}

bool VehicleModel::applyLateralRoadStep(SimTK::State& state, WheelSide wheel, double offset) const {
  for (const WheelSite& site : wheelSites_)
    if (site.side == wheel) return contacts_.front()->applyLateralRoadStep(state, site, offset);
  return false;
}

plugins::ContactPoint VehicleModel::calcContactPoint(const SimTK::State& state, WheelSide wheel) const {
  for (const WheelSite& site : wheelSites_)
    if (site.side == wheel) {
      const bool moving = state.getSystemStage() >= SimTK::Stage::Velocity;
      return contacts_.front()->calcContactPoint(site, site.wheel.getBodyRotation(state),
                                                 moving ? site.wheel.getBodyAngularVelocity(state) : Vec3(0));
    }
  throw std::logic_error("calcContactPoint: no such wheel");
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

}  // namespace motostab::vehicle
