// `cohesion F [I J]`: a touching contact holds up to F of pull (core/cohesion.h) as an effect
// (effect.h): the pull goes into u_free before the solve, and the reported forces are the
// solver's mu' less it.
#pragma once

#include "effect.h"

namespace hardcontact {

class CohesionEffect : public Effect {
 public:
  static std::vector<EffectKeyword> keywords();

  bool present() const override;    // some coefficient > 0
  // Touching rows (D <= tol size) pull with their F; rows added by later rounds are not
  // touching.
  bool begin_step(EffectStep &step) override;
  const std::vector<double> *reported_forces(const ContactProblem &p,
                                             const std::vector<double> &mu, int block) override;

 private:
  std::vector<double> table_;    // F per type pair, (ntypes + 1)^2
  std::vector<double> row_f_;    // F per row
  std::vector<double> pull_;     // what pulls each row this step
  std::vector<double> force_;    // mu' - pull
};

}    // namespace hardcontact
