// Coulomb friction with twisting resistance: per contact the normal force, two tangential
// components and one twisting component, m = (m_n, m_t, m_w) in
//   K = {|m_t| <= mu m_n, |m_w| <= mut m_n}.
// The twisting component is a force-like multiplier m_w whose torque R m_w n about the normal
// (R = rolling_radius: a_i a_j / (a_i + a_j) from the arms, a_i on a wall) opposes the pair's
// relative spin about the normal: its row of G reads h R n . (w_j - w_i), so the twisting
// torque is at most mut R m_n, as the keyword promises. n is orthogonal to both tangents,
// so the spins do not couple this row with the tangential or rolling ones (a disc of its own,
// uncoupled). De Saxce's shift gains mut |g_w|: a contact that twists keeps g_n = 0 and
// dissipates mut m_n R |n . (w_j - w_i)| (disc_law.h).
#pragma once

#include "disc_law.h"
#include "rolling.h"

namespace hardcontact {

// The pair's relative spin about the normal: a torque R m_w n on j (its opposite on i),
// |m_w| <= mut m_n.
struct TwistingDisc : CoupleDisc<1, TwistingDisc> {
  static constexpr int size = 1;
  static const Vec3 &axis(const ContactProblem &p, int c, int) { return p.normal[c]; }
  // n is orthogonal to the tangents: no entry of A couples this row with the others
  static constexpr bool coupled = false;
  static double coupling(const ContactProblem &, int) { return 0.0; }
  static constexpr const char *keyword = "twisting";
  static constexpr const char *bound =
      "a coefficient >= 0 (the twisting torque is at most twisting x R x the normal force)";
  static constexpr const char *usage =
      "twisting mut [I J]: twisting resistance >= 0 (torque about the normal at most mut R F_n) "
      "for type pairs I J (all: default)";
};

// two discs: the tangential force, then the twisting one, |m_w| <= twisting m_n
using TwistingLaw = DiscLaw<TangentialDisc, TwistingDisc>;
// three: the tangential force, the rolling force, the twisting one
using RollingTwistingLaw = DiscLaw<TangentialDisc, RollingDisc, TwistingDisc>;

}    // namespace hardcontact
