// The table of effects (effect.h): adding an effect is adding a line here and its class's files.
#include "effect.h"

#include "cohesion_effect.h"
#include "restitution_effect.h"

namespace hardcontact {

const std::vector<EffectKind> &effect_kinds()
{
  static const std::vector<EffectKind> kinds = {
      {"restitution", &make_effect<RestitutionEffect>, RestitutionEffect::keywords()},
      {"cohesion", &make_effect<CohesionEffect>, CohesionEffect::keywords()},
  };
  return kinds;
}

}    // namespace hardcontact
