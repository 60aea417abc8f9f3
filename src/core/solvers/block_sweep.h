// One projected Gauss-Seidel sweep over a list of rows, made consistent under domain
// decomposition by a block-Jacobi split (the sweep of pgs):
// - rows coupling an owned body with a ghost (held by both processes) are updated first, all
//   at once from the velocities of the last exchange (their gaps g), with the Gershgorin step
//   of their row (dual_operator.h), so both processes compute the same multiplier and apply
//   their half of the same impulse: momentum stays exact. The simultaneous step is a descent
//   step because that row sum bounds the row of the dual operator;
// - rows whose two bodies are owned here (or a body and a wall) are then swept Gauss-Seidel,
//   each seeing the impulses of the rows before it, each block moved to the law's set from a
//   projected gradient step of length 1 / its largest eigenvalue (the exact minimiser along a
//   normal row, a descent step for a friction block).
// Each sweep decreases the dual objective; ghost velocities are refreshed at the end. The
// caller's row list must be the same on every process for the rows two processes share.
#pragma once

#include "../dual_operator.h"
#include "../residual.h"

#include <vector>

namespace hardcontact {

// dmu: scratch (kept by the caller, no allocation once sized); g: the gradients at u on the
// rows; shift: friction's shift of each row's normal gap (IterativeSolver), or null.
template <class Law>
void block_sweep(const DualOperator &op, const std::vector<int> &rows, const std::vector<double> &g,
                 const double *shift, std::vector<double> &dmu, std::vector<double> &mu,
                 std::vector<Vec3> &u)
{
  constexpr int B = Law::block;
  const ContactProblem &p = op.problem();
  double next[B], step[B];
  const int nrows = static_cast<int>(rows.size());
  dmu.assign(static_cast<size_t>(B) * nrows, 0.0);
  for (int q = 0; q < nrows; ++q) {
    const int c = rows[q];
    if (p.body_j[c] < p.n_owned) continue;    // owned pair or wall: swept below
    const double bound = op.template gershgorin_row<Law>(c);
    if (bound <= 0.0) continue;
    const double *m = &mu[static_cast<size_t>(B) * c];
    const double *gc = &g[static_cast<size_t>(B) * c];
    for (int k = 0; k < B; ++k) next[k] = m[k] - gc[k] / bound;
    Law::project(next, law_coefficients<Law>(p, c));
    for (int k = 0; k < B; ++k) dmu[static_cast<size_t>(B) * q + k] = next[k] - m[k];
  }
  for (int q = 0; q < nrows; ++q) {
    const double *d = &dmu[static_cast<size_t>(B) * q];
    bool any = false;
    for (int k = 0; k < B; ++k) any = any || d[k] != 0.0;
    if (!any) continue;
    const int c = rows[q];
    for (int k = 0; k < B; ++k) mu[static_cast<size_t>(B) * c + k] += d[k];
    op.template apply_block<Law>(c, d, u);
  }
  for (const int c : rows) {
    if (p.body_j[c] >= p.n_owned) continue;
    const double diag = op.template block_diagonal<Law>(c);
    if (diag <= 0.0) continue;
    double *m = &mu[static_cast<size_t>(B) * c];
    op.template gap_block<Law>(c, u, step);
    if (shift != nullptr) step[0] += shift[c];
    for (int k = 0; k < B; ++k) next[k] = m[k] - step[k] / diag;
    Law::project(next, law_coefficients<Law>(p, c));
    for (int k = 0; k < B; ++k) {
      step[k] = next[k] - m[k];    // applied below
      m[k] = next[k];
    }
    op.template apply_block<Law>(c, step, u);
  }
  op.forward(u);
}

}    // namespace hardcontact
