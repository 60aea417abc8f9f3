// The only code that applies G and G^T of eq. 15-16 (G_c = grad D_c: -n_c on body i, +n_c on
// body j, eq. 1), so that every solver shares one definition of the dual operator
// A = h^2 G M^-1 G^T of section 3.3. Bound to a problem once per solve; its scratch (degrees)
// is kept between solves, so no call allocates once sizes have settled.
#pragma once

#include "contact_problem.h"
#include "container_bytes.h"
#include "distributed_ops.h"

#include <Eigen/SparseCore>

#include <algorithm>
#include <vector>

namespace hardcontact {

class DualOperator {
 public:
  void bind(const ContactProblem &p, DistributedOps &ops)
  {
    p_ = &p;
    ops_ = &ops;
  }
  const ContactProblem &problem() const { return *p_; }
  DistributedOps &ops() const { return *ops_; }

  // Eq. 16: u = u_free + h M^-1 G^T mu over the listed rows (rows outside hold mu = 0), for
  // owned bodies, then the ghosts' u from their owners. Each row pushes only its owned bodies:
  // a row coupling an owned body with a ghost is held by both processes (newton off), so each
  // side applies its own half exactly once. B: the law's block (multipliers per row, mu[B c..]).
  template <int B = 1>
  void velocities(const std::vector<int> &rows, const std::vector<double> &mu,
                  std::vector<Vec3> &u) const
  {
    velocities_with<B>(rows, [&](int c) { return &mu[static_cast<size_t>(B) * c]; }, u);
  }
  // The same with each row's block computed as the row is applied (mu_of(c) -> pointer to
  // its B multipliers): a solver's update of mu fused into the one pass over the rows.
  template <int B = 1, class MuOf>
  void velocities_with(const std::vector<int> &rows, MuOf &&mu_of, std::vector<Vec3> &u) const
  {
    start_velocities(u);
    if constexpr (B == 1) {
      const RowKernel k(*p_);
      double *v = doubles(u);
      for (const int c : rows) {
        const double *m = mu_of(c);
        if (m[0] != 0.0) k.apply(c, m[0], v);
      }
    } else {
      for (const int c : rows) {
        const double *m = mu_of(c);
        if (nonzero<B>(m)) apply_block<B>(c, m, u);
      }
    }
    forward(u);
  }
  // The same over every row.
  template <int B = 1>
  void velocities(const std::vector<double> &mu, std::vector<Vec3> &u) const
  {
    start_velocities(u);
    const int nc = p_->n_contacts();
    for (int c = 0; c < nc; ++c) {
      const double *m = &mu[static_cast<size_t>(B) * c];
      if (nonzero<B>(m)) apply_block<B>(c, m, u);
    }
    forward(u);
  }
  // w = h M^-1 G^T m over the listed rows, from rest (no u_free): the velocity change of the
  // impulses m alone, so that h G_c w is A m (Krylov solvers). Ghosts from their owners.
  // moved: when given, the owned bodies the rows touch, and w must be 0 on every other owned
  // body (the caller zeroed it once): only these are cleared, so a product costs the rows and
  // their bodies, not every body (a bed forming under a million falling spheres).
  template <class MOf>
  void impulse_velocities_with(const std::vector<int> &rows, MOf &&m_of, std::vector<Vec3> &w,
                               const std::vector<int> *moved = nullptr) const
  {
    const ContactProblem &p = *p_;
    w.resize(p.n_dof());
    const int nb = p.n_bodies();
    if (moved == nullptr) {
      std::fill(w.begin(), w.begin() + p.n_owned, Vec3::Zero());
      if (p.rotates()) std::fill(w.begin() + nb, w.begin() + nb + p.n_owned, Vec3::Zero());
    } else {
      for (const int b : *moved) w[b] = Vec3::Zero();
      if (p.rotates())
        for (const int b : *moved) w[nb + b] = Vec3::Zero();
    }
    const RowKernel k(p);
    double *v = doubles(w);
    for (const int c : rows) {
      const double m = m_of(c);
      if (m != 0.0) k.apply(c, m, v);
    }
    forward(w);
  }
  // u = u_free (mu = 0).
  void free_velocities(std::vector<Vec3> &u) const
  {
    start_velocities(u);
    forward(u);
  }
  // Ghost copies of u from their owners (after in-place updates with apply()).
  void forward(std::vector<Vec3> &u) const
  {
    ops_->forward(doubles(u), 3);
    if (p_->rotates()) ops_->forward(doubles(u) + 3 * p_->n_bodies(), 3);
  }

