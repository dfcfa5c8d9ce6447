#include "response/matrix_pencil.h"

#include <algorithm>
#include <stdexcept>

namespace motostab::response {

PencilDecomposition calcPencilDecomposition(const Eigen::MatrixXd& samples, int pencilParameter) {
  const int n = static_cast<int>(samples.rows());
  const int k = static_cast<int>(samples.cols());
  const int l = pencilParameter > 0 ? pencilParameter : n / 3;
  if (l < 1 || n - l < 1) throw std::logic_error("matrix pencil: too few samples");
  const int rowsPerSignal = n - l;
  Eigen::MatrixXd hankel(rowsPerSignal * k, l + 1);
  for (int s = 0; s < k; ++s)
    for (int i = 0; i < rowsPerSignal; ++i) hankel.row(s * rowsPerSignal + i) = samples.col(s).segment(i, l + 1);
  Eigen::BDCSVD<Eigen::MatrixXd> svd(hankel, Eigen::ComputeThinV);
  PencilDecomposition out;
  out.rightVectors = svd.matrixV();
  out.singularValues = svd.singularValues();
  if (out.singularValues.size() > 0 && out.singularValues(0) > 0) out.singularValues /= out.singularValues(0);
  return out;
}

std::vector<std::complex<double>> calcPencilPoles(const PencilDecomposition& pencil, int order) {
  const auto& v = pencil.rightVectors;
  const int l = static_cast<int>(v.rows()) - 1;
  if (order < 1 || order > std::min<int>(l, static_cast<int>(v.cols())))
    throw std::logic_error("matrix pencil: order " + std::to_string(order) + " too large for the samples");
  const Eigen::MatrixXd vt = v.leftCols(order);
  const Eigen::MatrixXd shift = vt.topRows(l).colPivHouseholderQr().solve(vt.bottomRows(l));
  Eigen::EigenSolver<Eigen::MatrixXd> eig(shift, false);
  std::vector<std::complex<double>> poles(eig.eigenvalues().data(), eig.eigenvalues().data() + order);
  return poles;
}

}  // namespace motostab::response
