// Coefficient sources: the base lookup with scaling overrides, a .tir file source and an inline YAML source.
#include "tyres/coefficient_source.h"

#include <set>
#include <string>
#include <vector>

namespace motostab::tyres {

using io::YamlMap;

std::optional<double> CoefficientSource::find(const std::string& name) const {
  if (scaling_) {
    const auto it = scaling_->find(name);
    if (it != scaling_->end()) return it->second;
  }
  return findOwn(name);
}

double CoefficientSource::get(const std::string& name) const {
  const auto v = find(name);
  if (!v) fail(name, "missing coefficient (needed by the chosen Magic Formula equations)");
  return *v;
}

double CoefficientSource::getScaling(const std::string& name) const { return get(name, 1.0); }

double CoefficientSource::get(const std::string& name, double fallback) const {
  const auto v = find(name);
  return v ? *v : fallback;
}

namespace {

class TirSource : public CoefficientSource {
 public:
  TirSource(const TirFile& f, const std::map<std::string, double>* scaling) : CoefficientSource(scaling), f_(f) {}
  [[noreturn]] void fail(const std::string& name, const std::string& message) const override { f_.fail(name, message); }
  std::optional<std::string> findText(const std::string& name) const override {
    used_.insert(name);
    const TirEntry* e = f_.find(name);
    return e ? std::optional<std::string>(e->text) : std::nullopt;
  }
  // Sections of coefficients: not [MODEL], [DIMENSION], [OPERATING_CONDITIONS], [INERTIA] or the
  // ..._RANGE sections (descriptions and validity ranges, not model coefficients).
  std::vector<std::string> listUnused() const override {
    std::vector<std::string> out;
    for (const auto& [key, e] : f_.getEntries()) {
      const std::string& sec = e.section;
      const bool descriptive = sec == "MODEL" || sec == "DIMENSION" || sec == "OPERATING_CONDITIONS" || sec == "INERTIA" ||
                               (sec.size() > 6 && sec.compare(sec.size() - 6, 6, "_RANGE") == 0);
      if (descriptive || !e.isNumber || used_.count(key)) continue;
      const bool scaling = sec == "SCALING_COEFFICIENTS";
      if (scaling ? e.number != 1 : e.number != 0) out.push_back(key + " (line " + std::to_string(e.line) + ")");
    }
    return out;
  }

 protected:
  std::optional<double> findOwn(const std::string& name) const override {
    used_.insert(name);
    if (!f_.find(name)) return std::nullopt;
    return f_.getNumber(name);
  }

 private:
  const TirFile& f_;
  mutable std::set<std::string> used_;  ///< keys asked for (upper-case)
};

class YamlSource : public CoefficientSource {
 public:
  YamlSource(YamlMap& m, const std::map<std::string, double>* scaling) : CoefficientSource(scaling), m_(m) {}
  [[noreturn]] void fail(const std::string& name, const std::string& message) const override { m_.fail(name, message); }

 protected:
  std::optional<double> findOwn(const std::string& name) const override {
    if (!m_.has(name)) return std::nullopt;
    return m_.getDouble(name);
  }

 private:
  YamlMap& m_;
};

class MapSource : public CoefficientSource {
 public:
  MapSource(const std::map<std::string, double>& m, const std::map<std::string, double>* scaling, const std::string& origin)
      : CoefficientSource(scaling), m_(m), origin_(origin) {}
  [[noreturn]] void fail(const std::string& name, const std::string& message) const override {
    throw io::InputError({origin_, 0, 0, name}, message);
  }

 protected:
  std::optional<double> findOwn(const std::string& name) const override {
    const auto it = m_.find(name);
    return it == m_.end() ? std::nullopt : std::optional<double>(it->second);
  }

 private:
  std::map<std::string, double> m_;
  std::string origin_;
};

}  // namespace

std::unique_ptr<CoefficientSource> makeTirSource(const TirFile& file, const std::map<std::string, double>* scaling) {
  return std::make_unique<TirSource>(file, scaling);
}

std::unique_ptr<CoefficientSource> makeYamlSource(YamlMap& coefficients, const std::map<std::string, double>* scaling) {
  return std::make_unique<YamlSource>(coefficients, scaling);
}

std::unique_ptr<CoefficientSource> makeMapSource(const std::map<std::string, double>& coefficients,
                                                 const std::map<std::string, double>* scaling, const std::string& origin) {
  return std::make_unique<MapSource>(coefficients, scaling, origin);
}

std::string describeUnused(const CoefficientSource& source, const std::string& name) {
  const auto unused = source.listUnused();
  if (unused.empty()) return "";
  std::string out = name + ": " + std::to_string(unused.size()) +
                    " nonzero coefficient(s) that the implemented equations do not use, ignored:";
  for (const auto& u : unused) out += " " + u;
  return out;
}

}  // namespace motostab::tyres
