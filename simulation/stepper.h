#pragma once
// One integration back end behind a small interface: Simbody's integrators, or the ROS34PW2
// W-method (simulation/rosenbrock.h) for models without constraints.
#include <memory>
#include <string>
#include <vector>

#include <Simbody.h>

namespace motostab::simulation {

/// ASCII lower case, for case-insensitive option names.
std::string toLowerCase(std::string s);

enum class IntegratorKind { Auto, Rosenbrock, RungeKuttaMerson, RungeKutta3, CPodes, Verlet };

/// "auto", "ros34pw2" / "rosenbrock", "rkm" / "RungeKuttaMerson", "rk3" / "RungeKutta3",
/// "cpodes" / "CPodes", "verlet" / "Verlet" (case-insensitive). Throws InputError (key
/// "--integrator") on an unknown name.
IntegratorKind parseIntegratorKind(const std::string& name);
std::string getIntegratorName(IntegratorKind kind);

/// True if the system has position, velocity or acceleration constraint equations.
bool hasConstraints(const SimTK::State& state);

/// Auto resolves to Rosenbrock for systems without constraint equations (force-based tyres) and to
/// RungeKuttaMerson otherwise (rolling constraints need Simbody's projection).
IntegratorKind resolveIntegratorKind(IntegratorKind kind, const SimTK::State& state);

struct StepperOptions {
  IntegratorKind kind = IntegratorKind::Auto;
  double accuracy = 1e-6;             ///< relative accuracy; absolute on a unit scale (1 rad, 1 m, 1 rad/s)
  double constraintTolerance = 0;     ///< <= 0: equal to accuracy (Simbody integrators only)
  bool projectEveryStep = false;      ///< Simbody integrators only
  double maxStep = 0;                 ///< s; 0: the integrator's default (ROS34PW2 0.05 s, Simbody none)
  std::vector<int> cyclicY;           ///< indices in y = [q; u; z] that f does not depend on (ROS34PW2 only)
};

/// Advances a State one internal step at a time; the driver interpolates samples between steps.
class Stepper {
 public:
  virtual ~Stepper() = default;
  /// One internal step, ending no later than min(tEnd, tEvent) (s).
  virtual void step(double tEnd, double tEvent) = 0;
  virtual double getTime() const = 0;
  virtual const SimTK::Vector& getY() const = 0;
  /// dy/dt at the current state.
  virtual const SimTK::Vector& getYDot() = 0;
  /// The current state, to change discrete variables or y at a discontinuity; call reinitialize().
  virtual SimTK::State& updState() = 0;
  virtual void reinitialize() = 0;
  virtual int getNumSteps() const = 0;
  virtual std::string getName() const = 0;
};

/// Makes and initialises a stepper at `initial`.
std::unique_ptr<Stepper> makeStepper(const SimTK::MultibodySystem& system, const SimTK::State& initial,
                                     const StepperOptions& options);

}  // namespace motostab::simulation
