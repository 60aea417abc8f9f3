// fix hardcontact: set-up, keywords, checks and output. The step itself (scheme (S), eq. 14-19)
// is in fix_hardcontact_step.cpp.
#include "fix_hardcontact.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "neighbor.h"
#include "update.h"
#include "utils.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {

std::string joined(const std::vector<std::string> &names)
{
  std::string s;
  for (const auto &n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

}    // namespace

FixHardContact::FixHardContact(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), solver_name_("apgd"), warm_(memory)
{
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR,
               "Fix hardcontact requires atom attributes radius and rmass: use atom_style sphere");
  if (!atom->tag_enable)
    error->all(FLERR, "Fix hardcontact requires atom IDs: remove 'atom_modify id no'");

  parse_keywords(narg, arg);
  solver_ = hardcontact::make_solver(solver_name_);

  time_integrate = 1;
  force_reneighbor = 1;    // rebuilds are forced before a step could outrun the skin
  next_reneighbor = -1;

  vector_flag = 1;
  size_vector = NVECTOR;
  global_freq = 1;
  extvector = 0;    // already reduced over processes

  peratom_flag = 1;
  size_peratom_cols = 4;
  peratom_freq = 1;

  local_flag = 1;
  size_local_rows = 0;
  size_local_cols = 7;
  local_freq = 1;

  comm_forward = 3;
  ops_.attach(this, comm, world);

  // per-atom data (outputs, warm-start multipliers) travels with atoms and restart files
  restart_peratom = 1;
  maxexchange_dynamic = 1;
  create_attribute = 1;    // atoms created during the run (fix pour) start with no history
  array_atom = nullptr;
  array_local = nullptr;
  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; ++i)
    for (int k = 0; k < 4; ++k) array_atom[i][k] = 0.0;
}

FixHardContact::~FixHardContact()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(array_atom);
  memory->destroy(array_local);
}

int FixHardContact::setmask()
{
  return INITIAL_INTEGRATE | POST_NEIGHBOR;
}

// Every keyword is read here and only here; each error names the keyword and what to write.
void FixHardContact::parse_keywords(int narg, char **arg)
{
  auto number = [&](const char *keyword, const char *word) {
    if (!utils::is_double(word))
      error->all(FLERR, "Fix hardcontact {}: expected a number, got '{}'", keyword, word);
    // Checked before utils::numeric: modern LAMMPS stops there on 1e999 with a message that
    // does not name the keyword.
    if (!std::isfinite(std::strtod(word, nullptr)))
      error->all(FLERR, "Fix hardcontact {}: value '{}' is not a finite number", keyword, word);
    return utils::numeric(FLERR, word, false, lmp);
  };

  int iarg = 3;
  while (iarg < narg) {
    const std::string keyword = arg[iarg];
    auto need = [&](int n) {
      if (iarg + n >= narg)
        error->all(FLERR, "Fix hardcontact {} needs {} value(s) after it", keyword, n);
    };
    if (keyword == "solver") {
      need(1);
      solver_name_ = arg[iarg + 1];
      if (!hardcontact::make_solver(solver_name_))
        error->all(FLERR, "Fix hardcontact solver '{}' is unknown: use one of {}", solver_name_,
                   joined(hardcontact::solver_names()));
      iarg += 2;
    } else if (keyword == "tol") {
      need(1);
      settings_.tol = number("tol", arg[iarg + 1]);
      if (settings_.tol <= 0.0 || settings_.tol >= 1.0)
        error->all(FLERR, "Fix hardcontact tol must be in (0, 1) (an overlap relative to the "
                          "contact size), got {}", arg[iarg + 1]);
      iarg += 2;
    } else if (keyword == "maxiter") {
      need(1);
      if (!utils::is_integer(arg[iarg + 1]))
        error->all(FLERR, "Fix hardcontact maxiter: expected an integer, got '{}'", arg[iarg + 1]);
      const bigint maxiter = utils::bnumeric(FLERR, arg[iarg + 1], false, lmp);
      if (maxiter < 1 || maxiter > MAXSMALLINT)
        error->all(FLERR, "Fix hardcontact maxiter must be at least 1 and at most {}, got {}",
                   MAXSMALLINT, arg[iarg + 1]);
      settings_.maxiter = static_cast<int>(maxiter);
      iarg += 2;
    } else if (keyword == "rho") {
      need(1);
      settings_.rho = number("rho", arg[iarg + 1]);
      if (settings_.rho <= 0.0)
        error->all(FLERR, "Fix hardcontact rho must be positive (omit it for the automatic "
                          "step), got {}", arg[iarg + 1]);
      iarg += 2;
    } else if (keyword == "warmstart") {
      need(1);
      const std::string value = arg[iarg + 1];
      if (value != "yes" && value != "no")
        error->all(FLERR, "Fix hardcontact warmstart must be yes or no, got '{}'", value);
      warmstart_ = value == "yes";
      iarg += 2;
    } else if (keyword == "wall") {
      need(3);
      const std::string plane = arg[iarg + 1];
      int dim = -1;
      if (plane == "xplane") dim = 0;
      else if (plane == "yplane") dim = 1;
      else if (plane == "zplane") dim = 2;
      else
        error->all(FLERR, "Fix hardcontact wall '{}' is unknown: use xplane, yplane or zplane",
                   plane);
      if (dim == 2 && domain->dimension == 2)
        error->all(FLERR, "Fix hardcontact wall zplane is not allowed in a 2d simulation");
      const bool has_lo = strcmp(arg[iarg + 2], "NULL") != 0;
      const bool has_hi = strcmp(arg[iarg + 3], "NULL") != 0;
      if (!has_lo && !has_hi)
        error->all(FLERR, "Fix hardcontact wall {}: lo and hi cannot both be NULL", plane);
      double lo = 0.0, hi = 0.0;
      if (has_lo) lo = number("wall lo", arg[iarg + 2]);
      if (has_hi) hi = number("wall hi", arg[iarg + 3]);
      if (has_lo && has_hi && lo >= hi)
        error->all(FLERR, "Fix hardcontact wall {}: lo ({}) must be below hi ({})", plane, lo, hi);
      if (has_lo) walls_.push_back({dim, true, lo});
      if (has_hi) walls_.push_back({dim, false, hi});
      iarg += 4;
    } else {
      error->all(FLERR, "Fix hardcontact keyword '{}' is unknown: use solver, tol, maxiter, rho, "
                        "warmstart or wall", keyword);
    }
  }
  check_walls_in_box();
}

