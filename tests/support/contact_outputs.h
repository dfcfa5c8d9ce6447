#pragma once
// A named contact output of a vehicle model at a state (e.g. "front_tyre_Fz_N"), for tests.
#include <gtest/gtest.h>

#include <string>

#include "vehicle/vehicle_model.h"

namespace motostab::test {

/// The value of contact output `name` at `s`; a test failure (and 0) when the model has no such output.
inline double findContactOutput(const vehicle::VehicleModel& m, const SimTK::State& s, const std::string& name) {
  const auto names = m.getContactOutputNames();
  const auto values = m.calcContactOutputs(s);
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return values[i];
  ADD_FAILURE() << "no output " << name;
  return 0;
}

}  // namespace motostab::test
