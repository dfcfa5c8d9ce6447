// motostab tyre FILE.tir --fz N --slip-deg A:B:STEP --camber-deg G [--slip-ratio K] --out DIR: the
// steady-state forces of a Magic Formula .tir file over a slip-angle range, to check a supplier's
// file before a sweep (DIR/forces.csv, DIR/fy_vs_slip and DIR/mz_vs_slip plots).
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <utility>

#include "apps/commands.h"
#include "apps/common_options.h"
#include "io/csv.h"
#include "io/input_error.h"
#include "io/output_folder.h"
#include "io/result_error.h"
#include "output/tyre_curve_output.h"
#include "tyres/magic_formula.h"

namespace motostab::cli {

using io::InputError;
using io::OutputFolder;
using io::formatNumber;
using output::TyreCurvePoint;
using output::writeTyreCurve;
using tyres::MagicFormulaVariant;
using tyres::TirFile;
using tyres::makeTirSource;
using tyres::makeTyreForceLaw;
using tyres::warnUnused;

namespace {

struct TyreArgs {
  std::string file, slipRange, out;
  double fz = 0, camberDeg = 0, slipRatio = 0, speed = NAN;
};

// "A:B:STEP" in degrees: finite, A <= B, STEP > 0, at most kMaxSlipPoints points.
std::vector<double> parseSlipRange(const std::string& text) {
  const std::string expected = "A:B:STEP in degrees, finite, with A <= B, STEP > 0 and at most 1e5 points";
  const std::vector<double> v = parseRangeFields(text, "--slip-deg", false, expected);
  if (!(v[1] >= v[0] && v[2] > 0 && (v[1] - v[0]) / v[2] <= kMaxSlipPoints - 1))
    throw InputError({"--slip-deg", 0, 0, text}, expected);
  std::vector<double> out;
  const int n = static_cast<int>(std::floor((v[1] - v[0]) / v[2] + 1e-9));
  for (int i = 0; i <= n; ++i) out.push_back(v[0] + i * v[2]);
  return out;
}

void runTyre(const TyreArgs& a) {
  const std::vector<double> slips = parseSlipRange(a.slipRange);
  const TirFile file = TirFile::load(a.file);
  const auto source = makeTirSource(file, nullptr);
  const auto law = makeTyreForceLaw(file.getFitType() == 62 ? MagicFormulaVariant::MF62 : MagicFormulaVariant::MF61, *source);
  warnUnused(*source, a.file, std::cerr);
  const double speed = std::isnan(a.speed) ? file.getNumber("LONGVL") : a.speed;
  const double camber = a.camberDeg * M_PI / 180;
  std::vector<TyreCurvePoint> points;
  for (double deg : slips) {
    TyreCurvePoint p;
    p.slip = {a.fz, a.slipRatio, deg * M_PI / 180, camber, speed};
    p.forces = law->calcForces(p.slip);
    const auto& f = p.forces;
    for (const auto& [name, v] : {std::pair{"Fx", f.Fx}, {"Fy", f.Fy}, {"Mx", f.Mx}, {"My", f.My}, {"Mz", f.Mz}})
      if (!std::isfinite(v))  // outputs are checked before they are written
        throw io::ResultError("the tyre law gives " + std::string(name) + " = " + formatNumber(v, 6) + " at slip angle " +
                              formatNumber(deg, 6) + " deg: the file's coefficients give no finite force there");
    points.push_back(p);
  }
  const std::filesystem::path target = getOutputFolder(a.out, std::filesystem::path(a.file).stem().string(), "tyre");
  OutputFolder folder(target);
  std::ostringstream title;
  title << std::filesystem::path(a.file).filename().string() << ", Fz " << a.fz << " N, camber " << a.camberDeg
        << " deg, slip ratio " << a.slipRatio;
  writeTyreCurve(folder.getPath(), title.str(), points);
  folder.commit();
  std::cout << "Magic Formula " << file.getFitType() << " tyre " << a.file << " at Fz = " << a.fz << " N (ISO signs):\n"
            << "  cornering stiffness dFy/dalpha = " << formatNumber(law->calcCorneringStiffness(a.fz), 6) << " N/rad\n"
            << "  camber stiffness    dFy/dgamma = " << formatNumber(law->calcCamberStiffness(a.fz), 6) << " N/rad\n"
            << "  slip stiffness      dFx/dkappa = " << formatNumber(law->calcLongitudinalStiffness(a.fz), 6) << " N\n"
            << "  relaxation length   sigma      = " << formatNumber(law->calcRelaxationLength(a.fz, camber, speed), 6) << " m\n"
            << "  longitudinal relaxation length = " << formatNumber(law->calcLongitudinalRelaxationLength(a.fz), 6)
            << " m (reported only)\n"
            << "Wrote " << (target / "forces.csv").string() << " (" << points.size() << " rows) and "
            << (target / "{fy,mz}_vs_slip.{png,svg,gp}").string() << "\n";
}

}  // namespace

void registerTyreCommands(CLI::App& app) {
  auto a = std::make_shared<TyreArgs>();
  CLI::App* cmd = app.add_subcommand("tyre", "Steady-state forces of a Magic Formula .tir file (MF 6.1/6.2) over slip angle");
  cmd->add_option("file", a->file, "Tyre property file (.tir, FITTYP 61 or 62)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--fz", a->fz, "Normal load, N")->required()->check(makeNumberCheck(0, 1e7, true));
  cmd->add_option("--slip-deg", a->slipRange, "Slip angles A:B:STEP, degrees (ISO sign)")->required();
  cmd->add_option("--camber-deg", a->camberDeg, "Camber (inclination) angle, degrees (ISO sign: top leaning right > 0)")
      ->required()
      ->check(makeNumberCheck(-89, 89));
  cmd->add_option("--slip-ratio", a->slipRatio, "Longitudinal slip ratio")->capture_default_str()->check(makeNumberCheck(-1, 1));
  cmd->add_option("--speed", a->speed, "Forward speed for the rolling resistance, m/s (default: the file's LONGVL)")
      ->check(makeNumberCheck(0, 1e3));
  addOutOption(*cmd, a->out, "FILE's stem");
  cmd->callback([a] { runTyre(*a); });
}

}  // namespace motostab::cli
