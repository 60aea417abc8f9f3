#include "uzawa.h"

namespace hardcontact {

// rho = 1/L: inside (0, 2/L) with margin, and the exact one-step answer for an isolated pair.
// The bound holds for the working set only: chosen again whenever the set grows.
template <class Law>
double UzawaSolver<Law>::choose_rho(const SolverSettings &s)
{
  if (s.rho > 0.0) return s.rho;
  const double bound = this->op_.bound(this->set_.rows());
  return bound > 0.0 ? 1.0 / bound : 0.0;
}

template <class Law>
void UzawaSolver<Law>::start(const SolverSettings &s, std::vector<double> &mu,
                             std::vector<Vec3> &u)
{
  this->rho_ = choose_rho(s);
  this->op_.velocities(this->set_.rows(), mu, u);
}

// With C = -h G: mu_{k+1} = P(mu_k + rho (C u_k - D)) = P(mu_k - rho g(u_k)), then
// u_{k+1} = u(mu_{k+1}) by eq. 16. g(u_k) is in g_ (set_residual).
template <class Law>
bool UzawaSolver<Law>::step(const SolverSettings &, std::vector<double> &mu,
                            std::vector<Vec3> &u)
{
  for (const int c : this->set_.rows()) mu[c] = Law::project(mu[c] - this->rho_ * this->g_[c]);
  this->op_.velocities(this->set_.rows(), mu, u);
  return true;
}

// New rows start at mu = 0 and enter the update from the next pass, with a new step.
template <class Law>
void UzawaSolver<Law>::grown(const SolverSettings &s, std::vector<double> &, std::vector<Vec3> &)
{
  this->rho_ = choose_rho(s);
}

template class UzawaSolver<NormalLaw>;

}    // namespace hardcontact
