#include "uncertainty/sampling.h"

#include <cmath>

namespace motostab::uncertainty {

using scenario::ParameterUncertainty;


uint64_t mixSplit64(uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

double drawUniform(uint64_t seed, uint64_t a, uint64_t b, uint64_t c, uint64_t d) {
  uint64_t k = mixSplit64(seed);
  for (uint64_t counter : {a, b, c, d}) k = mixSplit64(k ^ counter);
  return (static_cast<double>(k >> 11) + 0.5) * 0x1.0p-53;
}

double drawStandardNormal(uint64_t seed, uint64_t a, uint64_t b, uint64_t c) {
  const double u1 = drawUniform(seed, a, b, c, 0), u2 = drawUniform(seed, a, b, c, 1);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
}

double transformDeviate(const ParameterUncertainty& p, double mu, double z, double u) {
  using D = ParameterUncertainty::Distribution;
  switch (p.distribution) {
    case D::Uniform:
      return mu + std::sqrt(3.0) * p.sigma * (2.0 * u - 1.0);
    case D::Lognormal: {
      if (p.sigma == 0) return mu;
      const double s2 = std::log1p(p.sigma * p.sigma / (mu * mu));
      return std::exp(std::log(mu) - 0.5 * s2 + std::sqrt(s2) * z);
    }
    case D::Normal:
      break;
  }
  return mu + p.sigma * z;
}

namespace {

// A stable 64-bit key of a parameter path (FNV-1a), so that a parameter's draws do not depend on
// which other parameters the section lists or in what order.
uint64_t hashPath(const std::string& path) {
  uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : path) h = (h ^ c) * 0x100000001b3ULL;
  return h;
}

}  // namespace

std::vector<double> drawParameters(uint64_t seed, uint64_t stream, uint64_t attempt,
                                   const std::vector<ParameterUncertainty>& params, const std::vector<double>& nominal) {
  std::vector<double> x(params.size());
  for (size_t j = 0; j < params.size(); ++j) {
    const uint64_t key = hashPath(params[j].path);
    const double z = drawStandardNormal(seed, stream, key, attempt);
    const double u = drawUniform(seed, stream, key, attempt, 2);
    x[j] = transformDeviate(params[j], nominal[j], z, u);
  }
  return x;
}

}  // namespace motostab::uncertainty
