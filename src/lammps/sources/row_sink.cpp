#include "row_sink.h"

#include "../../core/residual.h"

namespace hardcontact {

void RowSink::begin_candidates(double scale)
{
  p_.clear_contacts();
  // once per body, not once per offer (each pass offers every pair and wall)
  const int nb = p_.n_bodies();
  speed_.resize(nb);
  for (int b = 0; b < nb; ++b) speed_[b] = p_.u_free[b].norm();
  scale_ = scale;
  u_ = nullptr;
  added_ = 0;
}

void RowSink::begin_missed(const std::vector<Vec3> &u, double speed_scale, double tol,
                           std::vector<double> &speed)
{
  scale_ = 1.0;    // a candidate of the step is a row already
  const int nb = p_.n_bodies();
  speed.resize(nb);
  for (int b = 0; b < nb; ++b) speed[b] = u[b].norm();
  speed_u_ = &speed;
  u_ = &u;
  speed_scale_ = speed_scale;
  tol_ = tol;
  added_ = 0;
}

// Eq. 15 at u, measured like every solved row: the scale the solve just used, so that every
// row meets one criterion.
bool RowSink::violated(int i, int j, const Vec3 &n, double d, double size,
                       const Vec3 *u_wall) const
{
  const Vec3 uj = !is_wall(j) ? (*u_)[j] : u_wall ? *u_wall : Vec3::Zero();
  const Vec3 du = uj - (*u_)[i];
  const double g = d + p_.h * n.dot(du);
  const double scale = row_scale(size, p_.h, speed_scale_, tol_, p_.gap_roundoff);
  return row_violation(g, 0.0, scale) > tol_;
}

}    // namespace hardcontact
