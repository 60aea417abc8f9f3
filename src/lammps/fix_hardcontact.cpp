// fix hardcontact: the LAMMPS callbacks, each forwarding to the part that does the work
// (doc/architecture.md): keywords.*, neighbor_reach.*, step.* (scheme (S), eq. 14-18),
// integrate.* (eq. 19 and the skin), outputs.*, contact_history.*.
#include "fix_hardcontact.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "memory.h"
#include "update.h"
#include "utils.h"

#include "../core/laws/coulomb.h"
#include "../core/laws/normal.h"
#include "../core/laws/rolling.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {

// The atom style checks come before the keywords, so a deck with both faults names the first.
hardcontact::FixOptions checked_options(LAMMPS *lmp, int narg, char **arg)
{
  if (!lmp->atom->radius_flag || !lmp->atom->rmass_flag)
    lmp->error->all(
        FLERR, "Fix hardcontact requires atom attributes radius and rmass: use atom_style sphere");
  if (!lmp->atom->tag_enable)
    lmp->error->all(FLERR, "Fix hardcontact requires atom IDs: remove 'atom_modify id no'");
  hardcontact::FixOptions o = hardcontact::parse_keywords(lmp, narg, arg, 3);
  for (int r = 0; r < hardcontact::kResistancesListed; ++r)
    if (o.has_resistance(r) && !hardcontact::FixOptions::any_positive(o.friction))
      hardcontact::compat::error_all(lmp->error, FLERR,
                                     "Fix hardcontact {} needs friction: add 'friction mu' (a "
                                     "contact that can slide resists no rolling or twisting)",
                                     hardcontact::kResistanceKeywords[r]);
  hardcontact::ContactLaw law;
  if (!hardcontact::law_composing(o.has_friction(), o.resistances(), law))
    lmp->error->all(FLERR, "Fix hardcontact: no contact law composes these resistances "
                           "(core/laws/law_list.h): drop one of them");
  // The default solver: projected CG where the law is a bound (frictionless: doc/performance.md,
  // cg takes 0.5-0.7 x apgd's time on 3D piles); with friction nsgs sweeps and apgd where they
  // stall (solvers/hybrid.h: a packing at rest with mobilised friction takes a handful of
  // sweeps where apgd took hundreds of iterations)
  if (o.solver_name.empty()) o.solver_name = o.has_friction() ? "hybrid" : "cg";
  // The default tolerance with friction (keywords.h): frictional solves converge slowly in a
  // rearranging packing (its contact forces are indeterminate), and the scenes' observables
  // (a pile's height, a heap's and a drum's angle) are the same at 1e-2 as at 1e-4
  if (!o.tol_given && o.has_friction()) o.settings.tol = hardcontact::FixOptions::kFrictionTol;
  // The default speeds with friction (keywords.h): the slip conditions against the slides
  if (!o.speed_given && o.has_friction()) o.settings.contact_speed = true;
  if (o.has_friction()) {
    if (!lmp->atom->omega_flag || !lmp->atom->torque_flag)
      lmp->error->all(FLERR, "Fix hardcontact friction requires atom attributes omega and "
                             "torque (the spheres spin): use atom_style sphere");
    if (!hardcontact::solver_has_friction(o.solver_name))
      hardcontact::compat::error_all(lmp->error, FLERR,
                                     "Fix hardcontact solver {} has no friction: use hybrid (the "
                                     "default with friction), apgd, nsgs, pgs or uzawa",
                                     o.solver_name);
  }
  if (o.cone_given && !o.has_friction())
    lmp->error->all(FLERR, "Fix hardcontact cone applies with friction only (it is the "
                           "Coulomb cone's treatment): remove cone or add friction");
  if (o.settings.contact_speed && !o.has_friction())
    lmp->error->all(FLERR, "Fix hardcontact speed contact applies with friction only (without "
                           "it the law constrains the approach alone): remove speed or add "
                           "friction");
  if (o.settings.subspace > 0 && o.has_friction())
    lmp->error->all(FLERR, "Fix hardcontact subspace applies without friction only (with "
                           "friction its start leaves the cone): remove subspace or friction");
  if (o.settings.subspace > 0 && o.solver_name != "cg" && o.solver_name != "apgd")
    hardcontact::compat::error_all(lmp->error, FLERR,
                                   "Fix hardcontact subspace applies to solvers cg and apgd (the "
                                   "defaults), not {}: remove subspace or use cg or apgd",
                                   o.solver_name);
  // The default start of cg without friction: the span of the last 10 corrections. Loads and
  // shallow piles at rest take 8-20 x fewer iterations per step, deep piles and settles 3-6 %
  // fewer, for one product per step and 160 bytes per contact (bench/studies/subspace_default 10.7).
  if (!o.subspace_given && o.solver_name == "cg" && !o.has_friction())
    o.settings.subspace = hardcontact::FixOptions::kDefaultSubspace;
  return o;
}

