#include "swingarm/identification/swingarm_uncertainty.h"

#include <cmath>
#include <sstream>

#include "io/csv.h"

namespace motostab::swingarm::identification {

using io::formatNumber;


std::string formatSwingarmUncertainty(const SwingarmIdentification& id) {
  std::ostringstream y;
  y << "# Standard errors of `motostab identify swingarm` as scenario uncertainties: append to a scenario\n"
    << "# with a swingarm section (docs/uncertainty.md); `motostab uncertainty` samples them.\nuncertainty:\n";
  auto model = [&](const char* name, const LumpedModel& m) {
    const std::pair<const char*, const Estimate*> keys[] = {
        {"arm_m", &m.arm}, {"beta_deg", &m.betaDeg}, {"stiffness_Nm_per_rad", &m.stiffness}, {"damping_Nms_per_rad", &m.damping}};
    for (const auto& [key, e] : keys)
      if (std::isfinite(e->stderr_) && e->stderr_ > 0)
        y << "  swingarm." << name << "." << key << ": " << formatNumber(e->stderr_, 6) << "\n";
  };
  model("bending", id.bending);
  model("torsion", id.torsion);
  model("twist", id.twist);
  return y.str();
}

}  // namespace motostab::swingarm::identification
