#include "cohesion.h"

#include "dual_operator.h"

namespace hardcontact {

bool apply_cohesion(ContactProblem &p, const std::vector<double> &cohesion, double touch,
                    DistributedOps &ops, std::vector<double> &pull)
{
  const int nc = p.n_contacts();
  pull.assign(nc, 0.0);
  DualOperator op;
  op.bind(p, ops);
  bool any = false;
  for (int c = 0; c < nc; ++c) {
    if (cohesion[c] <= 0.0 || p.gap[c] > touch * p.size[c]) continue;
    pull[c] = cohesion[c];
    op.apply(c, -cohesion[c], p.u_free);    // an impulse -h F G_c: the pair pulled together
    any = true;
  }
  op.forward(p.u_free);
  return any;
}

}    // namespace hardcontact
