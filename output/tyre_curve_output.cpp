#include "output/tyre_curve_output.h"

#include "output/writer_tools.h"

namespace motostab::output {

const std::vector<std::string>& getTyreCurveColumns() {
  static const std::vector<std::string> columns{"fz_N",  "slip_angle_rad", "camber_rad", "slip_ratio", "fx_N",
                                                "fy_N",  "mz_Nm",          "mx_Nm",      "my_Nm"};
  return columns;
}

void writeTyreCurve(const std::filesystem::path& dir, const std::string& title, const std::vector<TyreCurvePoint>& points) {
  CsvWriter csv(getTyreCurveColumns());
  for (const auto& p : points) {
    csv.beginRow().add(p.slip.Fz).add(p.slip.alpha).add(p.slip.gamma).add(p.slip.kappa);
    csv.add(p.forces.Fx).add(p.forces.Fy).add(p.forces.Mz).add(p.forces.Mx).add(p.forces.My);
  }
  writeFileAtomically(dir / "forces.csv", csv.getText());
  const std::string common = "  set datafile separator ','\n  set grid\n  set key off\n  set xlabel 'slip angle (deg, ISO)'\n";
  renderGnuplot(dir, "fy_vs_slip",
                common + "  set title " + gnuplotText("Side force: " + title) +
                    "\n  set ylabel 'Fy (N)'\n  plot 'forces.csv' skip 1 using ($2*180/pi):6 with lines lw 2\n");
  renderGnuplot(dir, "mz_vs_slip",
                common + "  set title " + gnuplotText("Aligning moment: " + title) +
                    "\n  set ylabel 'Mz (N m)'\n  plot 'forces.csv' skip 1 using ($2*180/pi):7 with lines lw 2\n");
}

}  // namespace motostab::output