std::vector<hardcontact::MeshWallSource::Spec> mesh_specs(const hardcontact::FixOptions &o)
{
  std::vector<hardcontact::MeshWallSource::Spec> specs;
  for (const auto &m : o.wall_meshes) {
    hardcontact::MeshWallSource::Spec spec;
    spec.fix_id = m.fix_id;
    spec.file = m.file;
    spec.scale = m.scale;
    for (int d = 0; d < 3; ++d) spec.move[d] = m.move[d];
    spec.theta = m.theta;
    spec.point = hardcontact::Vec3(m.point[0], m.point[1], m.point[2]);
    spec.axis = hardcontact::Vec3(m.axis[0], m.axis[1], m.axis[2]);
    spec.friction = o.mesh_friction[specs.size()];
    specs.push_back(spec);
  }
  return specs;
}

}    // namespace

FixHardContact::FixHardContact(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), options_(checked_options(lmp, narg, arg)),
    law_(options_.contact_law()), solver_(hardcontact::make_solver(options_.solver_name, law_)),
    reach_(lmp), pairs_(lmp, groupbit),
    walls_(lmp, groupbit, std::move(options_.walls), std::move(options_.wall_variables),
           options_.plane_friction),
    meshes_(lmp, groupbit, mesh_specs(options_)),
    history_(memory, law_),
    step_(lmp, groupbit, ops_, reach_, {&pairs_}),
    integrate_(lmp, groupbit),
    outputs_(lmp, this, options_.has_friction()), virial_(lmp)
{
  // the wall sources, in the order of their wall codes: planes, each kind of the kinds' table
  // (sources/wall_kinds.cpp) with its walls in the order of the fix line, meshes
  add_wall_source(&walls_);
  for (const hardcontact::WallKind &kind : hardcontact::wall_kinds()) {
    std::vector<hardcontact::WallSpec> specs;
    for (const auto &w : options_.kind_walls)
      if (w.kind == &kind) specs.push_back(w.spec);
    if (specs.empty()) continue;
    kind_sources_.push_back(kind.create(lmp, groupbit, specs));
    add_wall_source(kind_sources_.back().get());
  }
  add_wall_source(&meshes_);
  walls_.check_in_box();
  integrate_.set_inertia(options_.disc ? 0.5 : 0.4);
  // the law's coefficients, and the effects the keywords asked for (effects/effect.h)
  hardcontact::StepLaw law;
  law.law = law_;
  if (options_.has_friction()) {
    law.friction = &options_.friction;
    law.wall_friction = &wall_friction_;
    for (int r = 0; r < hardcontact::kResistances; ++r)
      if (options_.has_resistance(r)) law.resistance[r] = &options_.resistance[r];
    law.inertia = options_.disc ? 0.5 : 0.4;
  }
  step_.set_law(law);
  for (const auto &part : options_.effects) step_.add_effect(part.effect.get());

  time_integrate = 1;
  // the contact forces in pressure and stress, as LAMMPS's constraint fixes do (fix_modify
  // virial no turns it off)
  hardcontact::compat::offer_virial(this);
  for (double &v : virial) v = 0.0;
  force_reneighbor = 1;    // rebuilds are forced before a step could outrun the skin
  next_reneighbor = -1;

  vector_flag = 1;
  size_vector = hardcontact::Outputs::NVECTOR;
  global_freq = 1;
  extvector = 0;    // already reduced over processes

  peratom_flag = 1;
  size_peratom_cols = outputs_.per_atom_columns();
  peratom_freq = 1;

  local_flag = 1;
  size_local_rows = 0;
  size_local_cols = outputs_.local_columns();
  local_freq = 1;

  comm_forward = hardcontact::LammpsOps::kMaxPerBody;
  ops_.attach(this, comm, error, world);

  // per-atom data (outputs, contact history) travels with atoms and restart files, and the
  // kept overlaps' back-off and budget (core/kept_overlaps.h) with the fix's global state
  restart_peratom = 1;
  restart_global = 1;
  create_attribute = 1;    // atoms created during the run (fix pour) start with no history
  array_atom = nullptr;
  array_local = nullptr;
  grow_arrays(atom->nmax);
  atom->add_callback(hardcontact::compat::kAtomGrowCallback);
  atom->add_callback(hardcontact::compat::kAtomRestartCallback);
  for (int i = 0; i < atom->nlocal; ++i) outputs_.clear_per_atom(i);

  report_comm_ = std::getenv("HARDCONTACT_COMM_TIMES") != nullptr;
  if (const char *prefix = std::getenv("HARDCONTACT_DUMP_PROBLEMS")) {
    dump_prefix_ = prefix;
    if (!dump_prefix_.empty() && comm->me == 0)
      hardcontact::compat::warning(error, FLERR,
                                   "Fix hardcontact writes every step's problem to {}.<step> "
                                   "(HARDCONTACT_DUMP_PROBLEMS is set; frictionless solves only)",
                                   dump_prefix_);
  }
}

