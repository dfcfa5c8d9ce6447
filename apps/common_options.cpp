#include "apps/common_options.h"

#include <cstdlib>
#include <sstream>
#include <vector>

#include "io/input_error.h"

namespace motostab::cli {

void parseSpeedRange(const std::string& text, double& start, double& stop, double& step) {
  std::vector<double> v;
  std::stringstream ss(text);
  std::string part;
  while (std::getline(ss, part, ':')) {
    char* end = nullptr;
    v.push_back(std::strtod(part.c_str(), &end));
    if (part.empty() || *end != '\0') v.clear(), v.resize(9);
  }
  if (v.size() != 3 || !(v[2] > 0) || v[1] < v[0] || v[0] < 0)
    throw InputError({"--speeds", 0, 0, text}, "expected START:STOP:STEP with 0 <= START <= STOP and STEP > 0");
  start = v[0], stop = v[1], step = v[2];
}

}  // namespace motostab::cli