  // g_c(u) = D_c + h G_c u, eq. 15: also the gradient of the dual objective at mu(u).
  double gap(int c, const std::vector<Vec3> &u) const { return p_->predicted_gap(c, u); }
  // The B components of h G_c u + D_c for row c: the gap, then (friction) the tangential
  // displacements h t_k . v_slip. Linear in u: De Saxce's shift of the gap (laws/disc_law.h)
  // is the solver's (IterativeSolver::gradient_block).
  template <int B>
  void gap_block(int c, const std::vector<Vec3> &u, double *g) const
  {
    if constexpr (B == 1) {
      g[0] = gap(c, u);
    } else {
      static_assert(B == 3 || B == 5, "blocks of 1 (normal), 3 (Coulomb) or 5 (rolling)");
      const ContactProblem &p = *p_;
      const Vec3 v = p.h * p.slip_velocity(c, u);
      g[0] = p.gap[c] + p.normal[c].dot(v);
      g[1] = p.tangent1[c].dot(v);
      g[2] = p.tangent2[c].dot(v);
      if constexpr (B == 5) {
        const Vec3 roll = (p.h * p.rolling_radius(c)) * p.relative_spin(c, u);
        g[3] = p.tangent1[c].dot(roll);
        g[4] = p.tangent2[c].dot(roll);
      }
    }
  }
  // Adds the velocity change of an impulse h dmu G_c to the owned bodies of row c.
  void apply(int c, double dmu, std::vector<Vec3> &u) const
  {
    RowKernel(*p_).apply(c, dmu, doubles(u));
  }
  // The same for a block: with friction the impulse h (m_n n + m_1 t_1 + m_2 t_2) acts on j
  // at -a_j n and its opposite on i at +a_i n (the arms), so both spin by -a I^-1 n x impulse.
  template <int B>
  void apply_block(int c, const double *dm, std::vector<Vec3> &u) const
  {
    if constexpr (B == 1) {
      apply(c, dm[0], u);
    } else {
      const ContactProblem &p = *p_;
      const Vec3 impulse =
          p.h * (dm[0] * p.normal[c] + dm[1] * p.tangent1[c] + dm[2] * p.tangent2[c]);
      const int i = p.body_i[c], j = p.body_j[c], nb = p.n_bodies();
      const Vec3 turn = p.normal[c].cross(impulse);
      if (i < p.n_owned) {
        u[i] -= p.inv_mass[i] * impulse;
        if (p.rotates()) u[nb + i] -= (p.inv_inertia[i] * p.arm_i[c]) * turn;
      }
      if (j >= 0 && j < p.n_owned) {
        u[j] += p.inv_mass[j] * impulse;
        if (p.rotates()) u[nb + j] -= (p.inv_inertia[j] * p.arm_j[c]) * turn;
      }
      if constexpr (B == 5) {
        // rolling: the angular impulse h R (m_r1 t_1 + m_r2 t_2) on j, its opposite on i
        const Vec3 twist =
            (p.h * p.rolling_radius(c)) * (dm[3] * p.tangent1[c] + dm[4] * p.tangent2[c]);
        if (i < p.n_owned) u[nb + i] -= p.inv_inertia[i] * twist;
        if (j >= 0 && j < p.n_owned) u[nb + j] += p.inv_inertia[j] * twist;
      }
    }
  }

