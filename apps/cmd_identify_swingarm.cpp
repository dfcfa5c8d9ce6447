// motostab identify static|frf|swingarm|cog|inertia|virtual-rig: swingarm identification by the
// twist-axis method (docs/swingarm-identification.md).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "apps/commands.h"
#include "apps/common_options.h"
#include "io/input_error.h"
#include "io/output_folder.h"
#include "swingarm/identification/decomposition.h"
#include "swingarm/identification/frf_test.h"
#include "swingarm/identification/mass_properties.h"
#include "swingarm/identification/static_test.h"
#include "swingarm/identification/virtual_rig.h"

namespace motostab::cli {
namespace {

namespace id = motostab::identification;

struct Args {
  std::string first, second, out;
  double noiseFactor = 1;
  unsigned long seed = 1;
};

void printStatic(const id::StaticResult& r) {
  std::printf("static: k_lat %.6g +/- %.2g N/m, a_tw %.5g +/- %.2g m, k_tw %.6g +/- %.2g Nm/rad, beta %.3f +/- %.3f deg\n",
              r.kLat, r.kLatStderr, r.aTw, r.aTwStderr, r.kTw, r.kTwStderr, r.betaDeg, r.betaStderrDeg);
}

void printFrf(const id::FrfResult& r) {
  std::printf("frf: %d hits averaged, %zu rejected\n", r.frf.averages, r.rejectedHits.size());
  for (const auto& h : r.rejectedHits) std::printf("  rejected %s\n", h.c_str());
  for (const auto& m : r.modes) {
    std::printf("  mode %9.3f +/- %.3f Hz  zeta %.5f +/- %.5f  eta %.5f", m.frequencyHz, m.frequencyStderrHz,
                m.dampingRatio, m.dampingStderr, m.lossFactor);
    if (m.hasAxis) std::printf("  axis a %.4f m beta %.2f deg (mpc %.3f)", m.axis.arm, m.axis.betaDeg, m.mpc);
    std::printf("%s\n", m.label.empty() ? "" : ("  [" + m.label + "]").c_str());
  }
}

}  // namespace

void registerSwingarmIdentifyCommands(CLI::App& identify) {
  auto args = std::make_shared<Args>();

  CLI::App* st = identify.add_subcommand("static", "Static twist axis, k_lat, a_tw, k_tw (seed eq. 1-4)");
  st->add_option("test", args->first, "static test YAML")->required()->check(CLI::ExistingFile);
  st->add_option("--out", args->out, "output folder")->required();
  st->callback([args] {
    const auto t = id::readStaticTest(args->first);
    const auto r = id::identifyStatic(t, id::readStaticReadings(t));
    OutputFolder out(args->out);
    id::writeStaticOutputs(t, r, out.getPath());
    out.commit();
    printStatic(r);
  });

  CLI::App* fr = identify.add_subcommand("frf", "Hammer test: H1, coherence, LSCF modes, modal twist axes");
  fr->add_option("test", args->first, "hammer test YAML")->required()->check(CLI::ExistingFile);
  fr->add_option("--out", args->out, "output folder")->required();
  fr->callback([args] {
    const auto t = id::readFrfTest(args->first);
    const auto r = id::identifyFrf(t, id::readHits(t));
    OutputFolder out(args->out);
    id::writeFrfOutputs(t, r, out.getPath());
    out.commit();
    printFrf(r);
  });

  CLI::App* sw = identify.add_subcommand("swingarm", "Whole chain: bending/torsion/twist stiffness and damping (seed eq. 1-25)");
  sw->add_option("static", args->first, "static test YAML")->required()->check(CLI::ExistingFile);
  sw->add_option("frf", args->second, "hammer test YAML")->required()->check(CLI::ExistingFile);
  sw->add_option("--out", args->out, "output folder")->required();
  sw->callback([args] {
    const auto st = id::readStaticTest(args->first);
    const auto ft = id::readFrfTest(args->second);
    const auto sr = id::identifyStatic(st, id::readStaticReadings(st));
    const auto fr = id::identifyFrf(ft, id::readHits(ft));
    if (std::abs(st.forcePoint.x - ft.forcePoint.x) > 1e-3 || std::abs(st.forcePoint.z - ft.forcePoint.z) > 1e-3)
      throw InputError({ft.file.string(), 0, 0, "force_point"}, "the hammer test's force point differs from the static test's");
    const auto swr = id::identifySwingarm(sr, fr);
    OutputFolder folder(args->out);
    id::writeStaticOutputs(st, sr, folder.getPath());
    id::writeFrfOutputs(ft, fr, folder.getPath() / "frf");
    id::writeSwingarmOutputs(swr, st, ft, folder.getPath());
    folder.commit();
    const std::filesystem::path out(args->out);
    printStatic(sr);
    printFrf(fr);
    std::printf("swingarm: k_b %.6g +/- %.2g, k_t %.6g +/- %.2g Nm/rad; c_b %.4g, c_t %.4g, c_tw %.4g Nms/rad -> %s\n",
                swr.bending.stiffness.value, swr.bending.stiffness.stderr_, swr.torsion.stiffness.value,
                swr.torsion.stiffness.stderr_, swr.bending.damping.value, swr.torsion.damping.value,
                swr.twist.damping.value, (out / "swingarm.yaml").c_str());
  });

  CLI::App* cg = identify.add_subcommand("cog", "Centre of gravity from a tilting load-cell rig");
  cg->add_option("test", args->first, "CoG test YAML")->required()->check(CLI::ExistingFile);
  cg->add_option("--out", args->out, "output folder")->required();
  cg->callback([args] {
    const auto t = id::readCogTest(args->first);
    const auto r = id::identifyCog(t);
    OutputFolder out(args->out);
    id::writeCogOutputs(t, r, out.getPath());
    out.commit();
    std::printf("cog: mass %.4f +/- %.4f kg, CoG (%.5f, %.5f, %.5f) +/- (%.5f, %.5f, %.5f) m\n", r.mass, r.massStderr,
                r.cog[0], r.cog[1], r.cog[2], r.cogStderr[0], r.cogStderr[1], r.cogStderr[2]);
  });

  CLI::App* in = identify.add_subcommand("inertia", "Moments of inertia from trifilar-pendulum periods");
  in->add_option("test", args->first, "inertia test YAML")->required()->check(CLI::ExistingFile);
  in->add_option("--out", args->out, "output folder")->required();
  in->callback([args] {
    const auto t = id::readInertiaTest(args->first);
    const auto r = id::identifyInertia(t);
    OutputFolder out(args->out);
    id::writeInertiaOutputs(t, r, out.getPath());
    out.commit();
    std::printf("inertia about CoG: Ixx %.5f +/- %.5f, Iyy %.5f +/- %.5f, Izz %.5f +/- %.5f kg m^2\n", r.tensor(0, 0),
                r.tensorStderr(0, 0), r.tensor(1, 1), r.tensorStderr(1, 1), r.tensor(2, 2), r.tensorStderr(2, 2));
  });

  CLI::App* vr = identify.add_subcommand("virtual-rig", "Write synthetic test inputs from the virtual rig (known truth)");
  vr->add_option("--out", args->out, "output folder")->required();
  vr->add_option("--noise-factor", args->noiseFactor, "scale every noise figure (1 = realistic)")->check(makeNumberCheck(0, 1e6, true));
  vr->add_option("--seed", args->seed, "random seed");
  vr->callback([args] {
    OutputFolder folder(args->out);
    const std::filesystem::path out = folder.getPath();
    const id::VirtualSwingarm rig;
    const auto noise = id::RigNoise().scaled(args->noiseFactor);
    std::vector<double> loads;  // load and unload, 0-4000-0 N in 250 N steps
    for (int i = 0; i <= 32; ++i) loads.push_back(250.0 * (i <= 16 ? i : 32 - i));
    id::writeStaticTestFiles(out, rig, id::simulateStaticReadings(rig, loads, noise, args->seed), noise.laserResolution);
    id::writeFrfTestFiles(out, rig, id::simulateHammerHits(rig, {}, noise, args->seed + 1),
                          "  band_hz: [60, 400]\n  model_order: [4, 24]\n");
    const id::VirtualPart part;
    id::writeCogTestFiles(out, part, {0.05, 0.0, 0.04}, 0.05 * args->noiseFactor, args->seed + 2);
    id::writeInertiaTestFiles(out, part, 1e-3 * args->noiseFactor, args->seed + 3);
    folder.commit();
    std::printf("virtual rig inputs written to %s (truth: docs/swingarm-identification.md, 'Virtual rig')\n",
                folder.getTarget().c_str());
  });
}

}  // namespace motostab::cli
