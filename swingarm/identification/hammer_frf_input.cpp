// Reading a hammer test: its YAML description (readFrfTest) and its hit CSV files (readHits).
#include <cmath>
#include <set>

#include "io/csv.h"
#include "io/number.h"
#include "io/input_error.h"
#include "swingarm/identification/hammer_frf.h"
#include "swingarm/identification/yaml_input.h"

namespace motostab::swingarm::identification {

namespace {

// The optional `processing` mapping of a hammer test.
void readFrfProcessing(YamlMap p, FrfTest& t) {
  if (p.has("band_hz")) {
    const auto b = p.getDoubleList("band_hz", 2);
    if (!(b[0] >= 0 && b[1] > b[0])) p.fail("band_hz", "need 0 <= low < high");
    t.bandMinHz = b[0], t.bandMaxHz = b[1];
  }
  if (p.has("model_order")) {
    const auto o = p.getDoubleList("model_order", 2);
    if (!(o[0] >= 2 && o[1] >= o[0] && o[1] <= 200 && o[0] == std::floor(o[0]) && o[1] == std::floor(o[1])))
      p.fail("model_order", "need integers 2 <= min <= max <= 200");
    t.minOrder = static_cast<int>(o[0]), t.maxOrder = static_cast<int>(o[1]);
  }
  t.exponentialEndValue = p.getPositive("exponential_end_value", t.exponentialEndValue);
  if (t.exponentialEndValue > 1) p.fail("exponential_end_value", "must be in (0, 1]");
  t.forceWindow = p.getBool("force_window", t.forceWindow);
  t.doubleHitFraction = p.getPositive("double_hit_fraction", t.doubleHitFraction);
  t.forceRange = p.getPositive("force_range_N", 0.0);
  t.responseRange = p.getPositive("response_range_mps2", 0.0);
  t.bendingModeHz = p.getPositive("bending_mode_hz", 0.0);
  t.torsionModeHz = p.getPositive("torsion_mode_hz", 0.0);
  const std::string from = p.getString("modal_axes_from", "ods");
  if (from != "ods" && from != "modal_model") p.fail("modal_axes_from", "expected 'ods' or 'modal_model'");
  t.axesFromModalModel = from == "modal_model";
  p.finish();
}

}  // namespace

FrfTest readFrfTest(const std::filesystem::path& file) {
  YamlMap root = openTestFile(file, "frf");
  FrfTest t;
  t.file = file;
  t.frame = root.getString("frame", "");
  t.forcePoint = readForcePoint(root);
  std::vector<YamlMap> channels = root.getMapList("channels");
  if (channels.empty()) root.fail("channels", "expected a non-empty list of channels");
  std::set<std::string> names;
  std::vector<PlatePoint> pts;
  for (YamlMap& m : channels) {
    FrfChannel c;
    c.name = m.getString("name");
    c.column = m.getString("column", c.name + "_mps2");
    c.position = {m.getDouble("x"), m.getDouble("z")};
    if (!names.insert(c.name).second) m.fail("name", "duplicate channel name '" + c.name + "'");
    m.finish();
    pts.push_back(c.position);
    t.channels.push_back(c);
  }
  if (pts.size() >= 3) {
    const std::string why = checkPlaneGeometry(pts);
    if (!why.empty()) root.fail("channels", why);
  }
  for (const auto& hit : root.getFilePathList("hits")) t.hits.push_back(hit);
  if (t.hits.empty()) root.fail("hits", "expected a non-empty list of CSV files");
  t.timeColumn = root.getString("time_column", t.timeColumn);
  t.forceColumn = root.getString("force_column", t.forceColumn);
  if (root.has("processing")) readFrfProcessing(root.getMap("processing"), t);
  root.finish();
  return t;
}

std::vector<modal::ImpactRecord> readHits(const FrfTest& test) {
  std::vector<modal::ImpactRecord> out;
  for (const auto& file : test.hits) {
    const CsvTable csv = readCsv(file);
    const std::string src = file.string();
    const auto t = csv.getColumn(test.timeColumn);
    modal::ImpactRecord r;
    r.force = csv.getColumn(test.forceColumn);
    for (const auto& c : test.channels) r.responses.push_back(csv.getColumn(c.column));
    if (t.size() < 16) throw InputError({src, 0, 0, test.timeColumn}, "too few samples (" + std::to_string(t.size()) + ")");
    // Signals beyond any physical magnitude (io/number.h) would make the spectra overflow.
    std::vector<std::pair<const std::vector<double>*, std::string>> signals{{&r.force, test.forceColumn}};
    for (size_t k = 0; k < test.channels.size(); ++k) signals.push_back({&r.responses[k], test.channels[k].column});
    for (const auto& [values, column] : signals)
      for (size_t i = 0; i < values->size(); ++i)
        if (std::abs((*values)[i]) > io::kMaxMagnitude)
          throw InputError({src, csv.lineNumbers[i], csv.getColumnIndex(column) + 1, column},
                           "a magnitude above 1e12, beyond any physical measurement");
    const int tc = csv.getColumnIndex(test.timeColumn) + 1;
    for (size_t i = 1; i < t.size(); ++i)
      if (!(t[i] > t[i - 1]))
        throw InputError({src, csv.lineNumbers[i], tc, test.timeColumn}, "time is not strictly increasing");
    r.dt = (t.back() - t.front()) / (t.size() - 1);
    for (size_t i = 1; i < t.size(); ++i)
      if (std::abs(t[i] - t[i - 1] - r.dt) > 0.05 * r.dt)
        throw InputError({src, csv.lineNumbers[i], tc, test.timeColumn},
                         "non-uniform sampling (step differs from the mean by more than 5 %)");
    if (!out.empty() && (r.force.size() != out[0].force.size() || std::abs(r.dt - out[0].dt) > 1e-3 * r.dt))
      throw InputError({src, 0, 0, test.timeColumn}, "hit differs from the first hit in length or sampling interval");
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace motostab::swingarm::identification
