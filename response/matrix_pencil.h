#pragma once
// Matrix pencil method (Hua & Sarkar 1990) for the common poles of uniformly sampled signals.
#include <complex>
#include <vector>

#include <Eigen/Dense>

namespace motostab::response {

/// The SVD of the stacked Hankel matrices of K signals: rows [y_k(i) ... y_k(i+L)], i = 0..N-L-1, for
/// every signal k. Computed once and truncated to each order by calcPencilPoles().
struct PencilDecomposition {
  Eigen::MatrixXd rightVectors;   ///< (L+1) x r right singular vectors, by decreasing singular value
  Eigen::VectorXd singularValues; ///< r singular values, divided by the largest
};

/// Builds and decomposes the Hankel matrices of `samples` (N x K, one uniformly sampled signal per
/// column) with pencil parameter L (L+1 columns; N/3 when `pencilParameter` <= 0).
PencilDecomposition calcPencilDecomposition(const Eigen::MatrixXd& samples, int pencilParameter = 0);

/// The `order` discrete poles z_m (per sample step) of the truncated pencil: eigenvalues of
/// pinv(V1) V2 with V1, V2 the first and last L rows of the leading `order` right singular vectors.
std::vector<std::complex<double>> calcPencilPoles(const PencilDecomposition& pencil, int order);

}  // namespace motostab::response
