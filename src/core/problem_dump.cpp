#include "problem_dump.h"

#include <cstdio>
#include <memory>

namespace hardcontact {

bool write_problem(const std::string &path, const ContactProblem &p,
                   const std::vector<double> &scales, const std::vector<double> &mu_start,
                   double tol)
{
  const std::unique_ptr<std::FILE, int (*)(std::FILE *)> file(std::fopen(path.c_str(), "w"),
                                                               &std::fclose);
  std::FILE *f = file.get();
  if (f == nullptr) return false;
  const int nb = p.n_bodies(), nc = p.n_contacts();
  std::fprintf(f, "hardcontact-problem 1 %d %d %d %.17g %.17g\n", nb, p.n_owned, nc, p.h, tol);
  for (int b = 0; b < nb; ++b) {
    const Vec3 &v = p.u_free[b];
    std::fprintf(f, "%.17g %.17g %.17g %.17g\n", p.inv_mass[b], v[0], v[1], v[2]);
  }
  for (int c = 0; c < nc; ++c) {
    const Vec3 &n = p.normal[c];
    std::fprintf(f, "%d %d %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", p.body_i[c], p.body_j[c],
                 n[0], n[1], n[2], p.target[c], p.size[c], scales[c], mu_start[c]);
  }
  return std::ferror(f) == 0;
}

}    // namespace hardcontact
