#pragma once
// DIR/linear_models.mat: the state-space models x' = A x + B u of a sweep or a linearisation in one
// MATLAB 5 file (matio), loadable by MATLAB, Octave (load) and SciPy (scipy.io.loadmat).
#include <filesystem>
#include <vector>

#include "analysis/linearize.h"

namespace motostab::output {

/// Writes `file` with the variables
///   A            n x n x K double, A(:, :, k) the state matrix at point k (1/s, ...)
///   B            n x m x K double, the input matrix (inputs: input_names, N m)
///   speeds_mps   K x 1 double, forward speed of each point (m/s)
///   roll_rad     K x 1 double, roll angle of each point's trim (rad; 0 for straight running)
///   state_names  n x 1 cell of char rows (LinearModel::states, the rows and columns of A)
///   input_names  m x 1 cell of char rows (LinearModel::inputNames, the columns of B)
/// for the K models in order. Every model needs the states and inputs of the first and a B
/// (std::logic_error otherwise, a caller's bug, e.g. a sweep run without SweepOptions::linearize.computeB).
/// Written completely or not at all (io/atomic_file.h); std::runtime_error if matio fails.
void writeLinearModelsMat(const std::filesystem::path& file, const std::vector<analysis::LinearModel>& models);

}  // namespace motostab::output