FixHardContact::~FixHardContact()
{
  atom->delete_callback(id, hardcontact::compat::kAtomGrowCallback);
  atom->delete_callback(id, hardcontact::compat::kAtomRestartCallback);
}

int FixHardContact::setmask()
{
  // POST_FORCE: the per-atom virial into vatom after the step's sorting and migration
  return INITIAL_INTEGRATE | POST_NEIGHBOR | POST_FORCE;
}

void FixHardContact::init()
{
  if (domain->triclinic)
    error->all(FLERR, "Fix hardcontact does not support triclinic boxes: use an orthogonal box");
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, "Fix hardcontact does not support run_style respa: use verlet");
  reach_.init(this, HARDCONTACT_FIX_INSTANCE);
  // each wall source's init, then the wall codes in the list's order and each wall's own
  // friction (sources/obstacles.h); a mesh's rows reach r_max + skin: half the list's
  // 2 r_max + skin, and a little more
  if (!obstacles_.init({0.5 * reach_.cutoff(), modify->find_fix(id), id}, wall_friction_))
    error->all(FLERR, "Fix hardcontact: the walls are too many to number (the meshes' "
                      "vertices, edges and triangles count one each): split or coarsen them");
  if (!solver_->traits().distributed && comm->nprocs > 1)
    hardcontact::compat::error_all(
        error, FLERR,
        "Fix hardcontact solver {} runs on one processor only (it assembles "
        "the whole contact operator): use apgd, pgs or uzawa with mpirun",
        options_.solver_name);
  for (const auto &part : options_.effects) part.effect->init(lmp);
  deck_checks_.check(lmp, *this, options_.has_effect("restitution"));
}

void FixHardContact::add_wall_source(hardcontact::WallSource *source)
{
  obstacles_.add(source);
  step_.add_source(source);
}

