#pragma once
// Robustness of the named causes: the same stepwise search on other preparations of the same data.
// Each data source is left out in turn (each eigenvalue file, each response run), and the eigenvalue
// rows measured over a speed range are taken at their mid speed (the range dropped). A variant that
// would leave no data, or that equals the original (no row has a range), is skipped. Each rerun takes
// as many steps as the search named causes on all the data (one when it named none). The causes are
// robust when every variant names the same ones in the same order; otherwise the diagnosis reports
// them as fragile and lists what each variant names.
#include <string>
#include <vector>

#include "diagnosis/measured_data.h"

namespace motostab::diagnosis {

/// One preparation of the data: a description ("eigenvalues: <file>", "response run 1: <file>",
/// "speed ranges -> mid speeds") and the data without that source.
struct DataVariant {
  std::string leftOut;
  MeasuredData data;
};

/// The variants of `data` the robustness reruns diagnose.
std::vector<DataVariant> makeRobustnessVariants(const MeasuredData& data);

}  // namespace motostab::diagnosis