void FixHardContact::check_walls_in_box()
{
  static const char *names[3] = {"xplane", "yplane", "zplane"};
  for (const auto &w : walls_) {
    if (domain->periodicity[w.dim])
      error->all(FLERR, "Fix hardcontact wall {} needs a non-periodic boundary in that "
                        "direction: change the boundary command", names[w.dim]);
    // A shrink-wrapped box follows the atoms: only fixed boundaries bound the wall.
    const bool fixed_lo = domain->boundary[w.dim][0] == 1, fixed_hi = domain->boundary[w.dim][1] == 1;
    if ((fixed_lo && w.coord < domain->boxlo[w.dim]) || (fixed_hi && w.coord > domain->boxhi[w.dim]))
      error->all(FLERR, "Fix hardcontact wall {} at {} lies outside the box ({} to {}): move "
                        "it inside", names[w.dim], w.coord, domain->boxlo[w.dim],
                 domain->boxhi[w.dim]);
  }
}

void FixHardContact::init()
{
  if (domain->triclinic)
    error->all(FLERR, "Fix hardcontact does not support triclinic boxes: use an orthogonal box");
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "Fix hardcontact does not support run_style respa: use verlet");
  check_walls_in_box();
  if (!solver_->traits().distributed && comm->nprocs > 1)
    error->all(FLERR, "Fix hardcontact solver {} runs on one processor only (it assembles "
                      "the whole contact operator): use apgd, pgs or uzawa with mpirun",
               solver_name_);

  // Contacts reach r_i + r_j <= 2 r_max; the list must hold every pair that close plus the
  // skin, and ghosts must reach as far (DESIGN.md: with pair_style none LAMMPS sets neither).
  double rmax_local = 0.0;
  for (int i = 0; i < atom->nlocal; ++i) rmax_local = MAX(rmax_local, atom->radius[i]);
  MPI_Allreduce(&rmax_local, &rmax_, 1, MPI_DOUBLE, MPI_MAX, world);
  // A ghost cutoff set by the user (comm_modify cutoff) makes room for larger spheres that
  // appear later (fix pour into an empty box).
  if (user_cutghost_ < 0.0) user_cutghost_ = comm->cutghostuser;
  rmax_ = MAX(rmax_, 0.5 * (user_cutghost_ - neighbor->skin));
  cutoff_ = 2.0 * rmax_ + neighbor->skin;
  comm->cutghostuser =
      MAX(user_cutghost_, hardcontact::compat::ghost_cutoff_for_request(cutoff_, neighbor->skin));
  if (force->pair == nullptr && (!neighbor->binsizeflag || binsize_set_here_)) {
    // Without a pair style LAMMPS bins with the whole box (master cutoff 0): O(N^2) lists,
    // and it stops sorting atoms (memory locality). Bin as a pair style of this reach would.
    neighbor->binsizeflag = 1;
    neighbor->binsize_user = 0.5 * cutoff_;
    binsize_set_here_ = true;
  }
  if (force->pair == nullptr && (atom->userbinsize == 0.0 || sortbin_set_here_)) {
    atom->userbinsize = 0.5 * cutoff_;
    sortbin_set_here_ = true;
  }
  hardcontact::compat::request_size_list(neighbor, this, instance_me, cutoff_);
}