void FixHardContact::init_list(int, NeighList *ptr)
{
  pairs_.set_list(ptr);
}

void FixHardContact::setup_post_neighbor()
{
  post_neighbor();
}

void FixHardContact::post_neighbor()
{
  reach_.check_all_radii();
  integrate_.store_build_positions();
}

// Step 0: no solve yet, but the diagnostics describe the positions the run starts from. The
// virial is the last step's (zero before the first run's first step).
void FixHardContact::setup(int vflag)
{
  start_virial(vflag);
  if (vflag_global) std::memcpy(virial, virial_.last_global(), sizeof(virial));
  post_force(vflag);
  ops_.take_times();    // HARDCONTACT_COMM_TIMES counts from here
  obstacles_.at_current_step();    // moving walls where they stand at this step
  step_.check_bodies(walls_.walls());
  obstacles_.check_sides();
  step_.find_overlaps(*solver_);
  outputs_.start_of_run(step_.problem(), obstacles_, options_.settings.tol);
  step_.clear();
}

// One step of scheme (S) (step.h), then its outputs at q^n, then q^{n+1} = q^n + h u^{n+1}.
void FixHardContact::initial_integrate(int vflag)
{
  start_virial(vflag);
  obstacles_.advance(update->dt);    // moving walls to t^{n+1}, with their velocities
  const bool moving = obstacles_.moving();
  const hardcontact::StepResult result =
      dump_prefix_.empty() ? step_.solve(*solver_, options_.settings,
                                         options_.warmstart ? &history_ : nullptr, moving)
                           : solve_and_dump(moving);
  obstacles_.commit(update->dt);    // the outputs measure q^{n+1} against the walls at t^{n+1}
  if (options_.warmstart) history_resized();
  outputs_.record_step(result, step_.problem(), step_.mu(), law_, step_.u(),
                       obstacles_, options_.settings, ops_);
  if (vflag_global || vflag_atom) {
    virial_.tally(step_.problem(), step_.mu(), step_.block(), step_.u(), update->dt, obstacles_,
                  vflag_global ? virial : nullptr, vflag_atom != 0);
    if (vflag_atom) history_resized();    // the first per-atom tally adds its values
  }
  const int spins = step_.block() > 1 ? step_.problem().n_bodies() : -1;
  if (integrate_.move(step_.u(), spins)) next_reneighbor = update->ntimestep;
}

void FixHardContact::start_virial(int vflag)
{
  if (vflag && hardcontact::compat::virial_on(this)) {
    v_setup(vflag);
  } else {
    evflag = 0;
    vflag_global = vflag_atom = 0;
  }
}

// The per-atom virial of the step's contacts (computed in initial_integrate, kept per atom
// through the sorting and migration since) where compute stress/atom reads it.
void FixHardContact::post_force(int)
{
  if (!vflag_atom) return;
  if (atom->nmax > maxvatom) {
    maxvatom = atom->nmax;
    memory->destroy(vatom);
    memory->create(vatom, maxvatom, hardcontact::ContactVirial::kComponents, "hardcontact:vatom");
  }
  virial_.copy_per_atom(vatom);
}

// The step with the developers' dump of its problem (core/problem_dump.h): prefix.<step>, and
// .<rank> after it when several processes run (each writes its own rows and bodies).
hardcontact::StepResult FixHardContact::solve_and_dump(bool moving_obstacles)
{
  hardcontact::SolverSettings settings = options_.settings;
  settings.dump_problem = dump_prefix_ + "." + std::to_string(update->ntimestep);
  if (comm->nprocs > 1) settings.dump_problem += "." + std::to_string(comm->me);
  const hardcontact::StepResult result =
      step_.solve(*solver_, settings, options_.warmstart ? &history_ : nullptr,
                  moving_obstacles);
  if (result.report.dump_failed)
    hardcontact::compat::error_one(lmp->error, FLERR,
                                   "Fix hardcontact cannot write {} (HARDCONTACT_DUMP_PROBLEMS): "
                                   "set it to a prefix in a writable directory, or unset it",
                                   settings.dump_problem);
  return result;
}

