#include "pgs.h"

namespace hardcontact {

// A block (one row: 1 component, or 3 with friction) moved to the law's set from a projected
// gradient step of length 1 / step_bound: the exact minimiser along a normal row (step_bound
// = A_cc), a descent step for a friction block (step_bound = its largest eigenvalue).
template <class Law>
bool PgsSolver<Law>::step(const SolverSettings &, std::vector<double> &mu, std::vector<Vec3> &u)
{
  const DualOperator &op = this->op_;
  const ContactProblem &p = op.problem();
  const std::vector<int> &rows = this->set_.rows();
  double next[B], g[B];
  // Boundary rows (Jacobi) from the exchanged velocities, whose gaps are in g_ ...
  const int nrows = static_cast<int>(rows.size());
  dmu_.assign(static_cast<size_t>(B) * nrows, 0.0);
  for (int q = 0; q < nrows; ++q) {
    const int c = rows[q];
    if (p.body_j[c] < p.n_owned) continue;    // owned pair or wall: swept below
    const double bound = op.template gershgorin_row<B>(c);
    if (bound <= 0.0) continue;
    const double *m = &mu[static_cast<size_t>(B) * c];
    const double *gc = &this->g_[static_cast<size_t>(B) * c];
    for (int k = 0; k < B; ++k) next[k] = m[k] - gc[k] / bound;
    Law::project(next, this->coef(c));
    for (int k = 0; k < B; ++k) dmu_[static_cast<size_t>(B) * q + k] = next[k] - m[k];
  }
  for (int q = 0; q < nrows; ++q) {
    const double *d = &dmu_[static_cast<size_t>(B) * q];
    bool any = false;
    for (int k = 0; k < B; ++k) any = any || d[k] != 0.0;
    if (!any) continue;
    const int c = rows[q];
    for (int k = 0; k < B; ++k) mu[static_cast<size_t>(B) * c + k] += d[k];
    op.template apply_block<B>(c, d, u);
  }
  // ... then rows inside this process, Gauss-Seidel: the exact minimiser along each row.
  for (const int c : rows) {
    if (p.body_j[c] >= p.n_owned) continue;
    const double diag = op.template block_diagonal<B>(c);
    if (diag <= 0.0) continue;
    double *m = &mu[static_cast<size_t>(B) * c];
    op.template gap_block<B>(c, u, g);
    for (int k = 0; k < B; ++k) next[k] = m[k] - g[k] / diag;
    Law::project(next, this->coef(c));
    for (int k = 0; k < B; ++k) {
      g[k] = next[k] - m[k];    // the step, applied below
      m[k] = next[k];
    }
    op.template apply_block<B>(c, g, u);
  }
  op.forward(u);
  return true;
}

template class PgsSolver<NormalLaw>;
template class PgsSolver<CoulombLaw>;
template class PgsSolver<RollingLaw>;

}    // namespace hardcontact
