"""Shared pieces of the stability deck tests (test_stab_*.py): deterministic data files for
atom_style sphere, one deck template with every per-step diagnostic the checks need, and the
checks of the paper's guarantees (SCHEME.md, section 4) on the thermo output and the dumps.

Why data files: create_atoms numbers atoms differently with the number of MPI ranks and
random() in atom-style variables is per rank; a data file written here (fixed numpy seeds,
every float at full precision with repr) gives the same scene on every rank count.

Thermo of every deck (one row per step, %.16g):
  Step Atoms c_ke  c_P[1..3] (sum m v)  c_P[4] (sum m |v|)  c_P[5] (sum m g z, 0 without
  gravity)  c_vmax (largest speed)  f_hc[1..9] (the fix's global vector, doc/fix_hardcontact.md)
"""

import math

import numpy as np

import lammps_run as lr
import physics_common as pc

DUMP_COLUMNS = "id radius mass x y z vx vy vz f_hc[1] f_hc[2] f_hc[3] f_hc[4]"
LOCAL_COLUMNS = "f_hc[1] f_hc[2] f_hc[3] f_hc[4] f_hc[5] f_hc[6] f_hc[7]"

DECK = """
units           lj
atom_style      sphere
dimension       {dim}
boundary        {boundary}
atom_modify     map array
comm_modify     vel yes
read_data       {data}
pair_style      none
neighbor        {skin} bin
neigh_modify    delay 0 every 1 check {check}
{forces}
fix             hc all hardcontact {keywords}
{enforce2d}
timestep        {h}
compute         ke all ke
variable        mvx atom mass*vx
variable        mvy atom mass*vy
variable        mvz atom mass*vz
variable        mv atom mass*sqrt(vx*vx+vy*vy+vz*vz)
variable        mgz atom mass*{g}*{up}
compute         P all reduce sum v_mvx v_mvy v_mvz v_mv v_mgz
variable        sp atom sqrt(vx*vx+vy*vy+vz*vz)
compute         vmax all reduce max v_sp
thermo_style    custom step atoms c_ke c_P[1] c_P[2] c_P[3] c_P[4] c_P[5] c_vmax &
                f_hc[1] f_hc[2] f_hc[3] f_hc[4] f_hc[5] f_hc[6] f_hc[7] f_hc[8] f_hc[9] f_hc[10] &
                f_hc[12]
thermo_modify   norm no lost error format float %.16g
thermo          {thermo}
{dumps}
run             {nsteps}
"""

THERMO_COLUMNS = ["Step", "Atoms", "c_ke", "c_P[1]", "c_P[2]", "c_P[3]", "c_P[4]", "c_P[5]", "c_vmax"] + \
    ["f_hc[%d]" % k for k in range(1, 11)] + ["f_hc[12]"]


def deck(data, nsteps, h, skin, keywords="", dim=3, boundary="f f f", gravity=0.0,
         thermo=1, dump_every=0, local_every=0, extra_dumps="", extra_forces="",
         rebuild_every_step=False):
    """The deck text. gravity g > 0 pulls along -z (3d) or -y (2d); dump_every > 0 writes
    dump.atoms (DUMP_COLUMNS, %.16g, sorted by id), local_every > 0 dump.local (the fix's
    local array)."""
    up = "y" if dim == 2 else "z"
    forces = extra_forces
    if gravity:
        vec = "0 -1 0" if dim == 2 else "0 0 -1"
        forces += "\nfix             grav all gravity %r vector %s" % (float(gravity), vec)
    dumps = extra_dumps
    if dump_every:
        dumps += ("\ndump            d all custom %d dump.atoms %s\n"
                  "dump_modify     d format float %%.16g sort id" % (dump_every, DUMP_COLUMNS))
    if local_every:
        dumps += ("\ndump            l all local %d dump.local %s\n"
                  "dump_modify     l format float %%.16g" % (local_every, LOCAL_COLUMNS))
    return DECK.format(dim=dim, boundary=boundary, data=data, skin=repr(float(skin)),
                       forces=forces, keywords=keywords,
                       enforce2d="fix             e2d all enforce2d" if dim == 2 else "",
                       h=repr(float(h)), g=repr(float(gravity)), up=up, thermo=thermo,
                       check="no" if rebuild_every_step else "yes",
                       dumps=dumps, nsteps=nsteps)


def write_data(path, box, radius, density, x, v=None, title="hardcontact stability test"):
    """LAMMPS data file for atom_style sphere (physics_common.write_sphere_data)."""
    pc.write_sphere_data(path, box, radius, density, x, v, title)


def run(args, text, workdir, data_path, np_=None, timeout=None):
    """Run a deck (np_ ranks, default args.np) with the data file copied in; check that it
    ran without ERROR and return (result, thermo block)."""
    res = lr.run_deck(args.lmp, text, args.np if np_ is None else np_, workdir,
                      files=[data_path], timeout=timeout or args.timeout)
    lr.check(not res.errors, "%s: no ERROR" % workdir)
    lr.check(len(res.thermo) == 1, "%s: one thermo block" % workdir)
    th = res.thermo[0]
    missing = [c for c in THERMO_COLUMNS if c not in th]
    lr.check(not missing, "thermo columns present (missing %s)" % missing)
    return res, th


# ----------------------------------------------------------------------------------- frames

# positions, velocities and the brute-force pair overlap are the physics tests' own
positions = pc.positions
velocities = pc.velocities


def pair_overlap(x, radius, block=256):
    """Largest overlap over ALL pairs relative to r_i + r_j (0 if none) and the pair (0-based):
    brute force, independent of the fix's neighbour list and candidates."""
    return pc.pair_overlaps(x, radius, block)


