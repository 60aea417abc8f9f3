// The one place that decides which offered (i, j) become rows of the contact problem: the
// candidate test of Remark 7 and, after a solve, the test for a row the candidates missed.
// Every source (pairs, walls, ...) feeds it, so both tests are written once.
#pragma once

#include "contact_source.h"

#include "lmptype.h"

#include <vector>

namespace hardcontact {

class RowSink {
 public:
  // tag, nlocal: to count a row shared by two processes on exactly one of them. speed: the
  // caller's workspace for |u_free| per body (kept between steps: no allocation per step).
  RowSink(ContactProblem &problem, const LAMMPS_NS::tagint *tag, int nlocal,
          std::vector<double> &speed) :
      p_(problem), tag_(tag), nlocal_(nlocal), speed_(speed)
  {
  }

  // Candidates: rows whose gap at q^n the free speeds could close within the step,
  // D <= scale h (|u_i| + |u_j|) (scale 1; scale 0: the overlapping rows, for diagnostics).
  void begin_candidates(double scale);
  // Missed rows: after a solve to velocities u with row scales of speed V (residual.h), the
  // non-candidates violated beyond tol at u (a light sphere struck by a heavy one can move
  // faster than its free speed). Then u satisfies eq. 15 for every offered row.
  // speed: the caller's workspace for |u| per body (kept between steps).
  void begin_missed(const std::vector<Vec3> &u, double speed_scale, double tol,
                    std::vector<double> &speed);

  // A row against a pair or a wall at rest. D: the gap at t^n (eq. 15).
  void offer(int i, int j, const Vec3 &n, double d, double size)
  {
    offer_row(i, j, n, d, size, nullptr);
  }
  // A row against a wall whose contact point moves at u_wall over the step (a moving plane,
  // region surface or mesh): its velocity enters both tests like a partner's, and the row
  // keeps it (Targets, slip).
  void offer(int i, int j, const Vec3 &n, double d, double size, const Vec3 &u_wall)
  {
    offer_row(i, j, n, d, size, &u_wall);
  }
  // moving: some wall moves this step (ContactStep::solve), so every row records
  // its wall's velocity (zero for a pair or a wall at rest).
  void set_moving(bool moving) { moving_ = moving; }
  // How far apart the surfaces of pair (i, j) may be and the pair still become a row in this
  // pass (the candidate test, or in the missed-row pass the gap u could close): a source may
  // skip a pair farther than that without computing its normal (offer_row would turn it down).
  double pair_reach(int i, int j) const
  {
    return u_ == nullptr ? scale_ * p_.h * (speed_[i] + speed_[j])
                         : p_.h * ((*speed_u_)[i] + (*speed_u_)[j]);
  }
  // The same for sphere i against a wall moving at speed wall (0 at rest): whether its gap d
  // is too wide.
  bool wall_too_far(int i, double d, double wall) const
  {
    return d > (u_ == nullptr ? scale_ * p_.h * (speed_[i] + wall) : p_.h * ((*speed_u_)[i] + wall));
  }
  // Rows added since the last begin_*.
  int added() const { return added_; }

 private:
  // u_wall: the wall's velocity at the contact, null for a pair or a wall at rest
  void offer_row(int i, int j, const Vec3 &n, double d, double size, const Vec3 *u_wall)
  {
    const double wall_speed = is_wall(j) && u_wall ? u_wall->norm() : 0.0;
    const double reach = speed_[i] + (!is_wall(j) ? speed_[j] : wall_speed);
    const bool candidate = d <= scale_ * p_.h * reach;
    if (u_ == nullptr) {
      if (!candidate) return;
    } else {
      if (candidate) return;
      // g = d + h n.(u_j - u_i) >= d - h (|u_i| + |u_j|): a gap u cannot close is not
      // violated, whatever its scale (most offers of the pass: one compare instead of the test)
      const double moved = (*speed_u_)[i] + (!is_wall(j) ? (*speed_u_)[j] : wall_speed);
      if (d > p_.h * moved || !violated(i, j, n, d, size, u_wall)) return;
    }
    // A pair held by two processes (newton off) is counted by the side of the smaller ID.
    const bool counted = is_wall(j) || j < nlocal_ || tag_[i] < tag_[j];
    p_.add_contact(i, j, n, d, size, counted);    // D < 0: see Targets
    if (moving_) p_.wall_velocity.push_back(u_wall ? *u_wall : Vec3::Zero());
    ++added_;
  }
  bool violated(int i, int j, const Vec3 &n, double d, double size, const Vec3 *u_wall) const;

  ContactProblem &p_;
  const LAMMPS_NS::tagint *tag_;
  int nlocal_;
  std::vector<double> &speed_;    // |u_free| per body, from begin_candidates
  double scale_ = 1.0;
  const std::vector<Vec3> *u_ = nullptr;    // set in the missed-row pass only
  const std::vector<double> *speed_u_ = nullptr;    // |u| per body, in that pass
  bool moving_ = false;
  double speed_scale_ = 0.0;
  double tol_ = 0.0;
  int added_ = 0;
};

}    // namespace hardcontact
