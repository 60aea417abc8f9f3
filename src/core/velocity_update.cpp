#include "velocity_update.h"

namespace hardcontact {

void contact_forces(const ContactProblem &p, const std::vector<double> &mu,
                    std::vector<Vec3> &force)
{
  force.assign(p.n_bodies(), Vec3::Zero());
  const int nc = p.n_contacts();
  for (int c = 0; c < nc; ++c) {
    if (mu[c] == 0.0) continue;
    const Vec3 f = mu[c] * p.normal[c];    // G_c is -n on body i, +n on body j (eq. 1)
    const int i = p.body_i[c], j = p.body_j[c];
    if (i < p.n_owned) force[i] -= f;
    if (j >= 0 && j < p.n_owned) force[j] += f;
  }
}

void velocities_from_multipliers(const ContactProblem &p, const std::vector<int> &rows,
                                 const std::vector<double> &mu, std::vector<Vec3> &u,
                                 DistributedOps &ops)
{
  u.resize(p.n_bodies());
  for (int b = 0; b < p.n_owned; ++b) u[b] = p.u_free[b];
  for (const int c : rows) {
    if (mu[c] == 0.0) continue;
    const Vec3 impulse = (p.h * mu[c]) * p.normal[c];
    const int i = p.body_i[c], j = p.body_j[c];
    if (i < p.n_owned) u[i] -= p.inv_mass[i] * impulse;
    if (j >= 0 && j < p.n_owned) u[j] += p.inv_mass[j] * impulse;
  }
  ops.forward(u.data()->data(), 3);
}

void velocities_from_multipliers(const ContactProblem &p, const std::vector<double> &mu,
                                 std::vector<Vec3> &u, DistributedOps &ops)
{
  std::vector<int> all(p.n_contacts());
  for (int c = 0; c < p.n_contacts(); ++c) all[c] = c;
  velocities_from_multipliers(p, all, mu, u, ops);
}

}    // namespace hardcontact
