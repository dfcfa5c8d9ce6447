#include "diagnosis/controller_groups.h"

#include <algorithm>

namespace motostab::diagnosis {

std::vector<ControllerGroup> splitByController(const MeasuredData& data) {
  std::vector<ControllerGroup> groups;
  bool any = false;
  for (const auto& e : data.eigenvalues) any = any || !e.controller.empty();
  for (const auto& r : data.responses) any = any || !r.controller.empty();
  if (!any) return groups;
  auto groupOf = [&](const std::vector<std::string>& overrides) -> ControllerGroup& {
    for (auto& g : groups)
      if (g.overrides == overrides) return g;
    groups.emplace_back();
    groups.back().overrides = overrides;
    groups.back().data.name = data.name;
    groups.back().data.file = data.file;
    groups.back().data.eigenvalueFiles = data.eigenvalueFiles;
    return groups.back();
  };
  for (size_t i = 0; i < data.eigenvalues.size(); ++i) {
    ControllerGroup& g = groupOf(data.eigenvalues[i].controller);
    g.rows.push_back(i);
    g.data.eigenvalues.push_back(data.eigenvalues[i]);
    g.data.eigenvalues.back().controller.clear();
  }
  for (size_t i = 0; i < data.responses.size(); ++i) {
    ControllerGroup& g = groupOf(data.responses[i].controller);
    g.runs.push_back(i);
    g.data.responses.push_back(data.responses[i]);
    g.data.responses.back().controller.clear();
  }
  return groups;
}

std::vector<std::string> getControllerPaths(const MeasuredData& data) {
  std::vector<std::string> paths;
  auto add = [&](const std::vector<std::string>& overrides) {
    for (const auto& o : overrides) paths.push_back(o.substr(0, o.find('=')));
  };
  for (const auto& e : data.eigenvalues) add(e.controller);
  for (const auto& r : data.responses) add(r.controller);
  std::sort(paths.begin(), paths.end());
  paths.erase(std::unique(paths.begin(), paths.end()), paths.end());
  return paths;
}

}  // namespace motostab::diagnosis
