#include "swingarm/identification/axes_plot.h"

#include <algorithm>
#include <sstream>

#include "io/atomic_file.h"
#include "io/csv.h"
#include "io/plot.h"

namespace motostab::swingarm::identification {

using io::formatNumber;
using io::gnuplotQuote;
using io::renderGnuplot;
using io::writeFileAtomically;


void writeAxesPlot(const std::filesystem::path& dir, const std::string& name, const std::string& title,
                   const std::vector<PlotMarker>& sensors, const PlatePoint& forcePoint,
                   const std::vector<PlotAxis>& axes) {
  double x0 = std::min(0.0, forcePoint.x), x1 = std::max(0.0, forcePoint.x);
  double z0 = forcePoint.z, z1 = forcePoint.z;
  double px0 = forcePoint.x, px1 = forcePoint.x, pz0 = forcePoint.z, pz1 = forcePoint.z;
  std::ostringstream pts;
  pts << "# x_m z_m label\n";
  for (const auto& s : sensors) {
    px0 = std::min(px0, s.position.x), px1 = std::max(px1, s.position.x);
    pz0 = std::min(pz0, s.position.z), pz1 = std::max(pz1, s.position.z);
    pts << formatNumber(s.position.x, 8) << " " << formatNumber(s.position.z, 8) << " \"" << s.label << "\"\n";
  }
  for (const auto& a : axes) x0 = std::min(x0, a.point[0]), x1 = std::max(x1, a.point[0]);
  const double margin = 0.02;
  px0 -= margin, px1 += margin, pz0 -= margin, pz1 += margin;
  x0 = std::min(x0, px0) - 0.05, x1 = std::max(x1, px1) + 0.05;
  z0 = std::min(z0, pz0) - 0.05, z1 = std::max(z1, pz1) + 0.05;
  const double span = std::max(x1 - x0, z1 - z0);
  const double cz = 0.5 * (z0 + z1);
  z0 = cz - 0.3 * span, z1 = cz + 0.3 * span;
  std::ostringstream plate, ax;
  plate << px0 << " " << pz0 << "\n" << px1 << " " << pz0 << "\n" << px1 << " " << pz1 << "\n"
        << px0 << " " << pz1 << "\n" << px0 << " " << pz0 << "\n\n\n0 0\n"
        << forcePoint.x << " " << forcePoint.z << "\n\n\n" << forcePoint.x << " " << forcePoint.z << "\n";
  for (const auto& a : axes) {
    const Eigen::Vector2d p = a.point - 2 * span * a.direction, q = a.point + 2 * span * a.direction;
    ax << "# " << a.label << "\n" << formatNumber(p[0], 8) << " " << formatNumber(p[1], 8) << "\n"
       << formatNumber(a.point[0], 8) << " " << formatNumber(a.point[1], 8) << "\n"
       << formatNumber(q[0], 8) << " " << formatNumber(q[1], 8) << "\n\n\n";
  }
  writeFileAtomically(dir / (name + "_points.dat"), pts.str());
  writeFileAtomically(dir / (name + "_plate.dat"), plate.str());
  writeFileAtomically(dir / (name + "_axes.dat"), ax.str());
  std::ostringstream gp;
  gp << "set title " << gnuplotQuote(title) << "\nset xlabel 'x (m), pivot at 0'\nset ylabel 'z (m)'\n"
     << "set size ratio -1\nset grid\nset key below\n"
     << "set xrange [" << x0 << ":" << x1 << "]\nset yrange [" << z0 << ":" << z1 << "]\n"
     << "plot '" << name << "_plate.dat' index 0 with lines lc rgb '#777777' lw 2 title 'reference plate', \\\n"
     << "  '' index 1 with lines dt 2 lc rgb '#aaaaaa' title 'swingarm (pivot to hub)', \\\n"
     << "  '" << name << "_points.dat' using 1:2 with points pt 7 ps 1 lc rgb 'red' title 'sensors', \\\n"
     << "  '' using 1:2:3 with labels offset 1.5,0.8 notitle, \\\n"
     << "  '" << name << "_plate.dat' index 2 with points pt 7 ps 2.5 lc rgb 'black' title 'force point'";
  const char* colours[] = {"black", "#1f77b4", "#d62728", "#2ca02c", "#9467bd"};
  for (size_t i = 0; i < axes.size(); ++i)
    gp << ", \\\n  '" << name << "_axes.dat' index " << i << " with lines lw " << (i == 0 ? 3 : 2) << " lc rgb '"
       << colours[i % 5] << "' title " << gnuplotQuote(axes[i].label);
  gp << "\n";
  renderGnuplot(dir, name, gp.str());
}

}  // namespace motostab::swingarm::identification