void FixHardContact::post_run()
{
  outputs_.end_of_run(options_.settings);
  if (report_comm_) report_comm_times();
}

// What the solver's synchronisation points cost in this run (bench/perf's report, section 5):
// per process, the forward communications (ghost velocities) and reductions, their calls and
// seconds, including the wait for the slowest process; the mean and the largest over the
// processes. A developers' switch (HARDCONTACT_COMM_TIMES), read by bench/perf.
void FixHardContact::report_comm_times()
{
  const hardcontact::LammpsOps::Times t = ops_.take_times();
  // sums, then maxima, in one reduction (counted in the next run's times, which setup resets)
  double v[4] = {t.forward_s, t.reduce_s, t.forward_s, t.reduce_s};
  ops_.sum_max_all(v, 2, 2);
  const double sum[2] = {v[0], v[1]}, most[2] = {v[2], v[3]};
  if (comm->me != 0) return;
  char line[320];
  std::snprintf(line, sizeof line,
                "Fix hardcontact communication in this run, per process: %ld forwards %.4g s "
                "(mean, max %.4g s), %ld reductions %.4g s (mean, max %.4g s), %d processes\n",
                t.forwards, sum[0] / comm->nprocs, most[0], t.reductions, sum[1] / comm->nprocs,
                most[1], comm->nprocs);
  if (screen) std::fputs(line, screen);
  if (logfile) std::fputs(line, logfile);
}

// fix_modify ID contacts pairs|walls|all: which active contacts the local array lists (all by
// default). Output only: the solve and every other output are the same.
int FixHardContact::modify_param(int narg, char **arg)
{
  if (std::strcmp(arg[0], "contacts") != 0) return 0;
  using Rows = hardcontact::Outputs::LocalRows;
  const char *value = narg > 1 ? arg[1] : "";
  if (std::strcmp(value, "pairs") == 0) outputs_.set_local_rows(Rows::PAIRS);
  else if (std::strcmp(value, "walls") == 0) outputs_.set_local_rows(Rows::WALLS);
  else if (std::strcmp(value, "all") == 0) outputs_.set_local_rows(Rows::ALL);
  else
    hardcontact::compat::error_all(error, FLERR,
                                   "Illegal fix_modify command: fix hardcontact contacts takes "
                                   "pairs, walls or all (which active contacts the local array "
                                   "lists), not '{}'",
                                   value);
  return 2;
}

double FixHardContact::compute_vector(int n)
{
  return outputs_.vector(n);
}

double FixHardContact::memory_usage()
{
  return outputs_.memory_usage() + step_.memory_usage() + solver_->memory_usage() +
         history_.memory_usage() + virial_.memory_usage();
}

/* ---------------------------------------------------------------------- per-atom data */

// What an atom carries when it migrates: its outputs, its per-atom virial once one was asked
// for, then its contact history.
void FixHardContact::history_resized()
{
  hardcontact::compat::set_exchange_size(this, comm,
                                         outputs_.per_atom_columns() + virial_.exchange_values() +
                                             history_.max_packed_size());
}

void FixHardContact::grow_arrays(int nmax)
{
  outputs_.grow_per_atom(nmax);
  virial_.grow(nmax);
  history_.grow(nmax);
  history_resized();
}

void FixHardContact::copy_arrays(int i, int j, int)
{
  const int n = outputs_.per_atom_columns();
  for (int k = 0; k < n; ++k) array_atom[j][k] = array_atom[i][k];
  virial_.copy(i, j);
  history_.copy(i, j);
}

void FixHardContact::set_arrays(int i)
{
  outputs_.clear_per_atom(i);
  virial_.clear(i);
  history_.clear(i);
}

