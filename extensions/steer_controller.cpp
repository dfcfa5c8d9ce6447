#include "extensions/steer_controller.h"

#include <algorithm>
#include <cmath>
#include <ostream>

#include "io/number.h"

namespace motostab::extensions {


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

double calcScheduleFactor(const SteerControllerParams& spec, double v) {
  switch (spec.schedule) {
    case SteerControllerParams::Schedule::None: return 1;
    case SteerControllerParams::Schedule::Below: return std::max(spec.scheduleBelow - v, 0.0);
    case SteerControllerParams::Schedule::Table: break;
  }
  const auto& t = spec.scheduleTable;
  if (v <= t.front()[0]) return t.front()[1];
  if (v >= t.back()[0]) return t.back()[1];
  const auto hi = std::upper_bound(t.begin(), t.end(), v, [](double x, const std::array<double, 2>& r) { return x < r[0]; });
  const auto lo = hi - 1;
  const double a = (v - (*lo)[0]) / ((*hi)[0] - (*lo)[0]);
  return (1 - a) * (*lo)[1] + a * (*hi)[1];
}

double calcSteerControllerCommand(const SteerControllerParams& c, const SteerControllerInputs& x) {
  const double law = c.rollAngleGain * x.roll + c.rollRateGain * x.rollRate + c.steerAngleGain * x.steer +
                     c.steerRateGain * x.steerRate;
  return calcScheduleFactor(c, x.speed) * c.gainFactor * law;
}

double calcSaturatedTorque(const SteerControllerParams& c, double y) {
  return c.torqueLimit > 0 ? std::clamp(y, -c.torqueLimit, c.torqueLimit) : y;
}

SteerController::SteerController(SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& rearFrame,
                                 const SimTK::MobilizedBody& frontFrame, const SteerControllerParams& spec)
    : forces_(forces), rear_(rearFrame), front_(frontFrame), spec_(spec) {}

void SteerController::allocateState(SimTK::State& s) const {
  if (spec_.delay > 0) zIndex_ = forces_.allocateZ(s, SimTK::Vector(1, 0.0));
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

namespace {

// The extension: the controller element, made when the forces are added.
class SteerControllerExtension : public plugins::ExtensionModel {
 public:
  explicit SteerControllerExtension(const SteerControllerParams& p) : p_(p) {}
  void addForces(plugins::BuildContext& ctx, const plugins::VehicleFrames& frames) override {
    controller_ = std::make_shared<const SteerController>(ctx.forces, frames.rearFrame, frames.frontFrame, p_);
    SimTK::Force::Custom(ctx.forces, new SteerControllerForce(controller_));
  }
  std::vector<plugins::AuxiliaryState> getStates() const override {
    if (p_.delay > 0) return {{"steer_controller_delay", plugins::StateRole::Controller, plugins::WheelSide::None}};
    return {};
  }
  std::vector<std::string> getOutputNames() const override { return {"steer_controller_torque"}; }
  std::vector<double> calcOutputs(const SimTK::State& state) const override { return {controller_->calcTorque(state)}; }
  void describe(std::ostream& os) const override {
    using S = SteerControllerParams::Schedule;
    const SteerControllerParams& c = p_;
    os << "  steer controller      T = " << (c.schedule == S::None ? "" : "f(v) ") << c.gainFactor << " ("
       << c.rollAngleGain << " roll + " << c.rollRateGain << " roll_rate + " << c.steerAngleGain << " steer + "
       << c.steerRateGain << " steer_rate) N m (ISO signs: T > 0 steers left";
    if (c.rollAngleGain < 0 || c.rollRateGain < 0) os << "; negative roll gains steer into the fall";
    os << ")\n";
    if (c.schedule == S::Below) os << "    schedule            f(v) = " << c.scheduleBelow << " - v below " << c.scheduleBelow << " m/s, 0 above\n";
    if (c.schedule == S::Table)
      os << "    schedule            f(v) interpolated in " << c.scheduleTable.size() << " rows, " << c.scheduleTable.front()[0]
         << " to " << c.scheduleTable.back()[0] << " m/s\n";
    if (c.delay > 0) os << "    delay               " << c.delay << " s (first-order Pade; state steer_controller_delay)\n";
    if (c.torqueLimit > 0) os << "    torque limit        " << c.torqueLimit << " N m (time domain; linear models see the unsaturated law)\n";
  }

 private:
  SteerControllerParams p_;
  std::shared_ptr<const SteerController> controller_;
};

// `schedule: {below_mps: v0}` or `schedule: {table: [[v, f], ...]}` (speeds strictly increasing).
void readSchedule(io::YamlMap m, SteerControllerParams& c) {
  if (m.has("below_mps") == m.has("table")) m.fail("", "give exactly one of below_mps and table");
  if (m.has("below_mps")) {
    c.schedule = SteerControllerParams::Schedule::Below;
    c.scheduleBelow = io::readNumber(m, getSteerControllerFields().back().get("below_mps"));
  } else {
    c.schedule = SteerControllerParams::Schedule::Table;
    const YAML::Node t = m.getNode()["table"];
    m.markUsed("table");
    if (!t.IsSequence() || t.size() < 2) m.fail("table", "expected a list of at least two [speed_mps, factor] rows");
    for (size_t i = 0; i < t.size(); ++i) {
      std::array<double, 2> row{0, 0};
      if (!t[i].IsSequence() || t[i].size() != 2) m.failElement("table", i, "expected [speed_mps, factor]");
      for (size_t j = 0; j < 2; ++j) {
        const auto v = t[i][j].IsScalar() ? io::parseFiniteNumber(t[i][j].Scalar()) : std::nullopt;
        if (!v) m.failElement("table", i, "expected finite numbers [speed_mps, factor]");
        row[j] = *v;
      }
      if (i > 0 && !(row[0] > c.scheduleTable.back()[0]))
        m.failElement("table", i, "speeds must increase strictly (not sorted by speed)");
      c.scheduleTable.push_back(row);
    }
  }
  m.finish();
}

}  // namespace

const std::vector<std::string>& getSteerControllerScalarKeys() {
  static const std::vector<std::string> keys = [] {
    std::vector<std::string> k;
    for (const io::Field& f : getSteerControllerFields().front().fields)
      if (f.shape == io::Shape::Number) k.push_back(f.key);
    return k;
  }();
  return keys;
}

const std::vector<io::SectionFields>& getSteerControllerFields() {
  using io::Field;
  using io::Quantity;
  using io::Range;
  using io::Shape;
  static const std::vector<io::SectionFields> f{
      {"steer_controller",
       {Field::number("roll_angle_Nm_per_rad", "N m/rad", Range::Any, "k_phi").withDefault(0).measures(Quantity::Other),
        Field::number("roll_rate_Nms_per_rad", "N m s/rad", Range::Any, "k_phid").withDefault(0).measures(Quantity::Other),
        Field::number("steer_angle_Nm_per_rad", "N m/rad", Range::Any, "k_delta").withDefault(0).measures(Quantity::Other),
        Field::number("steer_rate_Nms_per_rad", "N m s/rad", Range::Any, "k_deltad").withDefault(0).measures(Quantity::Other),
        Field::number("gain_factor", "", Range::Positive,
                      "g, multiplies every gain (the diagnosis fits it as `steer_controller_gain`)")
            .withDefault(1)
            .measures(Quantity::Other),
        Field::of(Shape::Other, "schedule", "", "", "`{below_mps: v0}` or `{table: [[speed_mps, factor], ...]}` (below)").optional(),
        Field::number("delay_s", "s", Range::Any,
                      "tau, a first-order Pade delay adding the z state `steer_controller_delay` (N m); 0: none (a "
                      "shorter delay's Pade root -2/tau would swamp every other root)")
            .within("0, or >= 1e-4")
            .withDefault(0)
            .measures(Quantity::Other),
        Field::number("torque_limit_Nm", "N m", Range::Positive, "L, saturation of the applied torque; absent: none").optional()}},
      {"steer_controller.schedule",
       {Field::number("below_mps", "m/s", Range::Positive, "v0: gains per m/s times v0 - v below v0, zero above; give exactly one of `below_mps` and `table`")
            .optional()
            .measures(Quantity::Other),
        Field::of(Shape::Other, "table", "", "at least two rows, speeds strictly increasing",
                  "`[[speed_mps, factor], ...]`: factor linear in speed, held beyond the ends")
            .optional()}}};
  return f;
}

SteerControllerParams readSteerController(io::YamlMap& m) {
  const io::SectionFields& f = getSteerControllerFields().front();
  SteerControllerParams c;
  c.rollAngleGain = io::readNumber(m, f.get("roll_angle_Nm_per_rad"));
  c.rollRateGain = io::readNumber(m, f.get("roll_rate_Nms_per_rad"));
  c.steerAngleGain = io::readNumber(m, f.get("steer_angle_Nm_per_rad"));
  c.steerRateGain = io::readNumber(m, f.get("steer_rate_Nms_per_rad"));
  c.gainFactor = io::readNumber(m, f.get("gain_factor"));
  if (m.has("schedule")) readSchedule(m.getMap("schedule"), c);
  const io::Field& delay = f.get("delay_s");
  c.delay = m.getZeroOrAtLeast(delay.key, kMinSteerDelay, delay.unit, delay.fallback);
  if (m.has("torque_limit_Nm")) c.torqueLimit = io::readNumber(m, f.get("torque_limit_Nm"));
  return c;
}

std::unique_ptr<plugins::ExtensionModel> makeSteerController(const SteerControllerParams& p) {
  return std::make_unique<SteerControllerExtension>(p);
}

void registerSteerController(plugins::PluginRegistrar& registry) {
  for (const io::SectionFields& f : getSteerControllerFields()) registry.addSectionFields(f);
  registry.addExtensionModel("steer_controller", [](io::YamlMap& m, const plugins::VehicleLayout&) {
    return makeSteerController(readSteerController(m));
  });
}

}  // namespace motostab::extensions
