// A square matrix with few diagonals (kl below and ku above the main one), factorised by
// Gaussian elimination with partial pivoting and solved for many right-hand sides: the
// linear systems of one-dimensional transport (media/fog_diffuse_field.h), whose cost
// grows with the size times the band's width squared instead of the size cubed.
#pragma once

#include <cstddef>
#include <vector>

namespace skylit {

class BandedMatrix {
 public:
  BandedMatrix(int size, int below, int above);

  int size() const { return n_; }
  // Element (row, col); |col − row| must lie within the band given at construction.
  double& at(int row, int col) { return a_[index(row, col)]; }

  // Replaces the matrix by its LU factors (partial pivoting: the pivots' row swaps can
  // widen the upper band by `below`, which the storage leaves room for). False when a
  // pivot vanishes (the matrix is singular).
  bool factorise();
  // Solves A x = b in place for a factorised matrix.
  void solve(std::vector<double>& b) const;

 private:
  size_t index(int row, int col) const {
    return static_cast<size_t>(row) * static_cast<size_t>(width_) + static_cast<size_t>(col - row + kl_);
  }
  int n_, kl_, ku_, width_;
  std::vector<double> a_;
  std::vector<int> pivot_;
};

}  // namespace skylit
