#pragma once
// An upper bound on the structured singular value mu of a complex matrix, from SLICOT's AB13MD
// (Fan, Tits & Doyle, "Robustness in the presence of mixed parametric uncertainty and unmodeled
// dynamics", IEEE TAC 36(1), 1991), and its use on a designed loop.
//
//   mu_Delta(M) = 1 / min { sigma_max(Delta) : Delta in the structure, det(I - M Delta) = 0 }
//
// (0 if no structured Delta makes I - M Delta singular; Skogestad & Postlethwaite, "Multivariable
// Feedback Control", 2nd ed., sec. 8.8). The structure is block diagonal: complex blocks (full,
// any size) and real scalars. rho(M) <= mu <= sigma_max(M) for an all-complex structure; for one
// full complex block mu = sigma_max(M) (AB13MD returns that exactly, by SVD); for two or three
// complex blocks the D-scaled bound is exact, and for a rank-one M = u v^H with scalar blocks mu is
// sum |u_i v_i|. With real blocks AB13MD adds the G scaling of Fan, Tits & Doyle: the bound is then
// at most the all-complex one.
//
// Known quirk (SLICOT 5.0, also reported upstream to SLICOT-Reference as its #4): for a 1 x 1 M and a
// single real block AB13MD returns 0 even when M is real, where mu = |M|. mu_upper_bound computes
// that case itself (|M| if Im M = 0, else 0: no real delta makes 1 - M delta vanish).
// Design-time code: allocates.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace chaser::control {

enum class BlockType { kReal, kComplex };

struct UncertaintyBlock {
  int size = 1;  // [-] rows (= columns) of the block; a real block is a scalar (size 1)
  BlockType type = BlockType::kComplex;
};

enum class MuStatus {
  kOk,
  kInvalidInput,          // ours: sizes, finiteness, a structure that does not fit M
  kLinearSolveFailed,     // AB13MD INFO 5
  kEigenvalueFailed,      // AB13MD INFO 6 (eigenvalues or singular values)
  kSlicotArgumentError,   // INFO 1-4 or < 0: validation should make it impossible
};
const char* to_string(MuStatus status);

struct MuBound {
  MuStatus status = MuStatus::kInvalidInput;
  std::string message;     // every problem found, when not ok
  int slicot_info = 0;
  double bound = 0.0;      // [-] the upper bound on mu
  Eigen::VectorXd d;       // AB13MD's D and G: M^H D^2 M + j (G M - M^H G) - bound^2 D^2 <= 0
  Eigen::VectorXd g;
  bool ok() const { return status == MuStatus::kOk; }
};

// Never throws: a matrix or structure that cannot be right comes back as kInvalidInput naming
// every problem (M square and finite, at least one block, sizes >= 1, real blocks scalar, sizes
// summing to M's order), checked before SLICOT sees it (AB13MD's XERBLA would stop the process).
MuBound mu_upper_bound(const Eigen::MatrixXcd& m, const std::vector<UncertaintyBlock>& blocks);

}  // namespace chaser::control
