#include "dual_operator.h"

#include "laws/law_list.h"

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

template <class Law>
void DualOperator::forces(const std::vector<double> &mu, std::vector<Vec3> &force,
                          std::vector<Vec3> *torque) const
{
  constexpr int B = Law::block;
  const ContactProblem &p = *p_;
  force.assign(p.n_bodies(), Vec3::Zero());
  if (torque) torque->assign(p.n_bodies(), Vec3::Zero());
  const int nc = p.n_contacts();
  Vec3 unused[4];    // what a body not owned here (or a wall) would receive
  for (int c = 0; c < nc; ++c) {
    const double *m = &mu[static_cast<size_t>(B) * c];
    if (!nonzero<B>(m)) continue;
    const int i = p.body_i[c], j = p.body_j[c];
    const bool own_i = i < p.n_owned, own_j = j >= 0 && j < p.n_owned;
    Vec3 &fi = own_i ? force[i] : unused[0];
    Vec3 &fj = own_j ? force[j] : unused[1];
    if constexpr (B > 1) {
      if (torque) {
        Law::add_forces(p, c, m, fi, fj, own_i ? &(*torque)[i] : &unused[2],
                        own_j ? &(*torque)[j] : &unused[3]);
        continue;
      }
    }
    Law::add_forces(p, c, m, fi, fj, nullptr, nullptr);
  }
}

#define HARDCONTACT_DETAIL_FORCES(Law, Enumerator, Suffix, unused)                                \
  template void DualOperator::forces<Law>(const std::vector<double> &, std::vector<Vec3> &,     \
                                          std::vector<Vec3> *) const;                           \
  template void contact_forces<Law>(const ContactProblem &, const std::vector<double> &,        \
                                    std::vector<Vec3> &, std::vector<Vec3> *);

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

template <class Law>
void contact_forces(const ContactProblem &p, const std::vector<double> &mu,
                    std::vector<Vec3> &force, std::vector<Vec3> *torque)
{
  SerialOps none;    // forces need no communication
  DualOperator op;
  op.bind(p, none);
  op.forces<Law>(mu, force, torque);
}
HARDCONTACT_LAWS_WITH(HARDCONTACT_DETAIL_FORCES, ~)

}    // namespace hardcontact
