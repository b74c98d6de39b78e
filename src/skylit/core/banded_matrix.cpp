#include "skylit/core/banded_matrix.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace skylit {

// Row r holds columns r − kl … r + kl + ku: its own band and the room its pivots' swaps
// need.
BandedMatrix::BandedMatrix(int size, int below, int above)
    : n_(size),
      kl_(below),
      ku_(above),
      width_(2 * below + above + 1),
      a_(static_cast<size_t>(size) * static_cast<size_t>(2 * below + above + 1), 0.0),
      pivot_(static_cast<size_t>(size), 0) {}

bool BandedMatrix::factorise() {
  const int reach = kl_ + ku_;  // the upper band after the swaps
  for (int r = 0; r < n_; ++r) {
    const int last_row = std::min(n_ - 1, r + kl_);
    int p = r;
    for (int i = r + 1; i <= last_row; ++i)
      if (std::abs(a_[index(i, r)]) > std::abs(a_[index(p, r)])) p = i;
    pivot_[static_cast<size_t>(r)] = p;
    if (a_[index(p, r)] == 0.0) return false;
    const int last_col = std::min(n_ - 1, r + reach);
    if (p != r)
      for (int c = r; c <= last_col; ++c) std::swap(a_[index(r, c)], a_[index(p, c)]);
    const double inverse = 1.0 / a_[index(r, r)];
    for (int i = r + 1; i <= last_row; ++i) {
      const double m = a_[index(i, r)] * inverse;
      a_[index(i, r)] = m;
      if (m == 0.0) continue;
      for (int c = r + 1; c <= last_col; ++c) a_[index(i, c)] -= m * a_[index(r, c)];
    }
  }
  return true;
}

void BandedMatrix::solve(std::vector<double>& b) const {
  for (int r = 0; r < n_; ++r) {
    const int p = pivot_[static_cast<size_t>(r)];
    if (p != r) std::swap(b[static_cast<size_t>(r)], b[static_cast<size_t>(p)]);
    const int last_row = std::min(n_ - 1, r + kl_);
    for (int i = r + 1; i <= last_row; ++i) b[static_cast<size_t>(i)] -= a_[index(i, r)] * b[static_cast<size_t>(r)];
  }
  const int reach = kl_ + ku_;
  for (int r = n_ - 1; r >= 0; --r) {
    double sum = b[static_cast<size_t>(r)];
    const int last_col = std::min(n_ - 1, r + reach);
    for (int c = r + 1; c <= last_col; ++c) sum -= a_[index(r, c)] * b[static_cast<size_t>(c)];
    b[static_cast<size_t>(r)] = sum / a_[index(r, r)];
  }
}

}  // namespace skylit
