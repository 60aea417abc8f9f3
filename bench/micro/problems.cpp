#include "problems.h"

#include "random_config.h"

#include <cmath>
#include <memory>
#include <random>
#include <stdexcept>

namespace micro {

namespace {

int n_spheres = 3000;

// The unit tests' packing (300 spheres in a box of 12, about 30 % of the volume) scaled to
// n spheres at the same density; masses within one decade, as the friction tests use.
hctest::RandomConfig packing(int n)
{
  hctest::RandomConfigOptions o;
  o.n = n;
  o.box = 12.0 * std::cbrt(n / 300.0);
  o.mass_decades = 1.0;
  hctest::RandomConfig c = hctest::random_config(2026u, o);
  // Squeezed towards the centre, so that most rows push, as in a jammed pile: the generator's
  // random velocities leave 16 % of the rows pushing, a solver's iteration then touches few of
  // them and its rate per row would flatter it. At this rate the squeeze alone closes every
  // candidate gap within the step (the candidates' skin is h 2 sqrt(3), centres are at least
  // 1 apart); 73 % of the rows push at the solution (3000 spheres).
  const double rate = 2.0 * std::sqrt(3.0);
  const Vec3 centre = Vec3::Constant(0.5 * o.box);
  for (int b = 0; b < c.p.n_bodies(); ++b) c.p.u_free[b] -= rate * (c.q[b] - centre);
  return c;
}

// Coefficients of the friction tests (tests/core/test_friction.cpp): friction 0.5, rolling 0.2.
constexpr double kFriction = 0.5;
constexpr double kRolling = 0.2;
// The warm start: apgd (every law has it) to the default tolerance, at most this many
// iterations (frictional rows of the squeezed packing stop short of it: the residual reached
// is printed in the run's context). A solver's cost per iteration hardly depends on it.
constexpr double kWarmTol = 1.0e-4;
constexpr int kWarmMaxIterations = 2000;

LawProblem make(ContactLaw law)
{
  static const hctest::RandomConfig base = packing(n_spheres);
  hctest::RandomConfig c = base;
  LawProblem out;
  if (law != ContactLaw::Normal) {
    std::mt19937 gen(7u);
    std::uniform_real_distribution<double> U(-1.0, 1.0);
    std::vector<Vec3> w(c.p.n_bodies());
    for (Vec3 &s : w) s = Vec3(U(gen), U(gen), U(gen));
    hctest::add_friction(c.p, c.r, kFriction, w);
    // each resistance the law holds, at kRolling (rolling 0, twisting 1)
    hardcontact::with_law(law, [&](auto rows_law) {
      for (int r = 0; r < hardcontact::kResistances; ++r)
        if (decltype(rows_law)::resistances & (1u << r))
          c.p.resistance[r].assign(c.p.n_contacts(), kRolling);
    });
  }
  out.p = std::move(c.p);
  std::unique_ptr<hardcontact::Solver> solver = hardcontact::make_solver("apgd", law);
  if (!solver) throw std::logic_error("micro: no apgd for the warm start");
  hardcontact::SolverSettings s;
  s.tol = kWarmTol;
  s.maxiter = kWarmMaxIterations;
  hardcontact::SerialOps ops;
  const hardcontact::SolveReport r = solver->solve(out.p, s, ops, out.warm, out.u);
  out.warm_residual = r.residual;
  out.warm_iterations = r.iterations;
  return out;
}

}    // namespace

void set_spheres(int n) { n_spheres = n; }
int spheres() { return n_spheres; }

const LawProblem &problem(ContactLaw law)
{
  static std::unique_ptr<LawProblem> built[hardcontact::kContactLaws];
  std::unique_ptr<LawProblem> &slot = built[static_cast<int>(law)];
  if (!slot) slot = std::make_unique<LawProblem>(make(law));
  return *slot;
}

const char *law_name(ContactLaw law)
{
  switch (law) {
    case ContactLaw::Normal: return "normal";
    case ContactLaw::Coulomb: return "coulomb";
    case ContactLaw::Rolling: return "rolling";
    case ContactLaw::Twisting: return "twisting";
    case ContactLaw::RollingTwisting: return "rolling_twisting";
  }
  return "?";
}

}    // namespace micro
