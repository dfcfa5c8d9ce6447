#pragma once
// Counter-based random draws for uncertainty studies: every number is a pure function of
// (seed, sample, parameter, attempt), so sample i is the same on any rank, thread or machine.
//
// Generator: SplitMix64 (Steele, Lea, Flood 2014, "Fast splittable pseudorandom number generators")
// applied to a key hashed from the counters; uniforms are the top 53 bits / 2^53 in (0, 1).
// Normal deviates: Box-Muller (Box and Muller 1958) z = sqrt(-2 ln u1) cos(2 pi u2).
// Distributions are parameterised by their nominal value mu (the scenario's) and standard deviation
// sigma, so that Var = sigma^2 for all three (the first-order estimate J Sigma J^T uses that):
//   normal     x = mu + sigma z
//   uniform    x = mu + sqrt(3) sigma (2u - 1)                  (half-width sqrt(3) sigma)
//   lognormal  x = exp(m + s z), s^2 = ln(1 + sigma^2/mu^2), m = ln mu - s^2/2   (mean mu, needs mu > 0)
#include <cstdint>
#include <vector>

#include "scenario/scenario.h"

namespace motostab::uncertainty {

/// SplitMix64 finaliser of x (a bijection of 64-bit words).
uint64_t mixSplit64(uint64_t x);

/// A uniform deviate in (0, 1) from the counters (seed, a, b, c, d).
double drawUniform(uint64_t seed, uint64_t a, uint64_t b, uint64_t c, uint64_t d);

/// A standard normal deviate from the counters (Box-Muller on two uniforms of the same key).
double drawStandardNormal(uint64_t seed, uint64_t a, uint64_t b, uint64_t c);

/// The value of one uncertain parameter with nominal `mu`, given a standard normal z and a uniform u
/// in (0, 1) drawn for it (the distribution uses the one it needs; see the header comment).
double transformDeviate(const scenario::ParameterUncertainty& p, double mu, double z, double u);

/// Parameter values of draw `stream` (a sample index, or a row of a Sobol design) at attempt
/// `attempt` (0 first; redraws of unphysical samples count up), for the parameters `params` with
/// nominal values `nominal`. Each parameter's deviates are keyed by a hash of its path, not its
/// position: adding, removing or reordering other parameters leaves its values unchanged.
std::vector<double> drawParameters(uint64_t seed, uint64_t stream, uint64_t attempt,
                                   const std::vector<scenario::ParameterUncertainty>& params, const std::vector<double>& nominal);

}  // namespace motostab::uncertainty
