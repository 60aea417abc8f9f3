#include "pgs.h"

namespace hardcontact {

// One sweep over the working set (block_sweep.h), from the gaps of the last exchange in g_
// (the base's residual pass leaves them current).
template <class Law>
bool PgsSolver<Law>::step(const SolverSettings &, std::vector<double> &mu, std::vector<Vec3> &u)
{
  block_sweep<Law>(this->op_, this->set_.rows(), this->g_,
                   B > 1 ? this->shift_.data() : nullptr, dmu_, mu, u);
  return true;
}

HARDCONTACT_INSTANTIATE_FOR_LAWS(PgsSolver)

}    // namespace hardcontact
