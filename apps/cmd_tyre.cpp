// motostab tyre FILE.tir --fz N --slip-deg A:B:STEP --camber-deg G [--slip-ratio K] --out DIR: the
// steady-state forces of a Magic Formula .tir file over a slip-angle range, to check a supplier's
// file before a sweep (DIR/forces.csv, DIR/fy_vs_slip and DIR/mz_vs_slip plots).
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>

#include "apps/commands.h"
#include "apps/common_options.h"
#include "apps/option_checks.h"
#include "io/csv.h"
#include "io/input_error.h"
#include "io/number.h"
#include "io/output_folder.h"
#include "output/tyre_curve_output.h"
#include "tyres/magic_formula.h"

namespace motostab::cli {

using io::InputError;
using io::OutputFolder;
using io::formatNumber;
using io::parseFiniteNumber;
using output::TyreCurvePoint;
using output::writeTyreCurve;
using tyres::TirFile;

namespace {

struct TyreArgs {
  std::string file, slipRange, out;
  double fz = 0, camberDeg = 0, slipRatio = 0, speed = NAN;
};

// "A:B:STEP" in degrees: finite, A <= B, STEP > 0, at most 1e5 points.
std::vector<double> parseSlipRange(const std::string& text) {
  std::vector<double> v;
  std::stringstream ss(text);
  std::string part;
  while (std::getline(ss, part, ':')) v.push_back(parseFiniteNumber(part).value_or(NAN));
  const io::InputLocation where{"--slip-deg", 0, 0, text};
  if (v.size() != 3) return makeSlipAngles(NAN, NAN, NAN, where);
  return makeSlipAngles(v[0], v[1], v[2], where);
}

void runTyre(const TyreArgs& a) {
  const std::vector<double> slips = parseSlipRange(a.slipRange);
  const TirForceLaw tir = loadTirForCurve(a.file, std::cerr);
  const TirFile& file = tir.file;
  const auto& law = tir.law;
  const double speed = std::isnan(a.speed) ? file.getNumber("LONGVL") : a.speed;
  const double camber = a.camberDeg * M_PI / 180;
  const std::vector<TyreCurvePoint> points = calcTyreCurve(*law, a.fz, slips, camber, a.slipRatio, speed);
  const std::filesystem::path target = a.out.empty() ? std::filesystem::path(std::filesystem::path(a.file).stem().string() + "-tyre")
                                                     : std::filesystem::path(a.out);
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
  cmd->add_option("--fz", a->fz, "Normal load, N")->required()->check(makeNumberCheck(kTyreLoadN));
  cmd->add_option("--slip-deg", a->slipRange, "Slip angles A:B:STEP, degrees (ISO sign)")->required();
  cmd->add_option("--camber-deg", a->camberDeg, "Camber (inclination) angle, degrees (ISO sign: top leaning right > 0)")
      ->required()
      ->check(makeNumberCheck(kCamberDeg));
  cmd->add_option("--slip-ratio", a->slipRatio, "Longitudinal slip ratio")->capture_default_str()->check(makeNumberCheck(kSlipRatio));
  cmd->add_option("--speed", a->speed, "Forward speed for the rolling resistance, m/s (default: the file's LONGVL)")
      ->check(makeNumberCheck(kSpeedMps));
  cmd->add_option("--out", a->out, "Output folder (default: <file stem>-tyre)");
  cmd->callback([a] { runTyre(*a); });
}

}  // namespace motostab::cli
