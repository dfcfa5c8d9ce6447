#pragma once
// Robustness of the named causes: the same stepwise search on other preparations of the same data.
// Each data source is left out in turn (each eigenvalue file, each response run), and the eigenvalue
// rows measured over a speed range are taken at their mid speed (the range dropped). A variant that
// would leave no data, or that equals the original (no row has a range), is skipped. A cause is robust
// when every variant names the same first cause; otherwise the diagnosis reports it as fragile and
// lists what each variant names.
#include <string>
#include <vector>

#include "diagnosis/measured_data.h"

namespace motostab {

/// One preparation of the data: a description ("eigenvalues: <file>", "response run 1: <file>",
/// "speed ranges -> mid speeds") and the data without that source.
struct DataVariant {
  std::string leftOut;
  MeasuredData data;
};

/// The variants of `data` the robustness reruns diagnose.
std::vector<DataVariant> makeRobustnessVariants(const MeasuredData& data);

}  // namespace motostab
