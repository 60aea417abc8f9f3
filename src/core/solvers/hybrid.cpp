#include "hybrid.h"

#include <algorithm>

namespace hardcontact {

template <class Law>
SolveReport HybridSolver<Law>::solve(const ContactProblem &p, const SolverSettings &s,
                                     DistributedOps &ops, std::vector<double> &mu,
                                     std::vector<Vec3> &u)
{
  int tried = 0;
  if (skip_ > 0) {
    --skip_;
  } else {
    // the lagged cone's caps are those of the warm start, not of the sweeps' iterate
    if (Law::block > 1 && s.cone == SolverSettings::Cone::Lagged) warm_ = mu;
    SolverSettings first = s;
    first.maxiter = std::min(kSweeps, s.maxiter);
    const SolveReport r = sweeps_.solve(p, first, ops, mu, u);
    if (r.converged) {
      backoff_ = 1;
      return r;
    }
    // every process takes the same decision: converged is a global verdict
    tried = r.iterations;
    skip_ = backoff_;
    backoff_ = std::min(2 * backoff_, kMaxBackoff);
  }
  if (tried > 0 && Law::block > 1 && s.cone == SolverSettings::Cone::Lagged)
    gradient_.lag_from(warm_);
  SolverSettings rest = s;
  rest.maxiter = std::max(1, s.maxiter - tried);
  SolveReport r = gradient_.solve(p, rest, ops, mu, u);
  r.iterations += tried;
  return r;
}

HARDCONTACT_INSTANTIATE_FOR_LAWS(HybridSolver)

}    // namespace hardcontact
