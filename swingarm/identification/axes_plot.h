#pragma once
// Plot of the reference plate, its sensors, the force point and twist axes in the x-z plane
// (as seed Fig. 3 and 5), rendered through io/plot.h.
#include <filesystem>
#include <string>
#include <vector>

#include "swingarm/identification/plate_motion.h"

namespace motostab::swingarm::identification {

/// A named sensor position on the plate.
struct PlotMarker {
  std::string label;
  PlatePoint position;
};

/// A named axis line through `point` with direction `direction` (x, z).
struct PlotAxis {
  std::string label;
  Eigen::Vector2d point, direction;
};

/// Writes DIR/NAME_points.dat, DIR/NAME_axes.dat, DIR/NAME_plate.dat and renders DIR/NAME.png/.svg:
/// the plate (bounding box of the sensors and the force point), the sensors, the force point, the
/// swingarm line from the pivot (origin) to the force point, and each axis.
void writeAxesPlot(const std::filesystem::path& dir, const std::string& name, const std::string& title,
                   const std::vector<PlotMarker>& sensors, const PlatePoint& forcePoint,
                   const std::vector<PlotAxis>& axes);

}  // namespace motostab::swingarm::identification
