#pragma once
// The names of the analysis chain (scenario -> model -> trim -> linearisation -> sweep) that many tests
// use, declared once in motostab::testing. A test in another namespace brings them in with
// `using namespace motostab::testing;`.
#include "analysis/linearize.h"
#include "analysis/sweep.h"
#include "analysis/trim.h"
#include "io/input_error.h"
#include "scenario/scenario.h"
#include "vehicle/vehicle_model.h"

namespace motostab::testing {

using analysis::LinearModel;
using analysis::LinearizeOptions;
using analysis::SweepOptions;
using analysis::SweepResult;
using analysis::TrimOptions;
using analysis::TrimResult;
using analysis::calcTrim;
using analysis::linearize;
using analysis::runSweep;
using io::InputError;
using scenario::Scenario;
using scenario::loadScenario;
using vehicle::VehicleModel;

}  // namespace motostab::testing
