// motostab identify static|frf|swingarm|cog|inertia|virtual-rig: swingarm identification by the
// twist-axis method (docs/swingarm-identification.md).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "apps/commands.h"
#include "apps/common_options.h"
#include "io/input_error.h"
#include "io/atomic_file.h"
#include "io/output_folder.h"
#include "output/swingarm_output.h"
#include "output/virtual_rig_output.h"
#include "swingarm/identification/decomposition.h"
#include "swingarm/identification/frf_diagnosis.h"
#include "swingarm/identification/hammer_frf.h"
#include "swingarm/identification/mass_properties.h"
#include "swingarm/identification/static_laser.h"
#include "swingarm/identification/swingarm_uncertainty.h"
#include "swingarm/identification/virtual_rig.h"

namespace motostab::cli {

using io::InputError;
using io::OutputFolder;
using io::writeFileAtomically;

namespace {

namespace id = motostab::swingarm::identification;

struct Args {
  std::string first, second, out;
  double noiseFactor = 1;
  unsigned long seed = 1;
  bool verbose = false;
};

void printStatic(const id::StaticResult& r) {
  std::printf("static: k_lat %.6g +/- %.2g N/m, a_tw %.5g +/- %.2g m, k_tw %.6g +/- %.2g Nm/rad, beta %.3f +/- %.3f deg\n",
              r.kLat, r.kLatStderr, r.aTw, r.aTwStderr, r.kTw, r.kTwStderr, r.betaDeg, r.betaStderrDeg);
}

void printFrf(const id::FrfResult& r, bool verbose) {
  std::printf("frf: %d hits averaged, %zu rejected; window %s; band %s; model orders %d-%d (%s)\n", r.frf.averages,
              r.rejectedHits.size(), r.window.description.c_str(), r.band.description.c_str(), r.options.minOrder,
              r.options.maxOrder, r.orderReason.c_str());
  for (const auto& h : r.rejectedHits) std::printf("  rejected %s\n", h.c_str());
  for (const auto& m : r.modes) {
    std::printf("  mode %9.3f +/- %.3f Hz  zeta %.5f +/- %.5f  eta %.5f", m.frequencyHz, m.frequencyStderrHz,
                m.dampingRatio, m.dampingStderr, m.lossFactor);
    if (m.hasAxis) std::printf("  axis a %.4f m beta %.2f deg (mpc %.3f)", m.axis.arm, m.axis.betaDeg, m.mpc);
    std::printf("%s\n", m.label.empty() ? "" : ("  [" + m.label + "]").c_str());
  }
  for (const auto& d : r.diagnostics) std::printf("  note: %s\n", d.c_str());
  if (verbose) std::printf("%s", id::formatStabilisationSummary(r).c_str());
}

// Writes a command's outputs into a temporary folder that replaces `target` as a whole (io/output_folder.h).
template <class Write>
void writeWholeFolder(const std::string& target, const Write& write) {
  OutputFolder folder(target);
  write(folder.getPath());
  folder.commit();
}

void runStatic(const Args& args) {
  const auto t = id::readStaticTest(args.first);
  const auto r = id::identifyStatic(t, id::readStaticReadings(t));
  writeWholeFolder(args.out, [&](const std::filesystem::path& dir) { output::writeStaticOutputs(t, r, dir); });
  printStatic(r);
}

void runFrf(const Args& args) {
  const auto t = id::readFrfTest(args.first);
  const auto r = id::identifyFrf(t, id::readHits(t));
  // Complete even without modes: the FRFs to look at.
  writeWholeFolder(args.out, [&](const std::filesystem::path& dir) { output::writeFrfOutputs(t, r, dir); });
  printFrf(r, args.verbose);
  id::requireModes(r);  // exit 3 with what was tried and what to set
}

void runSwingarm(const Args& args) {
  const auto st = id::readStaticTest(args.first);
  const auto ft = id::readFrfTest(args.second);
  const auto sr = id::identifyStatic(st, id::readStaticReadings(st));
  const auto fr = id::identifyFrf(ft, id::readHits(ft));
  if (std::abs(st.forcePoint.x - ft.forcePoint.x) > 1e-3 || std::abs(st.forcePoint.z - ft.forcePoint.z) > 1e-3)
    throw InputError({ft.file.string(), 0, 0, "force_point"}, "the hammer test's force point differs from the static test's");
  printStatic(sr);
  printFrf(fr, args.verbose);
  id::requireModes(fr);  // exit 3 (previous outputs kept): what was tried, which mode is missing, where to hit
  id::requireBendingAndTorsion(fr);
  const auto swr = id::identifySwingarm(sr, fr);
  OutputFolder folder(args.out);
  output::writeStaticOutputs(st, sr, folder.getPath());
  output::writeFrfOutputs(ft, fr, folder.getPath() / "frf");
  output::writeSwingarmOutputs(swr, st, ft, folder.getPath());
  writeFileAtomically(folder.getPath() / "swingarm_uncertainty.yaml", id::formatSwingarmUncertainty(swr));
  folder.commit();
  const std::filesystem::path out(args.out);
  std::printf("swingarm: k_b %.6g +/- %.2g, k_t %.6g +/- %.2g Nm/rad; c_b %.4g, c_t %.4g, c_tw %.4g Nms/rad -> %s (standard errors: swingarm_uncertainty.yaml)\n",
              swr.bending.stiffness.value, swr.bending.stiffness.stderr_, swr.torsion.stiffness.value,
              swr.torsion.stiffness.stderr_, swr.bending.damping.value, swr.torsion.damping.value,
              swr.twist.damping.value, (out / "swingarm.yaml").c_str());
}

void runCog(const Args& args) {
  const auto t = id::readCogTest(args.first);
  const auto r = id::identifyCog(t);
  writeWholeFolder(args.out, [&](const std::filesystem::path& dir) { output::writeCogOutputs(t, r, dir); });
  std::printf("cog: mass %.4f +/- %.4f kg, CoG (%.5f, %.5f, %.5f) +/- (%.5f, %.5f, %.5f) m\n", r.mass, r.massStderr,
              r.cog[0], r.cog[1], r.cog[2], r.cogStderr[0], r.cogStderr[1], r.cogStderr[2]);
}

void runInertia(const Args& args) {
  const auto t = id::readInertiaTest(args.first);
  const auto r = id::identifyInertia(t);
  writeWholeFolder(args.out, [&](const std::filesystem::path& dir) { output::writeInertiaOutputs(t, r, dir); });
  std::printf("inertia about CoG: Ixx %.5f +/- %.5f, Iyy %.5f +/- %.5f, Izz %.5f +/- %.5f kg m^2\n", r.tensor(0, 0),
              r.tensorStderr(0, 0), r.tensor(1, 1), r.tensorStderr(1, 1), r.tensor(2, 2), r.tensorStderr(2, 2));
}

void runVirtualRig(const Args& args) {
  OutputFolder folder(args.out);
  const std::filesystem::path out = folder.getPath();
  const id::VirtualSwingarm rig;
  const auto noise = id::RigNoise().scaled(args.noiseFactor);
  std::vector<double> loads;  // load and unload, 0-4000-0 N in 250 N steps
  for (int i = 0; i <= 32; ++i) loads.push_back(250.0 * (i <= 16 ? i : 32 - i));
  output::writeStaticTestFiles(out, rig, id::simulateStaticReadings(rig, loads, noise, args.seed), noise.laserResolution);
  output::writeFrfTestFiles(out, rig, id::simulateHammerHits(rig, {}, noise, args.seed + 1));  // default settings
  const id::VirtualPart part;
  output::writeCogTestFiles(out, id::simulateCogReadings(part, {0.05, 0.0, 0.04}, 0.05 * args.noiseFactor, args.seed + 2));
  output::writeInertiaTestFiles(out, id::simulateTrifilarTest(part, 1e-3 * args.noiseFactor, args.seed + 3));
  folder.commit();
  std::printf("virtual rig inputs written to %s (truth: docs/swingarm-identification.md, 'Virtual rig')\n",
              folder.getTarget().c_str());
}

// `args` with the output folder of the convention (apps/common_options.h): NAME the first input's stem.
Args withOutputFolder(Args args, const std::string& command) {
  const std::string stem = args.first.empty() ? "" : std::filesystem::path(args.first).stem().string();
  args.out = getOutputFolder(args.out, stem, "identify-" + command);
  return args;
}

const char* const kOutHelp = "output folder (default: NAME-identify-COMMAND in the working folder, NAME the first input's "
                             "stem; replaced whole only if motostab wrote it)";

}  // namespace

void registerSwingarmIdentifyCommands(CLI::App& identify) {
  auto args = std::make_shared<Args>();
  auto addTest = [&](const char* name, const char* help, const char* what, void (*run)(const Args&)) {
    CLI::App* c = identify.add_subcommand(name, help);
    c->add_option("test", args->first, what)->required()->check(CLI::ExistingFile);
    c->add_option("--out", args->out, kOutHelp);
    c->callback([args, run, name] { run(withOutputFolder(*args, name)); });
    return c;
  };
  addTest("static", "Static twist axis, k_lat, a_tw, k_tw (seed eq. 1-4)", "static test YAML", runStatic);
  addTest("frf", "Hammer test: H1, coherence, LSCF modes, modal twist axes", "hammer test YAML", runFrf)
      ->add_flag("--verbose", args->verbose, "print the stabilisation summary");
  addTest("cog", "Centre of gravity from a tilting load-cell rig", "CoG test YAML", runCog);
  addTest("inertia", "Moments of inertia from trifilar-pendulum periods", "inertia test YAML", runInertia);

  CLI::App* sw = identify.add_subcommand("swingarm", "Whole chain: bending/torsion/twist stiffness and damping (seed eq. 1-25)");
  sw->add_option("static", args->first, "static test YAML")->required()->check(CLI::ExistingFile);
  sw->add_option("frf", args->second, "hammer test YAML")->required()->check(CLI::ExistingFile);
  sw->add_option("--out", args->out, kOutHelp);
  sw->add_flag("--verbose", args->verbose, "print the stabilisation summary");
  sw->callback([args] { runSwingarm(withOutputFolder(*args, "swingarm")); });

  CLI::App* vr = identify.add_subcommand("virtual-rig", "Write synthetic test inputs from the virtual rig (known truth)");
  vr->add_option("--out", args->out, "output folder (default: identify-virtual-rig in the working folder)");
  vr->add_option("--noise-factor", args->noiseFactor, "scale every noise figure (1 = realistic)")->check(makeNumberCheck(0, 1e6, true));
  vr->add_option("--seed", args->seed, "random seed");
  vr->callback([args] { runVirtualRig(withOutputFolder(*args, "virtual-rig")); });
}

}  // namespace motostab::cli
