#include "flight/fdi/design/weighting.hpp"

#include <Eigen/QR>
#include <cmath>
#include <future>
#include <vector>

#include "core/constants.hpp"

namespace chaser::flight::fdi {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

namespace {

// Orthonormal basis of the complement of unit w in R^c: columns 1..c-1 of a Householder QR of w.
MatrixXd complement(const VectorXd& w) {
  const Index c = w.size();
  const MatrixXd full = w.householderQr().householderQ() * MatrixXd::Identity(c, c);
  return full.rightCols(c - 1);
}

std::vector<VectorXd> initial_grid(Index c, int points) {
  std::vector<VectorXd> grid;
  if (c == 1) {
    grid.push_back(VectorXd::Ones(1));
  } else if (c == 2) {
    for (int j = 0; j < points; ++j) {
      const double angle = kPi * j / points;
      grid.push_back((VectorXd(2) << std::cos(angle), std::sin(angle)).finished());
    }
  } else if (c == 3) {  // Fibonacci lattice on the upper hemisphere
    const double golden_angle = kPi * (3.0 - std::sqrt(5.0));
    for (int j = 0; j < points; ++j) {
      const double z = 1.0 - (j + 0.5) / points;
      const double r = std::sqrt(1.0 - z * z);
      grid.push_back((VectorXd(3) << r * std::cos(j * golden_angle), r * std::sin(j * golden_angle), z)
                         .finished());
    }
  } else {
    for (Index a = 0; a < c; ++a) {
      grid.push_back(VectorXd::Unit(c, a));
      for (Index b = a + 1; b < c; ++b) {
        grid.push_back((VectorXd::Unit(c, a) + VectorXd::Unit(c, b)) / std::sqrt(2.0));
        grid.push_back((VectorXd::Unit(c, a) - VectorXd::Unit(c, b)) / std::sqrt(2.0));
      }
    }
  }
  return grid;
}

// f at every grid point. The points are independent, so the second half is scored on another
// thread while this one scores the first: the same numbers in the same places as one loop (f is a
// pure function of its argument), in about half the time; the grid is most of a design's search.
std::vector<double> scores_on_grid(const std::vector<VectorXd>& grid, const std::function<double(const VectorXd&)>& f) {
  std::vector<double> scores(grid.size());
  const auto score_range = [&](std::size_t begin, std::size_t end) {
    for (std::size_t j = begin; j < end; ++j) scores[j] = f(grid[j]);
  };
  constexpr std::size_t kWorthASecondThread = 16;
  if (grid.size() < kWorthASecondThread) {
    score_range(0, grid.size());
    return scores;
  }
  const std::size_t half = grid.size() / 2;
  std::future<void> second = std::async(std::launch::async, score_range, half, grid.size());
  score_range(0, half);
  second.get();  // rethrows f's exception, if any
  return scores;
}

// Maximise f(w) over unit w: best grid point, then a compass search along the tangent directions.
VectorXd maximise_on_sphere(Index c, const std::function<double(const VectorXd&)>& f,
                            const SubspaceSearchOptions& options) {
  const std::vector<VectorXd> grid = initial_grid(c, options.grid_points);
  const std::vector<double> scores = scores_on_grid(grid, f);
  std::size_t best_j = 0;  // the first of the best, as a sequential scan finds it
  for (std::size_t j = 1; j < grid.size(); ++j)
    if (scores[j] > scores[best_j]) best_j = j;
  VectorXd best = grid[best_j];
  double best_score = scores[best_j];
  if (c == 1) return best;
  double step = kPi / std::sqrt(static_cast<double>(grid.size()));
  for (int moves = 0; step > options.final_step_rad && moves < options.max_moves; ++moves) {
    const MatrixXd tangents = complement(best);
    bool improved = false;
    for (Index t = 0; t < tangents.cols() && !improved; ++t)
      for (const double sign : {1.0, -1.0}) {
        const VectorXd trial = std::cos(step) * best + sign * std::sin(step) * tangents.col(t);
        const double s = f(trial);
        if (s > best_score) {
          best_score = s, best = trial.normalized(), improved = true;
          break;
        }
      }
    if (!improved) step *= 0.5;
  }
  return best;
}

}  // namespace

MatrixXd choose_subspace(const MatrixXd& basis, int p, const SubspaceScore& score,
                         const SubspaceSearchOptions& options) {
  const Index c = basis.cols();
  if (p <= 0) return MatrixXd(basis.rows(), 0);
  if (p >= c) return basis;
  if (p == 1) {
    const auto f = [&](const VectorXd& w) { return score(basis * w); };
    return basis * maximise_on_sphere(c, f, options);
  }
  if (p == c - 1) {
    const auto f = [&](const VectorXd& w) { return score(basis * complement(w)); };
    return basis * complement(maximise_on_sphere(c, f, options));
  }
  return basis.rightCols(p);
}

}  // namespace chaser::flight::fdi
