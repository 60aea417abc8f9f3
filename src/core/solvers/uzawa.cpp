#include "uzawa.h"

namespace hardcontact {

// rho = 1/L: inside (0, 2/L) with margin, and the exact one-step answer for an isolated pair.
// The bound holds for the working set only: chosen again whenever the set grows (new rows
// start at mu = 0 and enter the update from the next pass).
template <class Law>
void UzawaSolver<Law>::rows_changed(const SolverSettings &s)
{
  if (s.rho > 0.0) {
    this->rho_ = s.rho;
    return;
  }
  const double bound = this->op_.template bound<Law>(this->set_.rows());
  this->rho_ = bound > 0.0 ? 1.0 / bound : 0.0;
}

// With C = -h G: mu_{k+1} = P(mu_k + rho (C u_k - D)) = P(mu_k - rho g(u_k)), then
// u_{k+1} = u(mu_{k+1}) by eq. 16. g(u_k) is in g_ (set_residual).
template <class Law>
bool UzawaSolver<Law>::step(const SolverSettings &, std::vector<double> &mu,
                            std::vector<Vec3> &u)
{
  for (const int c : this->set_.rows()) {
    double *m = &mu[static_cast<size_t>(B) * c];
    const double *g = &this->g_[static_cast<size_t>(B) * c];
    for (int k = 0; k < B; ++k) m[k] -= this->rho_ * g[k];
    Law::project(m, this->coef(c));
  }
  this->op_.template velocities<Law>(this->set_.rows(), mu, u);
  return true;
}

HARDCONTACT_INSTANTIATE_FOR_LAWS(UzawaSolver)

}    // namespace hardcontact
