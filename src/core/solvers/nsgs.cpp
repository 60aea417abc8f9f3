#include "nsgs.h"

#include <algorithm>

namespace hardcontact {

// The diagonal of each set row's local solve: for a shared row the Gershgorin bound of its
// row of A (both processes know it; it makes the simultaneous update a descent step), for an
// owned row its block's diagonal. With rolling the spins couple each tangential entry with one
// rolling entry (h^2 R (a_k / I_k) per body); raising both by that coupling makes the diagonal
// dominate the block, so the discs' independent steps stay a descent step.
template <class Law>
void NsgsSolver<Law>::rows_changed(const SolverSettings &)
{
  const ContactProblem &p = this->op_.problem();
  const std::vector<int> &rows = this->set_.rows();
  this->op_.count_degrees(rows);
  diag_.resize(static_cast<size_t>(B) * p.n_contacts());
  shared_.clear();
  own_.clear();
  for (const int c : rows) {
    double *d = &diag_[static_cast<size_t>(B) * c];
    const bool shared = p.body_j[c] >= p.n_owned;
    if (shared) {
      const double bound = this->op_.template gershgorin_row<Law>(c);
      for (int k = 0; k < B; ++k) d[k] = bound;
    } else {
      this->op_.template block_diagonals<Law>(c, d);
      if constexpr (B > 1) Law::dominate_couplings(p, c, d);
    }
    bool movable = true;
    for (int k = 0; k < B; ++k) movable = movable && d[k] > 0.0;
    if (!movable) continue;    // a row between two obstacles: no force can change anything
    (shared ? shared_ : own_).push_back(c);
  }
}

template <class Law>
void NsgsSolver<Law>::true_gradient(int c, const std::vector<Vec3> &u, double *g) const
{
  this->op_.template gap_block<Law>(c, u, g);
}

template <class Law>
void NsgsSolver<Law>::local(int c, std::vector<double> &mu, std::vector<Vec3> &u)
{
  double g[B], next[B], d[B];
  true_gradient(c, u, g);
  double *m = &mu[static_cast<size_t>(B) * c];
  for (int k = 0; k < B; ++k) next[k] = m[k];
  local_law(next, g, &diag_[static_cast<size_t>(B) * c], this->coef(c));
  bool any = false;
  for (int k = 0; k < B; ++k) {
    d[k] = next[k] - m[k];
    any = any || d[k] != 0.0;
    m[k] = next[k];
  }
  if (any) this->op_.template apply_block<Law>(c, d, u);
}

template <class Law>
bool NsgsSolver<Law>::step(const SolverSettings &, std::vector<double> &mu, std::vector<Vec3> &u)
{
  // shared rows: all at once from the gaps of the last exchange (g_, from set_residual)
  const int ns = static_cast<int>(shared_.size());
  dmu_.assign(static_cast<size_t>(B) * ns, 0.0);
  for (int q = 0; q < ns; ++q) {
    const int c = shared_[q];
    double g[B], next[B];
    for (int k = 0; k < B; ++k) g[k] = this->g_[static_cast<size_t>(B) * c + k];
    if constexpr (B > 1) g[0] -= this->shift(c);
    const double *m = &mu[static_cast<size_t>(B) * c];
    for (int k = 0; k < B; ++k) next[k] = m[k];
    local_law(next, g, &diag_[static_cast<size_t>(B) * c], this->coef(c));
    for (int k = 0; k < B; ++k) dmu_[static_cast<size_t>(B) * q + k] = next[k] - m[k];
  }
  for (int q = 0; q < ns; ++q) {
    const double *d = &dmu_[static_cast<size_t>(B) * q];
    const int c = shared_[q];
    for (int k = 0; k < B; ++k) mu[static_cast<size_t>(B) * c + k] += d[k];
    this->op_.template apply_block<Law>(c, d, u);
  }
  // owned rows: Gauss-Seidel, forward and backward on alternate sweeps
  if (sweeps_++ % 2 == 0) {
    for (const int c : own_) local(c, mu, u);
  } else {
    for (auto c = own_.rbegin(); c != own_.rend(); ++c) local(*c, mu, u);
  }
  this->op_.forward(u);
  return true;
}

template <class Law>
double NsgsSolver<Law>::set_residual(const std::vector<double> &mu, const std::vector<Vec3> &u)
{
  double r = 0.0;
  for (const int c : this->set_.rows()) {
    double *g = &this->g_[static_cast<size_t>(B) * c];
    true_gradient(c, u, g);
    if constexpr (B > 1) {
      const double s =
          this->cone_ == SolverSettings::Cone::Convex ? 0.0 : Law::shift(g, this->coef(c));
      this->shift_[c] = s;
      g[0] += s;
    }
    r = std::max(r, this->set_violation(c, mu, r));
  }
  return r;
}

HARDCONTACT_INSTANTIATE_FOR_LAWS(NsgsSolver)

}    // namespace hardcontact
