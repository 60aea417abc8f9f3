// Coulomb friction as a cone complementarity law: per contact the normal force and two
// tangential components, m = (m_n, m_t) in the cone K = {|m_t| <= coef m_n}. The dual of the
// paper's projection (section 3.3) keeps its form with G extended by the tangential rows of
// the contact points' relative velocity (rotations through the arms, contact_problem.h):
// minimise 1/2 m.A m + b.m over K, gradient g = (gap, h v_t) in displacement units.
//
// Its optimality (m in K, g in the dual cone, m.g = 0) alone would make a sliding contact
// separate by h coef |v_t| per step (the convex relaxation). De Saxce's bipotential removes
// it: the normal target is shifted by s = coef |g_t| (DualOperator::shift), and s is brought to
// a fixed point by the solver (IterativeSolver), so that a sliding contact has g_n = 0 and
// the contact does the work -coef m_n |v_t| <= 0.
#pragma once

#include "disc_law.h"

namespace hardcontact {

// one disc: the tangential force, |m_t| <= friction m_n
using CoulombLaw = DiscLaw<TangentialDisc>;

}    // namespace hardcontact