void FixHardContact::init_list(int, NeighList *ptr)
{
  list_ = ptr;
}

void FixHardContact::setup_post_neighbor()
{
  post_neighbor();
}

void FixHardContact::post_neighbor()
{
  double rmax_local = 0.0;
  for (int i = 0; i < atom->nlocal; ++i) rmax_local = MAX(rmax_local, atom->radius[i]);
  double rmax_now;
  MPI_Allreduce(&rmax_local, &rmax_now, 1, MPI_DOUBLE, MPI_MAX, world);
  if (rmax_now > rmax_) radius_grew(rmax_now);
  store_xhold();
}

void FixHardContact::radius_grew(double rmax_now)
{
  error->all(FLERR, "Fix hardcontact: a sphere of radius {} appeared during the run, larger than "
                    "the {} the neighbor list and ghosts were sized for; its contacts could be "
                    "missed: use 'comm_modify cutoff {:.6g}' (room for radius {:.6g} with this "
                    "skin) before the run", rmax_now, rmax_,
             2.0 * rmax_now + neighbor->skin, rmax_now);
}

void FixHardContact::store_xhold()
{
  const int nlocal = atom->nlocal;
  xhold_.resize(nlocal);
  for (int i = 0; i < nlocal; ++i) xhold_[i] = hardcontact::Vec3(atom->x[i]);
}

// Step 0: no solve yet, but the diagnostics describe the positions the run starts from.
void FixHardContact::setup(int)
{
  check_atoms();
  build_bodies();
  build_candidates(0.0);
  overlap_diagnostics(0.0);
  diag_[ITERATIONS] = diag_[CANDIDATES] = diag_[ACTIVE] = diag_[RESIDUAL] = 0.0;
  diag_[RHO] = diag_[ROUNDS] = diag_[CLEARING_WORK] = 0.0;
  diag_[MAXITER_HITS] = static_cast<double>(maxiter_hits_);
  if (diag_[MAX_OVERLAP_RELATIVE] > settings_.tol && comm->me == 0)
    error->warning(FLERR, "Fix hardcontact: the run starts with overlapping spheres (largest "
                          "overlap {:.6g}, {:.3g} of the contact size); each step clears at most "
                          "h x the velocity the forces give in one step, plus 2 tol x its row scale, so "
                          "that no energy explodes (see the doc page)",
                   diag_[MAX_OVERLAP], diag_[MAX_OVERLAP_RELATIVE]);
  mu_.clear();
  problem_.clear_contacts();
  size_local_rows = 0;
  for (int i = 0; i < atom->nlocal; ++i)
    for (int k = 0; k < 4; ++k) array_atom[i][k] = 0.0;
}