def wall_overlap(x, radius, walls):
    """Largest overlap with flat walls relative to r: walls = [(dim, coord, +1 lo / -1 hi)]."""
    worst = 0.0
    for dim, coord, side in walls:
        gap = side * (x[:, dim] - coord) - radius
        worst = max(worst, float((-gap / radius).max()))
    return worst


def all_finite(fr):
    return all(np.all(np.isfinite(fr.columns[k].astype(float))) for k in fr.columns)


# ----------------------------------------------------------------------------------- checks

def dump_overlaps(frames, n, walls, chk, label):
    """Checks that every dumped frame holds n atoms, all finite, and returns the largest
    all-pairs overlap and wall overlap over the frames, each relative to the contact size
    (brute force: independent of the fix's neighbour list)."""
    worst_pair = worst_wall = 0.0
    for fr in frames:
        chk(all_finite(fr) and len(fr.columns["id"]) == n,
            "%s: step %d: %d atoms, all finite" % (label, fr.timestep, n))
        xs = positions(fr)
        worst_pair = max(worst_pair, pair_overlap(xs, fr.columns["radius"])[0])
        if walls:
            worst_wall = max(worst_wall, wall_overlap(xs, fr.columns["radius"], walls))
    return worst_pair, worst_wall


def momentum_drift(th):
    """max over steps of |P(t) - P(0)| / max_t sum m |v|: relative momentum error."""
    P = np.column_stack([th["c_P[1]"], th["c_P[2]"], th["c_P[3]"]])
    scale = max(float(th["c_P[4]"].max()), 1e-300)
    return float(np.abs(P - P[0]).max()) / scale


def energy_rises(e, scale=None):
    """Largest step-to-step increase of the series e, relative to scale (default e[0])."""
    e = np.asarray(e, dtype=float)
    if len(e) < 2:
        return 0.0
    s = scale if scale is not None else max(abs(float(e[0])), 1e-300)
    return float(max(0.0, np.diff(e).max())) / s


def check_common(th, natoms, tol, label, overlap_factor=1.0, check=lr.check):
    """What every stability case asserts from the per-step thermo: no lost atom, every value
    finite, f_hc[7] (largest overlap / contact size after the step) <= overlap_factor * tol
    at every step, and no solve stopped at maxiter (f_hc[6] = 0)."""
    check(bool(np.all(th["Atoms"] == natoms)), "%s: no lost atom (%d at every step)" % (label, natoms))
    finite = all(np.all(np.isfinite(th[c])) for c in th)
    check(finite, "%s: every thermo value finite (no NaN/inf)" % label)
    ov = float(th["f_hc[7]"].max())
    step = int(th["Step"][int(np.argmax(th["f_hc[7]"]))])
    check(ov <= overlap_factor * tol,
             "%s: largest overlap / size over the run %.3g (step %d) <= %.3g" %
             (label, ov, step, overlap_factor * tol))
    hits = float(th["f_hc[6]"][-1])
    check(hits == 0.0, "%s: no solve stopped at maxiter (f_hc[6] = %g)" % (label, hits))
    return ov


class Checks:
    """Soft assertions: every check of a case is evaluated and printed (ok / FAIL), so that
    one failing property does not hide the others; finish() raises if any failed."""

    def __init__(self):
        self.failed = []

    def __call__(self, condition, message):
        if condition:
            print("ok:", message)
        else:
            print("FAIL:", message)
            self.failed.append(message)
        return bool(condition)

    def finish(self):
        if self.failed:
            raise AssertionError("%d check(s) failed:\n  " % len(self.failed) +
                                 "\n  ".join(self.failed))


def report(name, **values):
    """One line of measured numbers, for doc/stability.md (grep 'MEASURED')."""
    parts = ["%s=%s" % (k, ("%.3g" % v) if isinstance(v, float) else v) for k, v in values.items()]
    print("MEASURED %s: %s" % (name, " ".join(parts)))


def _stacked_layers(n, nlayer, r, spacing, dims):
    """Layers of touching spheres of radius r, `spacing` apart along y (dims 1: rows of discs)
    or z (dims 2: square layers): even layers n per row from r, touching each other and the
    side walls of a box of width 2 r n; odd layers n - 1 per row in the hollows."""
    pts = []
    for k in range(nlayer):
        first, count = (r, n) if k % 2 == 0 else (2.0 * r, n - 1)
        row = [first + i * 2.0 * r for i in range(count)]
        level = r + k * spacing
        if dims == 1:
            pts += [(x, level, 0.0) for x in row]
        else:
            pts += [(x, y, level) for x in row for y in row]
    return np.array(pts)


def hex_lattice_2d(ncol, nrow, r, gap=0.0):
    """Hexagonal packing of discs of radius r in a box of width 2 r ncol: even rows hold ncol
    discs touching each other and both side walls, odd rows ncol - 1 discs in the hollows.
    gap: extra vertical distance between rows (0 = touching). Returns (N, 3), z = 0."""
    return _stacked_layers(ncol, nrow, r, math.sqrt(3.0) * r + gap, 1)


def fcc_lattice(n, nlayer, r, gap=0.0):
    """FCC packing of spheres of radius r stacked as (100) layers in a box of side 2 r n:
    even layers n x n touching spheres (touching the four side walls), odd layers
    (n-1) x (n-1) in the hollows, layer spacing sqrt(2) r (+ gap). Returns (N, 3)."""
    return _stacked_layers(n, nlayer, r, math.sqrt(2.0) * r + gap, 2)
