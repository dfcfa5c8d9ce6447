#pragma once
// Test descriptions (static, frf, cog, inertia) are read with the project's one strict YAML layer
// (io/yaml_map.h): unknown or duplicate keys, missing keys and bad values are InputErrors
// naming the file, line, column and key path; file names are relative to the test file. The io/ names the
// test readers share are declared here once.
#include <filesystem>
#include <string>

#include "io/csv.h"
#include "io/input_error.h"
#include "io/yaml_map.h"
#include "swingarm/identification/plate_motion.h"

namespace motostab::swingarm::identification {

using io::CsvTable;
using io::InputError;
using io::YamlMap;
using io::readCsv;

/// Loads a test description and checks its `test: <kind>` key (consumed).
io::YamlMap openTestFile(const std::filesystem::path& file, const std::string& kind);

/// The required `force_point: {x, z}` of a static or hammer test (m; consumed).
PlatePoint readForcePoint(io::YamlMap& root);

}  // namespace motostab::swingarm::identification
