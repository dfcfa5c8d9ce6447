#include "output/linear_models_mat.h"

#include <matio.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include "io/input_error.h"
#include "output/writer_tools.h"

namespace motostab::output {

using analysis::LinearModel;

namespace {

struct MatVarDeleter {
  void operator()(matvar_t* v) const { Mat_VarFree(v); }
};
using MatVar = std::unique_ptr<matvar_t, MatVarDeleter>;

// A double array of dimensions `dims` over `data` (column-major), copied by matio.
MatVar makeDoubleArray(const char* name, std::vector<size_t> dims, const std::vector<double>& data) {
  return MatVar(Mat_VarCreate(name, MAT_C_DOUBLE, MAT_T_DOUBLE, static_cast<int>(dims.size()), dims.data(),
                              const_cast<double*>(data.data()), 0));
}

// A column cell array of char rows (MATLAB's cellstr).
MatVar makeCellOfNames(const char* name, const std::vector<std::string>& names) {
  size_t dims[2] = {names.size(), 1};
  MatVar cell(Mat_VarCreate(name, MAT_C_CELL, MAT_T_CELL, 2, dims, nullptr, 0));
  if (!cell) return cell;
  for (size_t i = 0; i < names.size(); ++i) {
    size_t d[2] = {1, names[i].size()};
    matvar_t* text = Mat_VarCreate(nullptr, MAT_C_CHAR, MAT_T_UINT8, 2, d, const_cast<char*>(names[i].data()), 0);
    if (!text) return nullptr;
    Mat_VarSetCell(cell.get(), static_cast<int>(i), text);  // the cell owns it from here
  }
  return cell;
}

// The K matrices M(model) stacked as rows x cols x K, column-major.
template <class Get>
std::vector<double> stack(const std::vector<LinearModel>& models, Eigen::Index rows, Eigen::Index cols, Get get) {
  std::vector<double> out;
  out.reserve(static_cast<size_t>(rows * cols) * models.size());
  for (const LinearModel& lm : models) {
    const Eigen::MatrixXd& M = get(lm);
    for (Eigen::Index c = 0; c < cols; ++c)
      for (Eigen::Index r = 0; r < rows; ++r) out.push_back(M(r, c));
  }
  return out;
}

void checkModels(const std::vector<LinearModel>& models) {
  if (models.empty()) throw std::logic_error("writeLinearModelsMat: no models");
  const LinearModel& first = models.front();
  for (const LinearModel& lm : models) {
    bool same = lm.states.size() == first.states.size() && lm.inputNames == first.inputNames;
    for (size_t i = 0; same && i < lm.states.size(); ++i) same = lm.states[i].name == first.states[i].name;
    if (!same) throw std::logic_error("writeLinearModelsMat: the models differ in their states or inputs");
    if (lm.B.rows() != lm.A.rows() || lm.B.cols() != static_cast<Eigen::Index>(lm.inputNames.size()))
      throw std::logic_error("writeLinearModelsMat: a model without its input matrix B");
  }
}

// Writes the variables into a new MAT 5 file at `scratch`, the temporary of the user's `file` (named in errors).
void writeMatFile(const std::string& scratch, const std::string& file, const std::vector<MatVar>& vars) {
  errno = 0;
  mat_t* mat = Mat_CreateVer(scratch.c_str(), nullptr, MAT_FT_MAT5);
  const std::string reason = errno ? std::string(": ") + std::strerror(errno) : "";
  if (!mat) throw io::OutputError(file, "matio cannot create its temporary " + scratch + reason);
  bool ok = true;
  for (const MatVar& v : vars) ok = ok && v && Mat_VarWrite(mat, v.get(), MAT_COMPRESSION_NONE) == 0;
  Mat_Close(mat);
  if (!ok) throw io::OutputError(file, "matio could not write the variables into its temporary " + scratch + " (a full disk?)");
}

}  // namespace

void writeLinearModelsMat(const std::filesystem::path& file, const std::vector<LinearModel>& models) {
  checkModels(models);
  const Eigen::Index n = models.front().A.rows(), m = static_cast<Eigen::Index>(models.front().inputNames.size());
  const size_t K = models.size();
  std::vector<double> speeds, rolls;
  for (const LinearModel& lm : models) speeds.push_back(lm.speed), rolls.push_back(lm.roll);
  std::vector<std::string> states;
  for (const auto& s : models.front().states) states.push_back(s.name);
  const std::vector<double> A = stack(models, n, n, [](const LinearModel& lm) -> const Eigen::MatrixXd& { return lm.A; });
  const std::vector<double> B = stack(models, n, m, [](const LinearModel& lm) -> const Eigen::MatrixXd& { return lm.B; });
  std::vector<MatVar> vars;
  vars.push_back(makeDoubleArray("A", {static_cast<size_t>(n), static_cast<size_t>(n), K}, A));
  vars.push_back(makeDoubleArray("B", {static_cast<size_t>(n), static_cast<size_t>(m), K}, B));
  vars.push_back(makeDoubleArray("speeds_mps", {K, 1}, speeds));
  vars.push_back(makeDoubleArray("roll_rad", {K, 1}, rolls));
  vars.push_back(makeCellOfNames("state_names", states));
  vars.push_back(makeCellOfNames("input_names", models.front().inputNames));
  // matio writes to a path; the bytes then go through the atomic writer (complete or absent).
  const std::string scratch = io::makeTemporarySibling(file.string() + ".matio");
  try {
    writeMatFile(scratch, file.string(), vars);
    std::ifstream in(scratch, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    std::filesystem::remove(scratch);
    writeFileAtomically(file, bytes.str());
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(scratch, ignored);
    throw;
  }
}

}  // namespace motostab::output
