#include "control/mu_bound.hpp"

#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <limits>

#include <fmt/format.h>

// AB13MD (SLICOT 5.0, src/AB13MD.f; the argument list is the same in 4.0 and 5.7): Fortran 77, every
// argument by reference, Z column-major COMPLEX*16 (layout of std::complex<double>), INTEGER = int.
// FACT is CHARACTER*1: gfortran passes its length as a hidden trailing argument (size_t since GCC 8).
extern "C" void ab13md_(const char* fact, const int* n, std::complex<double>* z, const int* ldz, const int* m,
                        const int* nblock, const int* itype, double* x, double* bound, double* d, double* g,
                        int* iwork, double* dwork, const int* ldwork, std::complex<double>* zwork,
                        const int* lzwork, int* info, std::size_t fact_len);

namespace chaser::control {
namespace {

constexpr int kItypeReal = 1;     // AB13MD's ITYPE
constexpr int kItypeComplex = 2;

// AB13MD's documented minimum workspaces (its argument list, LDWORK and LZWORK), in 64 bits.
std::int64_t min_ldwork(std::int64_t n, std::int64_t m) {
  return 2 * n * n * m - n * n + 9 * m * m + n * m + 11 * n + 33 * m - 11;
}
std::int64_t min_lzwork(std::int64_t n, std::int64_t m) { return 6 * n * n * m + 12 * n * n + 6 * m + 6 * n - 3; }

std::vector<std::string> validate_inputs(const Eigen::MatrixXcd& z, const std::vector<UncertaintyBlock>& blocks) {
  std::vector<std::string> problems;
  if (z.rows() != z.cols()) problems.push_back(fmt::format("M must be square (got {} x {})", z.rows(), z.cols()));
  if (z.rows() == 0) problems.push_back("M is empty");
  if (!z.allFinite()) problems.push_back("M has a non-finite entry");
  if (blocks.empty()) problems.push_back("the structure has no block");
  std::int64_t sum = 0;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const UncertaintyBlock& b = blocks[i];
    if (b.size < 1) problems.push_back(fmt::format("block {}: size must be >= 1 (got {})", i + 1, b.size));
    if (b.type == BlockType::kReal && b.size != 1)
      problems.push_back(fmt::format("block {}: a real block must be a scalar (got size {})", i + 1, b.size));
    sum += b.size;
  }
  if (!blocks.empty() && sum != z.rows())
    problems.push_back(fmt::format("the block sizes sum to {}, M has order {}", sum, z.rows()));
  const std::int64_t n = z.rows(), m = static_cast<std::int64_t>(blocks.size());
  if (min_lzwork(n, m) > std::numeric_limits<int>::max() || min_ldwork(n, m) > std::numeric_limits<int>::max())
    problems.push_back("M is too large for AB13MD's INTEGER workspace sizes");
  return problems;
}

MuBound refuse(MuStatus status, std::string message, int info = 0) {
  MuBound r;
  r.status = status;
  r.message = std::move(message);
  r.slicot_info = info;
  return r;
}

// mu of a 1 x 1 M over one real scalar: 1 - z delta = 0 needs delta = 1 / z real.
MuBound scalar_real(std::complex<double> z) {
  MuBound r;
  r.status = MuStatus::kOk;
  r.bound = z.imag() == 0.0 ? std::abs(z) : 0.0;
  r.d = Eigen::VectorXd::Ones(1);
  r.g = Eigen::VectorXd::Zero(1);
  return r;
}

}  // namespace

const char* to_string(MuStatus status) {
  switch (status) {
    case MuStatus::kOk: return "ok";
    case MuStatus::kInvalidInput: return "invalid input";
    case MuStatus::kLinearSolveFailed: return "AB13MD: a linear solve or matrix inversion failed";
    case MuStatus::kEigenvalueFailed: return "AB13MD: an eigenvalue or singular value computation failed";
    case MuStatus::kSlicotArgumentError: return "AB13MD refused an argument";
  }
  return "unknown";
}

MuBound mu_upper_bound(const Eigen::MatrixXcd& m, const std::vector<UncertaintyBlock>& blocks) {
  const std::vector<std::string> problems = validate_inputs(m, blocks);
  if (!problems.empty()) {
    std::string text = "mu_upper_bound:";
    for (const std::string& p : problems) text += "\n  " + p;
    return refuse(MuStatus::kInvalidInput, text);
  }
  if (m.rows() == 1 && blocks[0].type == BlockType::kReal) return scalar_real(m(0, 0));

  const int n = static_cast<int>(m.rows()), nb = static_cast<int>(blocks.size());
  std::vector<int> nblock, itype;
  int n_real = 0;
  for (const UncertaintyBlock& b : blocks) {
    nblock.push_back(b.size);
    itype.push_back(b.type == BlockType::kReal ? kItypeReal : kItypeComplex);
    n_real += b.type == BlockType::kReal ? 1 : 0;
  }
  Eigen::MatrixXcd z = m;  // AB13MD only reads Z; a copy keeps the caller's const
  std::vector<double> x(static_cast<std::size_t>(nb + n_real));  // M + MR - 1, one spare
  std::vector<int> iwork(static_cast<std::size_t>(std::max(4 * nb - 2, n)) + 1);
  const int ldwork = static_cast<int>(min_ldwork(n, nb)), lzwork = static_cast<int>(min_lzwork(n, nb));
  std::vector<double> dwork(static_cast<std::size_t>(ldwork));
  std::vector<std::complex<double>> zwork(static_cast<std::size_t>(lzwork));
  MuBound r;
  r.d = Eigen::VectorXd::Zero(n);
  r.g = Eigen::VectorXd::Zero(n);
  int info = 0;
  const char fact = 'N';
  ab13md_(&fact, &n, z.data(), &n, &nb, nblock.data(), itype.data(), x.data(), &r.bound, r.d.data(), r.g.data(),
          iwork.data(), dwork.data(), &ldwork, zwork.data(), &lzwork, &info, 1);
  r.slicot_info = info;
  if (info == 5) return refuse(MuStatus::kLinearSolveFailed, to_string(MuStatus::kLinearSolveFailed), info);
  if (info == 6) return refuse(MuStatus::kEigenvalueFailed, to_string(MuStatus::kEigenvalueFailed), info);
  if (info != 0)
    return refuse(MuStatus::kSlicotArgumentError, fmt::format("AB13MD returned INFO = {}", info), info);
  r.status = MuStatus::kOk;
  return r;
}

}  // namespace chaser::control