  // A_cc = h^2 (w_i + w_j): the exact step along one row (Gauss-Seidel).
  double diagonal(int c) const
  {
    const ContactProblem &p = *p_;
    const int j = p.body_j[c];
    return p.h * p.h * (p.inv_mass[p.body_i[c]] + (is_wall(j) ? 0.0 : p.inv_mass[j]));
  }
  // The largest eigenvalue of the block A_cc: with friction it is diagonal (n, t_1, t_2 are
  // orthonormal and n x n = 0), its tangential entries h^2 sum (w + a^2 / I). With rolling
  // the spins couple the tangential and rolling entries: its trace bounds it (A_cc >= 0).
  template <int B>
  double block_diagonal(int c) const
  {
    if constexpr (B == 1) {
      return diagonal(c);
    } else if constexpr (B == 5) {
      const ContactProblem &p = *p_;
      const int i = p.body_i[c], j = p.body_j[c];
      const double r2 = p.rolling_radius(c) * p.rolling_radius(c);
      double t = 3.0 * p.inv_mass[i] + p.inv_inertia[i] * (2.0 * p.arm_i[c] * p.arm_i[c] + 2.0 * r2);
      if (!is_wall(j))
        t += 3.0 * p.inv_mass[j] + p.inv_inertia[j] * (2.0 * p.arm_j[c] * p.arm_j[c] + 2.0 * r2);
      return p.h * p.h * t;
    } else {
      const ContactProblem &p = *p_;
      const int i = p.body_i[c], j = p.body_j[c];
      double d = p.inv_mass[i];
      if (p.rotates()) d += p.inv_inertia[i] * p.arm_i[c] * p.arm_i[c];
      if (!is_wall(j)) {
        d += p.inv_mass[j];
        if (p.rotates()) d += p.inv_inertia[j] * p.arm_j[c] * p.arm_j[c];
      }
      return p.h * p.h * d;
    }
  }
  // The diagonal of the block A_cc, d[0..B): the normal entry h^2 (w_i + w_j), the two
  // tangential ones h^2 sum (w + a^2 / I) (equal: the block is diagonal with friction,
  // block_diagonal), and with rolling the two rolling ones h^2 R^2 (1/I_i + 1/I_j) (the
  // block couples these with the tangential ones; the diagonal ignores it).
  template <int B>
  void block_diagonals(int c, double *d) const
  {
    const ContactProblem &p = *p_;
    const int i = p.body_i[c], j = p.body_j[c];
    const bool wall = is_wall(j);
    const double h2 = p.h * p.h;
    d[0] = h2 * (p.inv_mass[i] + (wall ? 0.0 : p.inv_mass[j]));
    if constexpr (B > 1) {
      double t = p.inv_mass[i] + p.inv_inertia[i] * p.arm_i[c] * p.arm_i[c];
      if (!wall) t += p.inv_mass[j] + p.inv_inertia[j] * p.arm_j[c] * p.arm_j[c];
      d[1] = d[2] = h2 * t;
    }
    if constexpr (B == 5) {
      const double r = p.rolling_radius(c);
      d[3] = d[4] = h2 * r * r * (p.inv_inertia[i] + (wall ? 0.0 : p.inv_inertia[j]));
    }
  }
  // Gershgorin: the off-diagonal entries of row c are h^2 w_k n_c.n_d for rows d sharing body
  // k, so |A_cc| + sum |A_cd| <= h^2 (w_i deg_i + w_j deg_j) with deg_k the rows touching k.
  // With friction each of the B components of a row meets B of every row d on body k, each
  // entry at most w_k + A_k^2 / I_k, A_k the longest arm on k (a rolling radius is shorter
  // than either arm). count_degrees() over the listed
  // rows first (owners count, ghosts receive: an owner holds every row of its own bodies).
  void count_degrees(const std::vector<int> &rows);
  template <int B = 1>
  double gershgorin_row(int c) const
  {
    const ContactProblem &p = *p_;
    const int i = p.body_i[c], j = p.body_j[c];
    if constexpr (B == 1) {
      double row = p.inv_mass[i] * deg_[i];
      if (!is_wall(j)) row += p.inv_mass[j] * deg_[j];
      return p.h * p.h * row;
    } else {
      double row = body_weight(i) * deg_[i];
      if (!is_wall(j)) row += body_weight(j) * deg_[j];
      return B * p.h * p.h * row;
    }
  }
  // L >= largest eigenvalue of A restricted to the listed rows, over all processes (Remark 8
  // for any radii and masses: 2 kappa h^2 / m with equal masses and kappa rows per body).
  // 0 when there is no row. Counts degrees.
  template <int B = 1>
  double bound(const std::vector<int> &rows)
  {
    count_degrees(rows);
    double b = 0.0;
    for (const int c : rows) {
      const double r = gershgorin_row<B>(c);
      b = b > r ? b : r;
    }
    return ops_->max_all(b);
  }

  // The assembled A over every row, for direct solvers (normal law); ghosts count as their
  // owned copy (ContactProblem::owner; throws if a body is owned by another process).
  Eigen::SparseMatrix<double> assembled() const;

  // sum_c G_c^T mu_c on each owned body: the contact force (eq. 16 divided by h), per body,
  // and with friction the contact torque (torque: null to skip).
  template <int B = 1>
  void forces(const std::vector<double> &mu, std::vector<Vec3> &force,
              std::vector<Vec3> *torque = nullptr) const;

  double memory_usage() const { return bytes_of(deg_, arm2_); }

 private:
  // u = u_free (owned bodies), then the spins.
  void start_velocities(std::vector<Vec3> &u) const
  {
    const ContactProblem &p = *p_;
    const int nb = p.n_bodies();
    u.resize(p.n_dof());
    for (int b = 0; b < p.n_owned; ++b) u[b] = p.u_free[b];
    if (p.rotates())
      for (int b = 0; b < p.n_owned; ++b) u[nb + b] = p.w_free[b];
  }
  template <int B>
  static bool nonzero(const double *m)
  {
    if constexpr (B == 1) return m[0] != 0.0;
    else if constexpr (B == 3) return m[0] != 0.0 || m[1] != 0.0 || m[2] != 0.0;
    else return m[0] != 0.0 || m[1] != 0.0 || m[2] != 0.0 || m[3] != 0.0 || m[4] != 0.0;
  }
  // w + A^2 / I: bounds the inverse effective mass of a body's contact points in a
  // tangential direction (A^2 from count_degrees)
  double body_weight(int b) const
  {
    const ContactProblem &p = *p_;
    return p.inv_mass[b] + (p.rotates() ? p.inv_inertia[b] * arm2_[b] : 0.0);
  }

  const ContactProblem *p_ = nullptr;
  DistributedOps *ops_ = nullptr;
  std::vector<double> deg_;      // per body, from count_degrees()
  std::vector<double> arm2_;     // per body, the longest arm squared (friction), ditto
};

// One-off forms of the above, for the host and tests (they bind an operator of their own).
double dual_operator_bound(const ContactProblem &p, DistributedOps &ops);
double dual_operator_bound(const ContactProblem &p, const std::vector<int> &rows,
                           DistributedOps &ops);
template <int B = 1>
void contact_forces(const ContactProblem &p, const std::vector<double> &mu,
                    std::vector<Vec3> &force, std::vector<Vec3> *torque = nullptr);

}    // namespace hardcontact