int FixHardContact::pack_exchange(int i, double *buf)
{
  const int n = outputs_.per_atom_columns();
  for (int k = 0; k < n; ++k) buf[k] = array_atom[i][k];
  const int m = n + virial_.pack(i, buf + n);
  return m + history_.pack(i, buf + m);
}

int FixHardContact::unpack_exchange(int nlocal, double *buf)
{
  const int n = outputs_.per_atom_columns();
  for (int k = 0; k < n; ++k) array_atom[nlocal][k] = buf[k];
  const int m = n + virial_.unpack(nlocal, buf + n);
  return m + history_.unpack(nlocal, buf + m);
}

// The global state: a format tag, then the kept overlaps' state (core/kept_overlaps.h) and the
// solver's (solver.h: the hybrid's back-off), so that a split run keeps and clears overlaps and
// picks its solvers in the same steps as the unsplit one. LAMMPS
// calls this on every process; only the first writes (the others have no file).
namespace {
constexpr double kGlobalStateFormat = 2.0;
// the tag, the kept overlaps' back-off and budget, the solver's state (hybrid: its back-off)
constexpr int kGlobalStateSize =
    1 + hardcontact::KeptOverlaps::kStateSize + hardcontact::Solver::kStateSize;
}

void FixHardContact::write_restart(FILE *fp)
{
  double list[kGlobalStateSize];
  list[0] = kGlobalStateFormat;
  step_.kept_overlaps().save_state(list + 1);
  solver_->save_state(list + 1 + hardcontact::KeptOverlaps::kStateSize);
  if (comm->me == 0) {
    const int size = static_cast<int>(sizeof(list));
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(list, sizeof(double), kGlobalStateSize, fp);
  }
}

// Every process receives the same bytes. A state of another format (a later build's) is
// ignored: the run then starts with a fresh back-off and budget, as before restart files held
// them.
void FixHardContact::restart(char *buf)
{
  double list[kGlobalStateSize];
  std::memcpy(list, buf, sizeof(double));    // the tag first: another format may be shorter
  if (list[0] != kGlobalStateFormat) return;
  std::memcpy(list, buf, sizeof(list));
  step_.kept_overlaps().load_state(list + 1);
  solver_->load_state(list + 1 + hardcontact::KeptOverlaps::kStateSize);
}

// Restart files hold the contact history, so a split run starts its next solve where the
// unsplit one would.
int FixHardContact::pack_restart(int i, double *buf)
{
  buf[0] = 1 + history_.packed_size(i);    // LAMMPS convention: own size first
  return 1 + history_.pack(i, buf + 1);
}

void FixHardContact::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; ++k) m += static_cast<int>(extra[nlocal][m]);
  history_.unpack(nlocal, &extra[nlocal][m + 1]);
}

int FixHardContact::size_restart(int nlocal)
{
  return 1 + history_.packed_size(nlocal);
}

int FixHardContact::maxsize_restart()
{
  return 1 + history_.max_packed_size();
}

// The values of ops_.forward (lammps_ops.h), per LAMMPS atom index.
int FixHardContact::pack_forward_comm(int n, int *list, double *buf, int, int *)
{
  const double *data = ops_.data();
  const int per = ops_.per_body(), blocks = ops_.blocks();
  const long stride = ops_.block_stride();
  int m = 0;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < blocks; ++b)
      for (int k = 0; k < per; ++k) buf[m++] = data[b * stride + per * list[a] + k];
  return m;
}

void FixHardContact::unpack_forward_comm(int n, int first, double *buf)
{
  double *data = ops_.data();
  const int per = ops_.per_body(), blocks = ops_.blocks();
  const long stride = ops_.block_stride();
  int m = 0;
  for (int a = first; a < first + n; ++a)
    for (int b = 0; b < blocks; ++b)
      for (int k = 0; k < per; ++k) data[b * stride + per * a + k] = buf[m++];
}
