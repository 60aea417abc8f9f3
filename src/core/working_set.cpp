#include "working_set.h"

#include "laws/law_list.h"

namespace hardcontact {

template <class Law>
void WorkingSet<Law>::init(const ContactProblem &p, const std::vector<double> &mu, double tol,
                      DistributedOps &ops)
{
  const int nc = p.n_contacts();
  speed_scale_ = row_scales(p, tol, ops, scale_);
  // friction: the slip conditions' scales (residual.h, contact_speed_scale), h max(V, V_t)
  // with `speed contact`, else the gap conditions' own. A condition every process shares (V_t
  // is a reduction): not p.rotates(), false on a process that holds no sphere.
  if constexpr (Law::block > 1) {
    if (p.contact_speed_scale) {
      const double v = std::max(speed_scale_, contact_speed_scale(p, ops));
      slip_scale_.resize(nc);
      for (int c = 0; c < nc; ++c)
        slip_scale_[c] = row_scale(p.size[c], p.h, v, tol, p.gap_roundoff);
    } else {
      slip_scale_ = scale_;
    }
  }
  rows_.clear();
  member_.assign(nc, 0);
  next_check_ = 1;
  for (int c = 0; c < nc; ++c) {
    const int j = p.body_j[c];
    const Vec3 du = (is_wall(j) ? Vec3::Zero() : p.u_free[j]) - p.u_free[p.body_i[c]];
    if (mu[static_cast<size_t>(Law::block) * c] > 0.0 || p.target[c] <= p.h * du.norm()) {
      rows_.push_back(c);
      member_[c] = 1;
    }
  }
}

template <class Law>
int WorkingSet<Law>::expand(const ContactProblem &p, const std::vector<Vec3> &u, double tol)
{
  int added = 0;
  const int nc = p.n_contacts();
  for (int c = 0; c < nc; ++c) {
    if (member_[c]) continue;
    if (NormalLaw::violation(p.predicted_gap(c, u), 0.0, scale_[c]) <= tol) continue;
    rows_.push_back(c);
    member_[c] = 1;
    ++added;
  }
  return added;
}

template <class Law>
typename WorkingSet<Law>::Verdict WorkingSet<Law>::check(int k, double residual, double tol,
                                      const ContactProblem &p, const std::vector<double> &mu,
                                      const std::vector<Vec3> &u, DistributedOps &ops)
{
  const bool scheduled = k == next_check_;
  if (residual > tol && !scheduled) return Verdict::Iterate;
  if (scheduled) next_check_ += next_check_ < 64 ? next_check_ : 64;
  if (ops.sum_all(expand(p, u, tol)) > 0.0) return Verdict::Grown;
  if (residual > tol) return Verdict::Iterate;
  return energy_within_bound(p, mu, u, ops, Law::block) ? Verdict::Converged : Verdict::Iterate;
}

HARDCONTACT_INSTANTIATE_FOR_LAWS(WorkingSet)

}    // namespace hardcontact
