// Fuzz target: the Magic Formula tyre property file reader (tyres/tir_file.h) and the force law built
// from it, evaluated at a few operating points and at its small-slip stiffnesses, as `motostab tyre` does.
#include <cmath>

#include "tests/fuzz/fuzz_support.h"
#include "tyres/coefficient_source.h"
#include "tyres/magic_formula.h"
#include "tyres/tir_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  namespace ty = motostab::tyres;
  const std::string text(reinterpret_cast<const char*>(data), size);
  motostab::fuzz::expectInputErrorOnly([&] {
    const ty::TirFile file = ty::TirFile::parse(text, "fuzz.tir");
    const auto source = ty::makeTirSource(file, nullptr);
    const auto law = ty::makeTyreForceLaw(file.getFitType() == 62 ? ty::MagicFormulaVariant::MF62 : ty::MagicFormulaVariant::MF61,
                                          *source);
    const double fz = law->getNominalLoad();
    for (const double alpha : {-0.2, 0.0, 0.05})
      for (const double gamma : {0.0, 0.3}) law->calcForces({fz, 0.01, alpha, gamma, 20.0});
    law->calcCorneringStiffness(fz);
    law->calcCamberStiffness(fz);
    law->calcRelaxationLength(fz, 0.0, 20.0);
  });
  return 0;
}