// Radius and mass must be usable, and no value may be NaN or infinite: a NaN would spread to
// every body through the solve. One collective error names the first bad atom.
void FixHardContact::check_atoms()
{
  double **x = atom->x, **v = atom->v;
  double *radius = atom->radius, *rmass = atom->rmass;
  int *mask = atom->mask;
  tagint bad[3] = {0, 0, 0};    // non-finite, non-positive radius/mass, behind a wall
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(mask[i] & groupbit)) continue;
    bool finite = std::isfinite(radius[i]) && std::isfinite(rmass[i]);
    for (int k = 0; k < 3; ++k) finite = finite && std::isfinite(x[i][k]) && std::isfinite(v[i][k]);
    if (!finite && !bad[0]) bad[0] = atom->tag[i];
    if ((radius[i] <= 0.0 || rmass[i] <= 0.0) && !bad[1]) bad[1] = atom->tag[i];
    for (const auto &w : walls_)
      if (w.gap(x[i], radius[i]) < -radius[i] && !bad[2]) bad[2] = atom->tag[i];
  }
  tagint all[3];
  MPI_Allreduce(bad, all, 3, MPI_LMP_TAGINT, MPI_MAX, world);
  if (all[0])
    error->all(FLERR, "Fix hardcontact: atom {} has a non-finite position, velocity, radius or "
                      "mass: fix the data file or the commands that set it", all[0]);
  if (all[1])
    error->all(FLERR, "Fix hardcontact: atom {} has radius or mass <= 0: every atom of the "
                      "group needs a positive diameter and density (set diameter / set density)",
               all[1]);
  if (all[2])
    error->all(FLERR, "Fix hardcontact: the centre of atom {} is behind a wall: move the wall "
                      "or the atom", all[2]);
}

/* ---------------------------------------------------------------------- output */

double FixHardContact::compute_vector(int n)
{
  return diag_[n];
}

double FixHardContact::memory_usage()
{
  double bytes = 4.0 * sizeof(double) * atom->nmax;
  bytes += 7.0 * sizeof(double) * nlocal_rows_max_;
  bytes += (sizeof(int) * 2 + sizeof(double) * 6) * problem_.body_i.capacity();
  bytes += sizeof(double) * 7 * problem_.inv_mass.capacity();
  return bytes;
}

// Per-atom output follows its atom when atoms migrate or are sorted (it is computed in
// initial_integrate, before the exchange of the same step).
void FixHardContact::grow_arrays(int nmax)
{
  memory->grow(array_atom, nmax, 4, "hardcontact:array_atom");
  warm_.grow(nmax);
  nmax_ = nmax;
  maxexchange = 4 + warm_.max_packed_size();
}

void FixHardContact::copy_arrays(int i, int j, int)
{
  for (int k = 0; k < 4; ++k) array_atom[j][k] = array_atom[i][k];
  warm_.copy(i, j);
}

void FixHardContact::set_arrays(int i)
{
  for (int k = 0; k < 4; ++k) array_atom[i][k] = 0.0;
  warm_.clear(i);
}

int FixHardContact::pack_exchange(int i, double *buf)
{
  for (int k = 0; k < 4; ++k) buf[k] = array_atom[i][k];
  return 4 + warm_.pack(i, buf + 4);
}

int FixHardContact::unpack_exchange(int nlocal, double *buf)
{
  for (int k = 0; k < 4; ++k) array_atom[nlocal][k] = buf[k];
  return 4 + warm_.unpack(nlocal, buf + 4);
}

// Restart files hold the warm-start multipliers, so a split run starts its next solve where
// the unsplit one would.
int FixHardContact::pack_restart(int i, double *buf)
{
  buf[0] = 1 + warm_.packed_size(i);    // LAMMPS convention: own size first
  return 1 + warm_.pack(i, buf + 1);
}

void FixHardContact::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; ++k) m += static_cast<int>(extra[nlocal][m]);
  warm_.unpack(nlocal, &extra[nlocal][m + 1]);
}

int FixHardContact::size_restart(int nlocal)
{
  return 1 + warm_.packed_size(nlocal);
}

int FixHardContact::maxsize_restart()
{
  return 1 + warm_.max_packed_size();
}

int FixHardContact::pack_forward_comm(int n, int *list, double *buf, int, int *)
{
  const double *data = ops_.data();
  const int per = ops_.per_body();
  int m = 0;
  for (int a = 0; a < n; ++a)
    for (int k = 0; k < per; ++k) buf[m++] = data[per * list[a] + k];
  return m;
}

void FixHardContact::unpack_forward_comm(int n, int first, double *buf)
{
  double *data = ops_.data();
  const int per = ops_.per_body();
  int m = 0;
  for (int a = first; a < first + n; ++a)
    for (int k = 0; k < per; ++k) data[per * a + k] = buf[m++];
}
