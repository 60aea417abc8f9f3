#include "dual_operator.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace hardcontact {

void DualOperator::count_degrees(const std::vector<int> &rows)
{
  const ContactProblem &p = *p_;
  deg_.assign(p.n_bodies(), 0.0);
  for (const int c : rows) {
    const int i = p.body_i[c], j = p.body_j[c];
    if (i < p.n_owned) deg_[i] += 1.0;
    if (j >= 0 && j < p.n_owned) deg_[j] += 1.0;
  }
  ops_->forward(deg_.data(), 1);
  if (!p.rotates()) return;
  arm2_.assign(p.n_bodies(), 0.0);
  for (const int c : rows) {
    const int i = p.body_i[c], j = p.body_j[c];
    if (i < p.n_owned) arm2_[i] = std::max(arm2_[i], p.arm_i[c] * p.arm_i[c]);
    if (j >= 0 && j < p.n_owned) arm2_[j] = std::max(arm2_[j], p.arm_j[c] * p.arm_j[c]);
  }
  ops_->forward(arm2_.data(), 1);
}

Eigen::SparseMatrix<double> DualOperator::assembled() const
{
  const ContactProblem &p = *p_;
  const int nc = p.n_contacts();
  auto body_of = [&](int b) {
    if (b < p.n_owned) return b;
    const int o = p.owner.empty() ? -1 : p.owner[b];
    if (o < 0) throw std::runtime_error("the assembled operator needs every body on one process");
    return o;
  };
  // rows c and d sharing body k couple by h^2 w_k s_c s_d n_c.n_d, s = -1 on i, +1 on j
  std::vector<std::vector<std::pair<int, double>>> rows_of(p.n_owned);    // (row, sign)
  for (int c = 0; c < nc; ++c) {
    rows_of[body_of(p.body_i[c])].push_back({c, -1.0});
    if (p.body_j[c] >= 0) rows_of[body_of(p.body_j[c])].push_back({c, 1.0});
  }
  std::vector<Eigen::Triplet<double>> t;
  const double h2 = p.h * p.h;
  for (int k = 0; k < p.n_owned; ++k) {
    const double w = h2 * p.inv_mass[k];
    if (w == 0.0) continue;
    for (const auto &a : rows_of[k])
      for (const auto &b : rows_of[k])
        t.emplace_back(a.first, b.first,
                       w * a.second * b.second * p.normal[a.first].dot(p.normal[b.first]));
  }
  Eigen::SparseMatrix<double> A(nc, nc);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

template <int B>
void DualOperator::forces(const std::vector<double> &mu, std::vector<Vec3> &force,
                          std::vector<Vec3> *torque) const
{
  const ContactProblem &p = *p_;
  force.assign(p.n_bodies(), Vec3::Zero());
  if (torque) torque->assign(p.n_bodies(), Vec3::Zero());
  const int nc = p.n_contacts();
  for (int c = 0; c < nc; ++c) {
    const double *m = &mu[static_cast<size_t>(B) * c];
    if (!nonzero<B>(m)) continue;
    Vec3 f = m[0] * p.normal[c];
    if constexpr (B > 1) f += m[1] * p.tangent1[c] + m[2] * p.tangent2[c];
    const int i = p.body_i[c], j = p.body_j[c];
    if (i < p.n_owned) force[i] -= f;
    if (j >= 0 && j < p.n_owned) force[j] += f;
    if constexpr (B > 1) {
      if (!torque) continue;
      // the force on j acts at -a_j n, its opposite on i at +a_i n (apply_block)
      const Vec3 turn = p.normal[c].cross(f);
      if (i < p.n_owned) (*torque)[i] -= p.arm_i[c] * turn;
      if (j >= 0 && j < p.n_owned) (*torque)[j] -= p.arm_j[c] * turn;
      if constexpr (B == 5) {
        const Vec3 twist = p.rolling_radius(c) * (m[3] * p.tangent1[c] + m[4] * p.tangent2[c]);
        if (i < p.n_owned) (*torque)[i] -= twist;
        if (j >= 0 && j < p.n_owned) (*torque)[j] += twist;
      }
    }
  }
}
template void DualOperator::forces<1>(const std::vector<double> &, std::vector<Vec3> &,
                                      std::vector<Vec3> *) const;
template void DualOperator::forces<3>(const std::vector<double> &, std::vector<Vec3> &,
                                      std::vector<Vec3> *) const;
template void DualOperator::forces<5>(const std::vector<double> &, std::vector<Vec3> &,
                                      std::vector<Vec3> *) const;

double dual_operator_bound(const ContactProblem &p, const std::vector<int> &rows,
                           DistributedOps &ops)
{
  DualOperator op;
  op.bind(p, ops);
  return op.bound(rows);
}

double dual_operator_bound(const ContactProblem &p, DistributedOps &ops)
{
  std::vector<int> all(p.n_contacts());
  for (int c = 0; c < p.n_contacts(); ++c) all[c] = c;
  return dual_operator_bound(p, all, ops);
}

template <int B>
void contact_forces(const ContactProblem &p, const std::vector<double> &mu,
                    std::vector<Vec3> &force, std::vector<Vec3> *torque)
{
  SerialOps none;    // forces need no communication
  DualOperator op;
  op.bind(p, none);
  op.forces<B>(mu, force, torque);
}
template void contact_forces<1>(const ContactProblem &, const std::vector<double> &,
                                std::vector<Vec3> &, std::vector<Vec3> *);
template void contact_forces<3>(const ContactProblem &, const std::vector<double> &,
                                std::vector<Vec3> &, std::vector<Vec3> *);
template void contact_forces<5>(const ContactProblem &, const std::vector<double> &,
                                std::vector<Vec3> &, std::vector<Vec3> *);

}    // namespace hardcontact
