// `restitution e [I J]` and `bounce vmin`: Newton's restitution at velocity level
// (core/restitution.h) as an effect (effect.h). Present when restitution is given; `bounce`
// alone asks for nothing.
#pragma once

#include "effect.h"

namespace hardcontact {

class RestitutionEffect : public Effect {
 public:
  static std::vector<EffectKeyword> keywords();

  bool present() const override;    // some coefficient > 0
  // u^n, the approach speeds at the start of the step (ghosts from their owners)
  bool begin_step(EffectStep &step) override;
  void target_rows(EffectStep &step, int first) override;

 private:
  std::vector<double> table_;    // e per type pair, (ntypes + 1)^2
  double vmin_ = 0.0;            // approach speeds below it stay inelastic
  std::vector<Vec3> u_start_;    // u^n per body
  std::vector<double> row_e_;    // e per row
};

}    // namespace hardcontact
