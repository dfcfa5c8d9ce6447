#include "output/virtual_rig_output.h"

#include <sstream>

#include "output/writer_tools.h"

namespace motostab::output {

using swingarm::identification::CogRigReadings;
using swingarm::identification::InertiaTest;
using swingarm::identification::StaticReadings;
using swingarm::identification::VirtualSwingarm;

namespace {

std::string num(double v, int digits = 10) { return formatNumber(v, digits); }

std::string sensorList(const VirtualSwingarm& rig, const char* prefix) {
  std::ostringstream s;
  for (size_t j = 0; j < rig.sensorPoints.size(); ++j)
    s << "  - {name: " << prefix << j + 1 << ", x: " << num(rig.sensorPoints[j].x) << ", z: "
      << num(rig.sensorPoints[j].z) << "}\n";
  return s.str();
}

// "[p1, p2, ...]" with 8 significant digits.
std::string formatPeriods(const std::vector<double>& periods) {
  std::ostringstream s;
  s << "[";
  for (size_t i = 0; i < periods.size(); ++i) s << (i ? ", " : "") << num(periods[i], 8);
  return s.str() + "]";
}

}  // namespace

void writeStaticTestFiles(const std::filesystem::path& dir, const VirtualSwingarm& rig, const StaticReadings& r,
                          double laserResolution) {
  std::ostringstream y;
  y << "test: static\n"
    << "frame: \"x along the swingarm from the pivot towards the hub, z up, y lateral (the force direction); metres\"\n"
    << "force_point: {x: " << num(rig.forcePoint.x) << ", z: " << num(rig.forcePoint.z) << "}\n"
    << "sensors:\n" << sensorList(rig, "L") << "readings: static.csv\n"
    << "sensor_resolution_m: " << num(laserResolution) << "\n";
  writeFileAtomically(dir / "static.yaml", y.str());
  std::ostringstream c;
  c << "# virtual rig (motostab), laser resolution " << num(laserResolution) << " m\nforce_N";
  for (size_t j = 0; j < rig.sensorPoints.size(); ++j) c << ",L" << j + 1 << "_m";
  c << "\n";
  for (size_t i = 0; i < r.force.size(); ++i) {
    c << num(r.force[i]);
    for (int j = 0; j < r.dy.cols(); ++j) c << "," << num(r.dy(i, j));
    c << "\n";
  }
  writeFileAtomically(dir / "static.csv", c.str());
}

void writeFrfTestFiles(const std::filesystem::path& dir, const VirtualSwingarm& rig,
                       const std::vector<modal::ImpactRecord>& hits, const std::string& processing) {
  std::ostringstream y;
  y << "test: frf\nframe: \"same convention as the static test\"\n"
    << "force_point: {x: " << num(rig.forcePoint.x) << ", z: " << num(rig.forcePoint.z) << "}\n"
    << "channels:\n" << sensorList(rig, "A") << "hits: [";
  for (size_t h = 0; h < hits.size(); ++h) y << (h ? ", " : "") << "hit" << h + 1 << ".csv";
  y << "]\n";
  if (!processing.empty()) y << "processing:\n" << processing;
  writeFileAtomically(dir / "frf.yaml", y.str());
  for (size_t h = 0; h < hits.size(); ++h) {
    std::ostringstream c;
    c << "time_s,force_N";
    for (size_t j = 0; j < hits[h].responses.size(); ++j) c << ",A" << j + 1 << "_mps2";
    c << "\n";
    for (size_t k = 0; k < hits[h].force.size(); ++k) {
      c << num(k * hits[h].dt, 9) << "," << num(hits[h].force[k], 7);
      for (const auto& ch : hits[h].responses) c << "," << num(ch[k], 7);
      c << "\n";
    }
    writeFileAtomically(dir / ("hit" + std::to_string(h + 1) + ".csv"), c.str());
  }
}

void writeCogTestFiles(const std::filesystem::path& dir, const CogRigReadings& r) {
  std::ostringstream rd, tr;
  rd << "tilt_deg,N1_N,N2_N,N3_N,N4_N\n";
  tr << "tilt_deg,N1_N,N2_N,N3_N,N4_N\n";
  for (size_t i = 0; i < r.tiltDeg.size(); ++i) {
    rd << r.tiltDeg[i];
    tr << r.tiltDeg[i];
    for (int j = 0; j < 4; ++j) {
      rd << "," << num(r.loads[i][j], 8);
      tr << "," << num(r.tareLoads[i][j], 8);
    }
    rd << "\n";
    tr << "\n";
  }
  writeFileAtomically(dir / "cog.csv", rd.str());
  writeFileAtomically(dir / "cog_tare.csv", tr.str());
  std::ostringstream y;
  y << "test: cog\nframe: \"platform: x normal to the tilt hinge towards the raised side, y along the hinge, z up "
       "from the platform surface; metres\"\nload_cells:\n";
  for (const auto& c : r.cells) y << "  - {name: " << c.name << ", x: " << c.x << ", y: " << c.y << "}\n";
  y << "readings: cog.csv\ntare: cog_tare.csv\nload_cell_resolution_N: 0.05\npart_origin_m: [" << num(r.partOrigin[0])
    << ", " << num(r.partOrigin[1]) << ", " << num(r.partOrigin[2]) << "]\n";
  writeFileAtomically(dir / "cog.yaml", y.str());
}

void writeInertiaTestFiles(const std::filesystem::path& dir, const InertiaTest& t) {
  std::ostringstream y;
  y << "test: inertia\nframe: \"part frame of the CoG test; setup axes in that frame\"\n"
    << "pendulum: {wire_length_m: " << t.wireLength << ", radius_m: " << t.radius << ", plate_mass_kg: " << t.plateMass
    << "}\n"
    << "period_resolution_s: " << t.periodResolution << "\npart_mass_kg: " << num(t.partMass) << "\n"
    << "plate_periods_s: " << formatPeriods(t.platePeriods) << "\nsetups:\n";
  for (const auto& s : t.setups)
    y << "  - {name: " << s.name << ", axis: [" << num(s.axis[0]) << ", " << num(s.axis[1]) << ", " << num(s.axis[2])
      << "], cog_offset_m: " << s.cogOffset << ", periods_s: " << formatPeriods(s.periods) << "}\n";
  writeFileAtomically(dir / "inertia.yaml", y.str());
}

}  // namespace motostab::output
