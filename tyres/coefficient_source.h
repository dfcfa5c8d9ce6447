#pragma once
// Where Magic Formula coefficients come from: a .tir file or an inline scenario map, with scaling overrides.
#include <map>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "io/yaml_map.h"
#include "tyres/tir_file.h"

namespace motostab::tyres {

/// Where coefficients come from: a .tir file or an inline `coefficients` map, with scaling factors
/// (L...) overridden by a scenario's `scaling` map. Names are the .tir keys (PKY1, LMUY, ...).
class CoefficientSource {
 public:
  /// `scaling` (may be null): scaling factors that take precedence over the source's own values.
  explicit CoefficientSource(const std::map<std::string, double>* scaling = nullptr) : scaling_(scaling) {}
  virtual ~CoefficientSource() = default;
  /// The value of `name`: from `scaling` if it is there, else the source's own.
  std::optional<double> find(const std::string& name) const;
  [[noreturn]] virtual void fail(const std::string& name, const std::string& message) const = 0;
  /// A coefficient the equations need: missing is an InputError naming it.
  double get(const std::string& name) const;
  /// A scaling factor: 1 unless given.
  double getScaling(const std::string& name) const;
  /// An optional value.
  double get(const std::string& name, double fallback) const;
  /// A text value (e.g. TYRESIDE), or nothing; sources without text values return nothing.
  virtual std::optional<std::string> findText(const std::string&) const { return std::nullopt; }
  /// The source's nonzero coefficients that no equation has read so far ("KEY (line N)"), scaling
  /// factors only when they differ from 1; sources that reject unread keys themselves return none.
  virtual std::vector<std::string> listUnused() const { return {}; }

 protected:
  /// The source's own value of `name`, or nothing.
  virtual std::optional<double> findOwn(const std::string& name) const = 0;

 private:
  const std::map<std::string, double>* scaling_;
};

/// Coefficients of a .tir file, with scaling factors from `scaling` (may be null) taking precedence.
std::unique_ptr<CoefficientSource> makeTirSource(const TirFile& file, const std::map<std::string, double>* scaling);
/// Coefficients of an inline YAML map (each key must be read, unknown keys are errors at finish()).
std::unique_ptr<CoefficientSource> makeYamlSource(io::YamlMap& coefficients, const std::map<std::string, double>* scaling);
/// Coefficients given in code (the typed source: name -> value, names of the .tir keys), with scaling
/// factors from `scaling` (may be null) taking precedence. A missing or refused coefficient is an
/// InputError at {origin, key: the coefficient's name}. The map is copied.
std::unique_ptr<CoefficientSource> makeMapSource(const std::map<std::string, double>& coefficients,
                                                 const std::map<std::string, double>* scaling,
                                                 const std::string& origin = "coefficients");

/// One warning naming the source's unused nonzero coefficients (listUnused), "" if none; `name` names
/// the source (a file path). Readers record it (YamlMap::warn); commands report it.
std::string describeUnused(const CoefficientSource& source, const std::string& name);

}  // namespace motostab::tyres
