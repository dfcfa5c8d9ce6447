#pragma once
// The declared fields (io/field.h) of the sections the scenario loader reads itself: the top level,
// speeds_mps, geometry, the
// bodies (rear_frame, front_frame, total), the wheels and the swingarm's pivot and body. The loader
// reads through them; the plugins declare their own sections (PluginRegistrar::addSectionFields).
#include <vector>

#include "io/field.h"

namespace motostab::scenario {

/// The top-level keys the loader reads (path ""): name, gravity, the sections; every other top-level
/// mapping is a model-extension section.
const io::SectionFields& getTopLevelFields();

/// `speeds_mps`: start, stop, step of the default sweep, m/s.
const io::SectionFields& getSpeedRangeFields();

/// `geometry`: wheelbase_m, trail_m or normal_trail_m, steer_axis_tilt_deg.
const io::SectionFields& getGeometryFields();

/// A body's mass_kg, com_m and inertia_kgm2 (about its CoM), measured, for a section at `path`
/// whose body is `what` ("rear frame with rigid rider", "swingarm body in S").
io::SectionFields makeBodyFields(const std::string& path, const std::string& what);

/// A wheel's radius_m, crown_radius_m, mass_kg, spin_inertia_kgm2, diametral_inertia_kgm2 (`path`:
/// rear_wheel or front_wheel).
io::SectionFields makeWheelFields(const std::string& path);

/// The `swingarm` keys the loader reads (pivot_m, the body, compliance; suspension is an extension's).
const io::SectionFields& getSwingarmFields();

/// Every section above, in the order of the scenario format: the top level, speeds_mps, geometry, total, rear_frame,
/// front_frame, rear_wheel, front_wheel, swingarm.
const std::vector<io::SectionFields>& getScenarioFields();

}  // namespace motostab::scenario
