#include "diagnosis/robustness.h"

#include <algorithm>
#include <filesystem>

namespace motostab::diagnosis {

std::vector<DataVariant> makeRobustnessVariants(const MeasuredData& data) {
  std::vector<DataVariant> out;
  for (const std::string& file : data.eigenvalueFiles) {
    DataVariant v{"eigenvalues: " + std::filesystem::path(file).filename().string(), data};
    v.data.eigenvalues.clear();
    for (const auto& e : data.eigenvalues)
      if (e.where.file != file) v.data.eigenvalues.push_back(e);
    auto& files = v.data.eigenvalueFiles;
    files.erase(std::remove(files.begin(), files.end(), file), files.end());
    if (!v.data.eigenvalues.empty() || !v.data.responses.empty()) out.push_back(std::move(v));
  }
  for (size_t r = 0; r < data.responses.size(); ++r) {
    DataVariant v{"response run " + std::to_string(r + 1) + ": " + std::filesystem::path(data.responses[r].file).filename().string(), data};
    v.data.responses.erase(v.data.responses.begin() + static_cast<long>(r));
    if (!v.data.eigenvalues.empty() || !v.data.responses.empty()) out.push_back(std::move(v));
  }
  DataVariant mid{"speed ranges -> mid speeds", data};
  bool any = false;
  for (auto& e : mid.data.eigenvalues)
    if (e.hasRange) e.speed = 0.5 * (e.speedMin + e.speedMax), e.speedMin = e.speedMax = e.speed, e.hasRange = false, any = true;
  if (any) out.push_back(std::move(mid));
  return out;
}

}  // namespace motostab::diagnosis
