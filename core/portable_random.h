#pragma once
// Seeded random numbers that are the same with every standard library. std::mt19937_64's output is
// fixed by the C++ standard (26.6.3.2), but the algorithms of std::uniform_real_distribution and
// std::normal_distribution are not (libstdc++ and libc++ give different draws for one seed). Here the
// transforms are explicit: uniform = top 53 bits x 2^-53; normal = Box-Muller (Box & Muller 1958,
// Ann. Math. Stat. 29:610), both variates of a pair used. Draws agree across platforms up to the
// last-bit rounding of std::log/std::cos/std::sin.
#include <cmath>
#include <cstdint>
#include <random>

namespace motostab::core {

class PortableRandom {
 public:
  explicit PortableRandom(std::uint64_t seed) : engine_(seed) {}

  /// The engine's next raw 64-bit output (std::mt19937_64, fixed by the standard): seeds, bit patterns.
  std::uint64_t drawBits() { return engine_(); }
  /// Uniform integer in [0, n) for n > 0 (modulo reduction; its bias, below n / 2^64, is negligible here).
  std::uint64_t drawIndex(std::uint64_t n) { return engine_() % n; }
  /// Uniform on [0, 1), resolution 2^-53.
  double drawUniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  /// Uniform on [a, b) (units of a and b).
  double drawUniform(double a, double b) { return a + (b - a) * drawUniform(); }
  /// Standard normal (mean 0, standard deviation 1).
  double drawNormal() {
    if (hasSpare_) {
      hasSpare_ = false;
      return spare_;
    }
    const double r = std::sqrt(-2.0 * std::log(1.0 - drawUniform()));  // 1 - u in (0, 1]
    const double phi = 2.0 * M_PI * drawUniform();
    spare_ = r * std::sin(phi);
    hasSpare_ = true;
    return r * std::cos(phi);
  }
  /// Normal with mean `mean` and standard deviation `sigma`.
  double drawNormal(double mean, double sigma) { return mean + sigma * drawNormal(); }

 private:
  std::mt19937_64 engine_;
  double spare_ = 0;
  bool hasSpare_ = false;
};

}  // namespace motostab::core
