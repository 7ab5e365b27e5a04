#include "flight/fdi/residual_generator.hpp"

#include <Eigen/LU>
#include <stdexcept>

#include "flight/fdi/design/residual_design.hpp"

namespace chaser::flight::fdi {

ResidualGeneratorParams make_residual_generator(const ResidualDesign& design) {
  const Eigen::Index n_r = design.Q.rows();
  const bool sizes_ok = design.A_bar.rows() == kFdiStateDim && design.A_bar.cols() == kFdiStateDim &&
                        design.B_bar.rows() == kFdiStateDim && design.B_bar.cols() == kFdiInputDim &&
                        design.inputs.C.rows() == kFdiOutputDim &&
                        design.inputs.C.cols() == kFdiStateDim && design.L.rows() == kFdiStateDim &&
                        design.L.cols() == kFdiOutputDim && design.Q.cols() == kFdiOutputDim &&
                        n_r >= 1 && n_r <= kFdiOutputDim;
  if (!sizes_ok)
    throw std::invalid_argument(
        "make_residual_generator: the runtime observer needs n_x = 6, n_y = 3, n_u = 3, n_r = 1..3");
  ResidualGeneratorParams p;
  p.C = design.inputs.C;
  p.L = design.L;
  p.A_c = design.A_bar - p.L * p.C;
  p.B_bar = design.B_bar;
  p.Q.topRows(n_r) = design.Q;
  p.residual_dim = static_cast<int>(n_r);
  p.x_from_y = p.C.transpose() * (p.C * p.C.transpose()).inverse();
  return p;
}

std::vector<std::string> validate(const ResidualGeneratorParams& params) {
  std::vector<std::string> problems;
  if (params.residual_dim < 1 || params.residual_dim > kFdiOutputDim)
    problems.push_back("residual.residual_dim: must be in 1..3");
  else if (params.residual_dim < kFdiOutputDim &&
           !params.Q.bottomRows(kFdiOutputDim - params.residual_dim).isZero(0.0))
    problems.push_back("residual.Q: rows at and beyond residual_dim must be zero");
  if (!params.A_c.allFinite() || !params.B_bar.allFinite() || !params.L.allFinite() ||
      !params.C.allFinite() || !params.Q.allFinite() || !params.x_from_y.allFinite())
    problems.push_back("residual: matrices must be finite");
  return problems;
}

Vec3 step_residual(const ResidualGeneratorParams& params, ResidualGeneratorState& state,
                   const Vec3& y, const Vec3& u_c) {
  if (!state.started) {
    state.x_hat = params.x_from_y * y;
    state.started = true;
  }
  const Vec3 r = params.Q * (y - params.C * state.x_hat);  // eq. 30, output
  state.x_hat = params.A_c * state.x_hat + params.B_bar * u_c + params.L * y;  // eq. 30, update
  return r;
}

}  // namespace chaser::flight::fdi
