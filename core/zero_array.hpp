#pragma once
// Fixed-size Eigen matrices at zero in a std::array, for state that lives across steps.
#include <array>
#include <cstddef>

namespace chaser {

// N matrices at zero. Not `std::array<Vec3, N> a{}`: an Eigen matrix's default constructor leaves
// its coefficients uninitialised, and value-initialising the array only runs it.
template <class Matrix, std::size_t N>
std::array<Matrix, N> zero_array() {
  std::array<Matrix, N> a;
  a.fill(Matrix::Zero());
  return a;
}

}  // namespace chaser
