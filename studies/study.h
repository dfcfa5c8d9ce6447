#pragma once
// The seed paper's swingarm study (sec. 4): sweeps of the rigid, bending, torsion and twist models,
// at identified and at halved stiffness, and weave mode shapes.
#include <complex>
#include <string>
#include <vector>

#include "analysis/sweep.h"
#include "scenario/scenario_source.h"
#include "scenario/parameter_overrides.h"

namespace motostab::studies {

struct StudyVariant {
  std::string name;                    ///< rigid, bending, torsion, twist
  scenario::ParameterOverrides overrides;  ///< scenario changes that select it
  analysis::SweepResult sweep;
};

/// One component of a mode shape: amplitude normalised to the largest component, phase relative to steer.
struct ShapeComponent {
  std::string name;  ///< roll, yaw, steer, lateral (displacement / wheelbase), swingarm_*
  double amplitude = 0;
  double phaseDeg = 0;
};

struct ModeShape {
  double speed = 0;                    ///< m/s
  std::complex<double> eigenvalue;     ///< 1/s
  std::vector<ShapeComponent> components;
};

struct StudyOptions {
  analysis::SweepOptions sweep;
  std::vector<std::string> variants{"rigid", "bending", "torsion", "twist"};
  double stiffnessScale = 0.5;             ///< the seed's "doubled compliances" (Fig. 11)
  double dampingScale = 1.0 / std::sqrt(2.0);  ///< sqrt(stiffnessScale) keeps each damping ratio (seed eq. 18)
  std::string shapeVariant = "torsion";
  std::vector<double> shapeSpeeds{10.0, 18.5, 30.0};
  scenario::ParameterOverrides overrides;  ///< applied to every variant first
  int threads = 2;
};

struct StudyResult {
  std::string scenario;
  double wheelbase = 0;
  std::vector<StudyVariant> nominal, halved;
  std::vector<ModeShape> weaveShapes;      ///< of options.shapeVariant, nominal stiffness
};

/// Runs every variant at identified and scaled stiffness (in parallel when threads > 1), each built from
/// `source` (the scenario file read once) with the options' and the variant's typed changes.
StudyResult runStudy(const scenario::ScenarioSource& source, const StudyOptions& options);

/// The weave shape of `model` at `speed`, continuing the weave of `sweep` (seed Fig. 12).
/// io::ResultError if the sweep has no weave.
ModeShape calcWeaveShape(const vehicle::VehicleModel& model, const analysis::SweepResult& sweep, double speed, const analysis::SweepOptions& options);

/// The branch labelled `label` (at most speeds) with a non-negative imaginary part at the last speed
/// (nullptr if none).
const analysis::ModeBranch* findBranch(const analysis::SweepResult& sweep, analysis::ModeLabel label);

}  // namespace motostab::studies
