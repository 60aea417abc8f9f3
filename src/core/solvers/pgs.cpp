#include "pgs.h"

namespace hardcontact {

template <class Law>
bool PgsSolver<Law>::step(const SolverSettings &, std::vector<double> &mu, std::vector<Vec3> &u)
{
  const DualOperator &op = this->op_;
  const ContactProblem &p = op.problem();
  const std::vector<int> &rows = this->set_.rows();
  // Boundary rows (Jacobi) from the exchanged velocities, whose gaps are in g_ ...
  const int nrows = static_cast<int>(rows.size());
  dmu_.assign(nrows, 0.0);
  for (int q = 0; q < nrows; ++q) {
    const int c = rows[q];
    if (p.body_j[c] < p.n_owned) continue;    // owned pair or wall: swept below
    const double bound = op.gershgorin_row(c);
    if (bound <= 0.0) continue;
    dmu_[q] = Law::project(mu[c] - this->g_[c] / bound) - mu[c];
  }
  for (int q = 0; q < nrows; ++q) {
    if (dmu_[q] == 0.0) continue;
    const int c = rows[q];
    mu[c] += dmu_[q];
    op.apply(c, dmu_[q], u);
  }
  // ... then rows inside this process, Gauss-Seidel: the exact minimiser along each row.
  for (const int c : rows) {
    if (p.body_j[c] >= p.n_owned) continue;
    const double diag = op.diagonal(c);
    if (diag <= 0.0) continue;
    const double next = Law::project(mu[c] - op.gap(c, u) / diag);
    op.apply(c, next - mu[c], u);
    mu[c] = next;
  }
  op.forward(u);
  return true;
}

template class PgsSolver<NormalLaw>;

}    // namespace hardcontact
