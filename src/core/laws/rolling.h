// Coulomb friction with rolling resistance: per contact the normal force, two tangential
// components and two rolling components, m = (m_n, m_t, m_r) in
//   K = {|m_t| <= mu m_n, |m_r| <= mur m_n}.
// A rolling component is a force m_r whose torque R m_r (R = a_i a_j / (a_i + a_j) from the
// arms, a_i for a wall) opposes the relative rolling of the pair: its row of G reads
// h R t_k . (w_j - w_i), so the rolling torque is at most mur R m_n, as the keyword promises.
// The dual cone of K is {g_n >= mu |g_t| + mur |g_r|}: De Saxce's shift is
// mu |g_t| + mur |g_r| (coulomb.h), which makes a sliding or rolling contact keep g_n = 0 and
// dissipate mu m_n |v_t| + mur m_n R |w_roll|.
#pragma once

#include "disc_law.h"

namespace hardcontact {

// two discs: the tangential force, then the rolling force, |m_r| <= rolling m_n
using RollingLaw = DiscLaw<TangentialDisc, RollingDisc>;

}    // namespace hardcontact
