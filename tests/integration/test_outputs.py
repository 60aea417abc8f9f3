#!/usr/bin/env python3
"""Outputs of fix hardcontact (global vector f_ID[1..9], per-atom array, local array), serially
or under mpirun (--np). Five scenes, each from a deterministic data file or fixed positions:

(a) contacts: 216 polydisperse spheres of different densities in a periodic box, random plus
    converging velocities, no walls, no forces, dumps every step. At every step:
    * the local rows are the active contacts, each once over all ranks: their number equals
      f_1[4]; no pair appears twice; every row has force > 0, j > 0, wall number 0, a unit
      normal, and that normal points from i to j at the positions the step started from;
    * per-atom outputs follow from the rows: f_1[2..4] of each atom = sum over its rows of
      (-force x normal) as atom i, (+force x normal) as atom j; f_1[1] = its row count;
    * the per-atom contact forces sum to zero (Newton's third law);
    * no pair (all pairs, from the dumped positions) overlaps by more than tol x size, f_1[2] is
      the largest overlap, residual f_1[5] <= tol; KE never increases (Prop. 3);
    * with --np > 1 the same deck on 1 rank gives the same candidate and active counts.
(b) wall load: a stable stack of 48 spheres drops onto 'wall zplane 0.0 NULL' under fix
    gravity (tol 1e-8): once settled the local rows with j = 0 carry the whole weight
    (sum m g) to 1e-4; and at every step, exactly, sum(wall forces) - weight = change of
    vertical momentum / h.
(c) starved solver: scene (a) with maxiter 2 (solver apgd, uzawa, uzawa warmstart no, pgs):
    a WARNING that names maxiter, f_1[6] counts up (by at most one per step, to the count of
    the end-of-run warning), and the total momentum (no walls, no forces) stays exact to
    round-off (Prop. 4 / Remark 10 of the paper). KE should not grow much either: with uzawa
    and warm start (the default) it does (a known bug, enforced only with --known-bugs).
(d) initial overlaps: pairs of unit spheres overlapping by 20% of the diameter.
    * at rest, no force: a WARNING about overlapping spheres; KE stays bounded and stops growing, the
      overlap stays 0.2;
    * under gravity on a floor (one pair stacked, one side by side): the overlap shrinks every
      step to zero, and KE stays of order m (g h)^2 per atom (below it);
    * KNOWN BUG (reported, enforced only with --known-bugs): five spheres in a row on the
      floor, each overlapping the next by 20%, under gravity: KE explodes (x4 per step).
(e) walls: 100 spheres thrown into a box with five walls: wall numbers and normals of the
    local rows follow the fix command, the per-atom forces add up to the wall rows' forces, and
    sum m dv = h (wall forces - weight) at every step.
(f) fix_modify 1 contacts pairs / walls: (e) again; the local array then lists exactly (e)'s rows
    with j > 0 (under dump_modify label BONDS, as OVITO reads bonds), resp. j = 0.

Known bugs print 'KNOWN BUG ...' and pass; --known-bugs makes them fail (not registered in
ctest)."""

import re
import sys

import numpy as np

import lammps_run as lr
import scene_data as sd

# ------------------------------------------------------------------------------- helpers

ROW_COLS = ["f_1[%d]" % k for k in range(1, 8)]
ATOM_COLS = "id mass radius x y z vx vy vz f_1[1] f_1[2] f_1[3] f_1[4]"


def rows_of(frame):
    """Local rows of a frame: i, j (int), force, normals (n, 3), wall number."""
    c = frame.columns
    if not len(c.get("f_1[1]", [])):
        return (np.zeros(0, int), np.zeros(0, int), np.zeros(0), np.zeros((0, 3)), np.zeros(0))
    return (c["f_1[1]"].astype(np.int64), c["f_1[2]"].astype(np.int64), c["f_1[3]"].astype(float),
            np.column_stack([c["f_1[4]"], c["f_1[5]"], c["f_1[6]"]]).astype(float),
            c["f_1[7]"].astype(float))


def read_local_tolerant(path):
    """dump local frames by step ({step: DumpFrame}); also reads empty frames without an
    ENTRIES line, and frames labelled otherwise (dump_modify label BONDS: ITEM: BONDS)."""
    out = {}
    with open(str(path)) as f:
        lines = f.read().splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
            count = int(lines[i + 3])
            label = "ITEM: " + lines[i + 2].split("NUMBER OF ", 1)[-1].strip() + " "
            j = i + 4
            while j < len(lines) and not lines[j].startswith(label) \
                    and not lines[j].startswith("ITEM: TIMESTEP"):
                j += 1
            if j < len(lines) and lines[j].startswith(label):
                names = lines[j].split()[2:]
                rows = [l.split() for l in lines[j + 1:j + 1 + count]]
                cols = {n: np.array([float(r[k]) for r in rows]) for k, n in enumerate(names)}
                i = j + 1 + count
            else:
                cols = {}
                i = j
            out[step] = lr.DumpFrame(step, cols, None)
        else:
            i += 1
    return out


def thermo_at(th, column, step):
    steps = list(th["Step"])
    return th[column][steps.index(step)]


GAS_DECK = """units           lj
atom_style      sphere
boundary        p p p
read_data       gas.data
pair_style      none
neighbor        {skin} bin
timestep        0.02
fix             1 all hardcontact {fix}
thermo_style    custom step ke f_1[1] f_1[2] f_1[3] f_1[4] f_1[5] f_1[6] f_1[7] f_1[8] f_1[9]
thermo_modify   norm no format float %.17g
thermo          1
dump            a all custom 1 atoms.dump {atom_cols}
dump_modify     a format float %.17g
dump            l all local 1 local.dump {row_cols}
dump_modify     l format float %.17g
run             {steps}
"""

GAS_STEPS = 40


def gas_deck(fix="", skin=0.5):
    return GAS_DECK.format(fix=fix, skin=skin, atom_cols=ATOM_COLS, row_cols=" ".join(ROW_COLS),
                           steps=GAS_STEPS)


def run_gas(args, name, fix, np_=None, skin=0.5):
    wd = lr.fresh_workdir("%s/%s" % (args.workdir, name))
    scene = sd.gas(converge=1.0, seed=2)
    sd.write_data(wd / "gas.data", scene, "outputs test: 216 colliding spheres, periodic box")
    res = lr.run_deck(args.lmp, gas_deck(fix, skin), args.np if np_ is None else np_, wd,
                      timeout=args.timeout)
    return scene, res, wd


def minimum_image(d, box):
    L = box[:, 1] - box[:, 0]
    return d - L * np.round(d / L)


def largest_overlap(frame, box):
    """Largest overlap over ALL pairs (minimum image), in distance and relative to r_i + r_j."""
    c = frame.columns
    x = np.column_stack([c["x"], c["y"], c["z"]])
    r = c["radius"]
    iu, ju = np.triu_indices(len(r), k=1)
    d = np.linalg.norm(minimum_image(x[ju] - x[iu], box), axis=1)
    ov = r[iu] + r[ju] - d
    k = int(np.argmax(ov))
    return max(float(ov[k]), 0.0), max(float(ov[k] / (r[iu[k]] + r[ju[k]])), 0.0)


# ------------------------------------------------------------------------------- (a)

def part_a(args):
    scene, res, wd = run_gas(args, "a_contacts", "")
    th = res.thermo[0]
    atoms = {f.timestep: f for f in lr.read_dump(wd / "atoms.dump")}
    local = read_local_tolerant(wd / "local.dump")
    box = scene.box
    n = len(scene.diameter)
    lr.check(sorted(atoms) == list(range(GAS_STEPS + 1)), "(a) atom dumps at every step")
    lr.check(int(th["f_1[6]"][-1]) == 0, "(a) every solve converged")
    total_rows = 0
    worst_newton = worst_atom = worst_normal = worst_dir = worst_diag = worst_rel = 0.0
    for step in range(1, GAS_STEPS + 1):
        fr = atoms[step]
        c = fr.columns
        ov, rel = largest_overlap(fr, box)
        worst_rel = max(worst_rel, rel)
        worst_diag = max(worst_diag, abs(ov - thermo_at(th, "f_1[2]", step)))
        lr_frame = local.get(step, lr.DumpFrame(step, {}, None))
        i, j, mu, nrm, wall = rows_of(lr_frame)
        nrows = len(i)
        total_rows += nrows
        active = int(thermo_at(th, "f_1[4]", step))
        assert nrows == active, "(a) step %d: %d local rows but f_1[4] = %d" % (step, nrows, active)
        if nrows:
            assert (mu > 0).all(), "(a) step %d: a row with force <= 0" % step
            assert (j > 0).all() and (wall == 0).all() and (i != j).all(), \
                "(a) step %d: a row with j <= 0, a wall number or i == j" % step
            pairs = {(min(a, b), max(a, b)) for a, b in zip(i, j)}
            assert len(pairs) == nrows, "(a) step %d: a pair appears twice (%d rows, %d pairs)" \
                % (step, nrows, len(pairs))
            worst_normal = max(worst_normal, float(np.abs(np.linalg.norm(nrm, axis=1) - 1).max()))
            # normal from i to j at the positions the step started from (minimum image)
            prev = atoms[step - 1].columns
            x = np.column_stack([prev["x"], prev["y"], prev["z"]])
            d = minimum_image(x[j - 1] - x[i - 1], box)
            e = d / np.linalg.norm(d, axis=1)[:, None]
            worst_dir = max(worst_dir, float(np.abs(e - nrm).max()))
        # per-atom forces from the rows
        ids = c["id"]
        assert list(ids) == list(range(1, n + 1)), "(a) step %d: all atoms dumped" % step
        F = np.column_stack([c["f_1[2]"], c["f_1[3]"], c["f_1[4]"]])
        F_rows = np.zeros((n, 3))
        count = np.zeros(n)
        for a, b, m_, e_ in zip(i, j, mu, nrm):
            F_rows[a - 1] -= m_ * e_
            F_rows[b - 1] += m_ * e_
            count[a - 1] += 1
            count[b - 1] += 1
        scale = max(float(mu.max()) if nrows else 0.0, 1e-300)
        worst_atom = max(worst_atom, float(np.abs(F - F_rows).max()) / scale)
        assert np.array_equal(c["f_1[1]"].astype(float), count), \
            "(a) step %d: f_1[1] differs from the row count of an atom (atoms %s)" % (
                step, list(ids[c["f_1[1]"] != count][:5]))
        fsum = np.abs(F).sum()
        if fsum > 0:
            worst_newton = max(worst_newton, float(np.abs(F.sum(axis=0)).max() / fsum))
    lr.check(total_rows > 2000, "(a) the scene has contacts: %d active rows over %d steps "
             "(peak %d)" % (total_rows, GAS_STEPS, th["f_1[4]"].max()))
    print("(a) on every step 1..%d: local rows = f_1[4], each pair once, force > 0, j > 0" % GAS_STEPS)
    print("(a) f_1[1] = number of rows of each atom, on every step")
    lr.check(worst_rel <= 1e-4, "(a) no pair overlaps by more than tol x (r_i + r_j) at any step "
             "(all pairs, from the dumps: %.2g)" % worst_rel)
    lr.check(worst_diag < 1e-12, "(a) f_1[2] is the largest overlap of the dumped positions (%.2g)"
             % worst_diag)
    lr.check((th["f_1[5]"][1:] <= 1e-4).all() and (th["f_1[9]"][1:] >= 1).all()
             and (th["f_1[8]"][1:] > 0).all() and (th["f_1[7]"] <= 1e-4).all(),
             "(a) every step: residual f_1[5] <= tol, f_1[7] <= tol, f_1[8] > 0, f_1[9] >= 1")
    ke = th["KinEng"]
    lr.check((np.diff(ke) <= 1e-12 * ke[:-1]).all(), "(a) KE never increases (Prop. 3): %.6g -> "
             "%.6g" % (ke[0], ke[-1]))
    lr.check(worst_normal < 1e-12, "(a) normals are unit vectors (%.2g)" % worst_normal)
    lr.check(worst_dir < 1e-9, "(a) normals point from i to j at the start of the step (%.2g)"
             % worst_dir)
    lr.check(worst_atom < 1e-12, "(a) per-atom force = sum of its rows' force x normal (largest "
             "difference %.2g of the largest row force)" % worst_atom)
    lr.check(worst_newton < 1e-12, "(a) per-atom contact forces sum to zero (%.2g of sum |F|)"
             % worst_newton)
    if args.np > 1:
        _, ref, _ = run_gas(args, "a_contacts_np1", "", np_=1)
        t1 = ref.thermo[0]
        lr.check(np.array_equal(t1["f_1[3]"], th["f_1[3]"]),
                 "(a) candidate counts f_1[3] on %d ranks equal those on 1 rank at every step"
                 % args.np)
        diff = np.abs(t1["f_1[4]"] - th["f_1[4]"])
        lr.check((diff <= 1 + 0.01 * t1["f_1[4]"]).all(),
                 "(a) active counts f_1[4] on %d ranks equal those on 1 rank (largest difference "
                 "%d)" % (args.np, diff.max()))


# ------------------------------------------------------------------------------- (b)

PILE_DECK = """units           lj
atom_style      sphere
boundary        p p f
read_data       pile.data
pair_style      none
neighbor        0.3 bin
timestep        {dt}
fix             g all gravity {g} vector 0 0 -1
fix             1 all hardcontact tol 1e-8 wall zplane 0.0 NULL
thermo_style    custom step ke f_1[1] f_1[3] f_1[4] f_1[5] f_1[6] f_1[7]
thermo_modify   norm no
thermo          50
run             {settle}
dump            a all custom 1 atoms.dump id mass vz
dump_modify     a format float %.17g
dump            l all local 1 local.dump {row_cols}
dump_modify     l format float %.17g
run             {last}
"""


def part_b(args):
    """A stable frictionless pile: three layers of 16 unit spheres (square lattice, then its
    hollows, then the lattice again) dropped from 0.01 above their resting heights. A
    disordered frictionless pile never comes to rest (it keeps creeping), so it would not
    give a settled load."""
    g, dt, settle, last = 1.0, 0.02, 300, 10
    wd = lr.fresh_workdir("%s/b_wall_load" % args.workdir)
    scene = sd.square_stack(n_side=4, layers=3)
    sd.write_data(wd / "pile.data", scene, "outputs test: 48 spheres stacked on a floor")
    res = lr.run_deck(args.lmp, PILE_DECK.format(dt=dt, g=g, settle=settle, last=last,
                                                 row_cols=" ".join(ROW_COLS)),
                      args.np, wd, timeout=args.timeout)
    weight = float(sd.mass(scene).sum() * g)
    atoms = {f.timestep: f for f in lr.read_dump(wd / "atoms.dump")}
    local = read_local_tolerant(wd / "local.dump")
    steps = list(range(settle + 1, settle + last + 1))
    lr.check(sorted(atoms) == [settle] + steps, "(b) dumps at steps %d to %d"
             % (settle, settle + last))
    worst_load = worst_balance = 0.0
    n_wall = set()
    for step in steps:
        i, j, mu, nrm, wall = rows_of(local[step])
        on_wall = j == 0
        n_wall.add(int(on_wall.sum()))
        assert (wall[on_wall] == 1).all() and (wall[~on_wall] == 0).all(), \
            "(b) step %d: wall numbers are 1 for the floor rows, 0 for pairs" % step
        assert (np.abs(nrm[on_wall] - [0, 0, -1]).max(initial=0) < 1e-15), \
            "(b) step %d: floor rows have normal (0, 0, -1) (towards the wall)" % step
        load = float(mu[on_wall].sum())
        worst_load = max(worst_load, abs(load / weight - 1.0))
        m = atoms[step].columns["mass"]
        dP = float((m * (atoms[step].columns["vz"] - atoms[step - 1].columns["vz"])).sum())
        worst_balance = max(worst_balance, abs((load - weight) - dP / dt) / weight)
    th = res.thermo[-1]
    lr.check(n_wall == {16}, "(b) the 16 spheres of the bottom layer touch the floor: %s" % n_wall)
    lr.check(th["KinEng"][-1] < 1e-10 * weight, "(b) the pile is at rest: KE %.3g"
             % th["KinEng"][-1])
    lr.check(worst_load < 1e-4, "(b) settled: the floor rows (j = 0) carry the weight %.6g to "
             "%.2g (worst of the last %d steps)" % (weight, worst_load, last))
    lr.check(worst_balance < 1e-9, "(b) every step: sum of floor forces - weight = d(momentum_z)/h "
             "(to %.2g of the weight)" % worst_balance)


# ------------------------------------------------------------------------------- (e)

BOX_DECK = """units           lj
atom_style      sphere
boundary        f f f
read_data       pile.data
pair_style      none
neighbor        1.0 bin
timestep        {dt}
fix             g all gravity {g} vector 0 0 -1
fix             1 all hardcontact wall xplane 0 {w} wall yplane 0 {w} wall zplane 0 NULL
{modify}
thermo_style    custom step f_1[4] f_1[6]
thermo          1
dump            a all custom 1 atoms.dump {atom_cols}
dump_modify     a format float %.17g
dump            l all local 1 local.dump {row_cols}
dump_modify     l format float %.17g {label}
run             {steps}
"""

# wall number -> (dimension, lo side?, unit normal from the sphere towards the wall)
BOX_WALLS = {1: (0, True, (-1, 0, 0)), 2: (0, False, (1, 0, 0)), 3: (1, True, (0, -1, 0)),
             4: (1, False, (0, 1, 0)), 5: (2, True, (0, 0, -1))}


def part_e(args):
    """Five walls: wall numbers follow the fix command (lo before hi), each with its normal,
    next to the sphere it pushes; the per-atom forces add up to the wall rows' forces (pairs
    cancel); and with gravity, sum m dv = h (sum of wall forces - weight) at every step."""
    g, dt, steps = 10.0, 0.02, 40
    wd = lr.fresh_workdir("%s/e_box_walls" % args.workdir)
    scene = sd.pile(n_side=5, layers=4, seed=1)
    width = scene.box[0, 1]
    planes = {1: 0.0, 2: width, 3: 0.0, 4: width, 5: 0.0}
    sd.write_data(wd / "pile.data", scene, "outputs test: 100 spheres thrown into a box")
    res = lr.run_deck(args.lmp, BOX_DECK.format(dt=dt, g=g, w=repr(width), steps=steps,
                                                atom_cols=ATOM_COLS, row_cols=" ".join(ROW_COLS),
                                                modify="", label=""),
                      args.np, wd, timeout=args.timeout)
    th = res.thermo[0]
    atoms = {f.timestep: f for f in lr.read_dump(wd / "atoms.dump")}
    local = read_local_tolerant(wd / "local.dump")
    used = set()
    worst_sum = worst_balance = worst_side = 0.0
    for step in range(1, steps + 1):
        i, j, mu, nrm, wall = rows_of(local.get(step, lr.DumpFrame(step, {}, None)))
        assert len(i) == th["f_1[4]"][step], "(e) step %d: rows = f_1[4]" % step
        on_wall = j == 0
        assert ((wall > 0) == on_wall).all(), "(e) step %d: j = 0 exactly for wall rows" % step
        prev = atoms[step - 1].columns
        for a, w, e_ in zip(i[on_wall], wall[on_wall].astype(int), nrm[on_wall]):
            assert w in BOX_WALLS, "(e) step %d: wall number %d (5 walls)" % (step, w)
            dim, lo, n_ref = BOX_WALLS[w]
            assert np.array_equal(e_, np.array(n_ref, float)), \
                "(e) step %d: wall %d has normal %s, expected %s" % (step, w, e_, n_ref)
            x = prev["xyz"[dim]][a - 1]
            gap = (x - planes[w] if lo else planes[w] - x) - prev["radius"][a - 1]
            worst_side = max(worst_side, -gap / prev["radius"][a - 1])
            assert gap < 0.5, "(e) step %d: atom %d is %.3g away from wall %d" % (step, a, gap, w)
            used.add(w)
        c = atoms[step].columns
        F = np.column_stack([c["f_1[2]"], c["f_1[3]"], c["f_1[4]"]])
        F_walls = -(mu[on_wall][:, None] * nrm[on_wall]).sum(axis=0)
        scale = max(float(np.abs(F).sum()), 1e-300)
        worst_sum = max(worst_sum, float(np.abs(F.sum(axis=0) - F_walls).max()) / scale)
        m = c["mass"]
        dP = (m[:, None] * (np.column_stack([c["vx"], c["vy"], c["vz"]])
                            - np.column_stack([prev["vx"], prev["vy"], prev["vz"]]))).sum(axis=0)
        expect = dt * (F_walls - np.array([0.0, 0.0, m.sum() * g]))
        worst_balance = max(worst_balance, float(np.abs(dP - expect).max()) / (m.sum() * g * dt))
    lr.check(used == set(BOX_WALLS), "(e) every wall 1..5 carries load at some step (%s)"
             % sorted(used))
    print("(e) wall numbers 1..5 = xlo, xhi, ylo, yhi, zlo, each with its normal, next to its sphere")
    lr.check(worst_side <= 1e-4, "(e) no sphere behind a wall by more than tol x r at the start of "
             "a step (%.2g)" % worst_side)
    lr.check(worst_sum < 1e-12, "(e) sum of per-atom forces = sum of wall rows' forces (%.2g)"
             % worst_sum)
    lr.check(worst_balance < 1e-9, "(e) every step: sum m dv = h (wall forces - weight) (%.2g of "
             "the weight impulse)" % worst_balance)
    part_f(args, wd, local, dict(dt=dt, g=g, w=repr(width), steps=steps, atom_cols=ATOM_COLS,
                                 row_cols=" ".join(ROW_COLS)))


def part_f(args, wd_e, local_all, fmt):
    """fix_modify 1 contacts pairs|walls: scene (e) again, its local array restricted to the
    pairs (labelled BONDS, as OVITO loads force chains) or to the wall rows: exactly the rows of
    (e) with j > 0, resp. j = 0, step by step (the filter changes no solve); the global active
    count f_1[4] stays the count of all rows."""
    for which, label in (("pairs", "label BONDS"), ("walls", "")):
        wd = lr.fresh_workdir("%s/f_contacts_%s" % (args.workdir, which))
        res = lr.run_deck(args.lmp, BOX_DECK.format(modify="fix_modify 1 contacts %s" % which,
                                                    label=label, **fmt),
                          args.np, wd, files=[wd_e / "pile.data"], timeout=args.timeout)
        th = res.thermo[0]
        local = read_local_tolerant(wd / "local.dump")
        rows = 0
        for step in range(1, fmt["steps"] + 1):
            empty = lr.DumpFrame(step, {}, None)
            i, j, mu, nrm, wall = rows_of(local_all.get(step, empty))
            assert len(i) == th["f_1[4]"][step], "(f) %s step %d: f_1[4] counts all rows" \
                % (which, step)
            keep = j > 0 if which == "pairs" else j == 0
            want = sorted(zip(i[keep], j[keep], mu[keep], wall[keep]))
            fi, fj, fmu, _, fwall = rows_of(local.get(step, empty))
            got = sorted(zip(fi, fj, fmu, fwall))
            assert got == want, "(f) step %d: contacts %s lists %d rows, (e) has %d such rows" \
                % (step, which, len(got), len(want))
            rows += len(got)
        lr.check(rows > 0, "(f) contacts %s: %d rows over %d steps, exactly (e)'s rows with %s"
                 % (which, rows, fmt["steps"], "j > 0" if which == "pairs" else "j = 0"))
        if label:
            text = (wd / "local.dump").read_text()
            lr.check("ITEM: NUMBER OF BONDS" in text and "ITEM: BONDS" in text,
                     "(f) dump_modify label BONDS: the header OVITO reads as bonds")


# ------------------------------------------------------------------------------- (c)

def part_c(args, known_bugs, options):
    tag = "(c, %s)" % options
    # a large skin: starved solves leave overlaps that the next steps push apart fast
    scene, res, wd = run_gas(args, "c_starved_" + options.replace(" ", "_"),
                             "%s maxiter 2" % options, skin=3.0)
    th = res.thermo[0]
    warn = [w for w in res.warnings if "maxiter" in w]
    lr.check(len(warn) >= 1, tag + " a WARNING names maxiter: %s" % (warn[:1],))
    hits = th["f_1[6]"].astype(float)
    lr.check(hits[-1] > GAS_STEPS / 2, tag + " f_1[6] counts the starved solves: %d of %d steps"
             % (hits[-1], GAS_STEPS))
    inc = np.diff(hits)
    lr.check(((inc >= 0) & (inc <= 1)).all(), tag + " f_1[6] grows by 0 or 1 per step")
    summary = [w for w in warn if re.search(r"(\d+) solve\(s\) of this run stopped unconverged \(maxiter 2\)", w)]
    lr.check(summary and int(re.search(r"(\d+) solve", summary[0]).group(1)) == int(hits[-1]),
             tag + " the end-of-run warning counts the same %d solves: %s" % (hits[-1], summary[:1]))
    first = [w for w in warn if "stopped unconverged after" in w and "(maxiter 2)" in w]
    lr.check(len(first) == 1, tag + " the first starved solve is reported once")
    first_step = int(th["Step"][np.argmax(hits > 0)])
    said = int(re.search(r"solve of step (\d+)", first[0]).group(1))
    if said != first_step:
        msg = ("KNOWN BUG (c): the WARNING says 'the solve of step %d stopped at maxiter' but "
               "f_1[6] first counts at step %d (the fix prints update->ntimestep + 1 in "
               "initial_integrate, where ntimestep is already the new step)" % (said, first_step))
        print(msg)
        if known_bugs:
            raise AssertionError(msg)
    # momentum: exact to round-off
    P, scale = [], 0.0
    for f in lr.read_dump(wd / "atoms.dump"):
        c = f.columns
        mv = c["mass"][:, None] * np.column_stack([c["vx"], c["vy"], c["vz"]])
        P.append(mv.sum(axis=0))
        scale = max(scale, float(np.abs(mv).sum()))
    drift = float(np.abs(np.array(P) - P[0]).max())
    lr.check(drift < 1e-13 * scale, tag + " total momentum exact with unconverged solves: drift "
             "%.2g, %.2g of sum |m v|" % (drift, drift / scale))
    ke = th["KinEng"]
    if ke.max() > 1.1 * ke[0]:
        msg = ("KNOWN BUG %s: starved solves blow the kinetic energy up (no force, no wall): "
               "KE %.6g at step 0, %.6g at step %d (largest overlap f_1[2] up to %.3g). With "
               "warmstart no the same deck keeps KE <= its start: the last step's multipliers, "
               "applied again with only 2 iterations to correct them, push apart spheres that "
               "no longer press on each other"
               % (tag, ke[0], ke.max(), int(th["Step"][np.argmax(ke)]), th["f_1[2]"].max()))
        print(msg)
        if known_bugs:
            raise AssertionError(msg)
    else:
        print("ok: %s KE stays below 1.1 x its start (%.6g -> largest %.6g)"
              % (tag, ke[0], ke.max()))


# ------------------------------------------------------------------------------- (d)

def spheres_on_floor(xlo, xhi, centres, neighbor, forces, thermo, outputs=""):
    """A deck template (str.format fields dt, steps and those in forces) of unit spheres at
    centres (x, y, z) above the plane z = 0, the fix's only wall, thermo every step."""
    atoms = "".join("create_atoms    1 single %g %g %g units box\n" % c for c in centres)
    return lr.preamble() + (
        "region          box block %g %g 0 10 0 10\n"
        "create_box      1 box\n" % (xlo, xhi)) + atoms + (
        "pair_style      none\n"
        "neighbor        %g bin\n"
        "timestep        {dt}\n"
        "%s\n"
        "fix             1 all hardcontact wall zplane 0 NULL\n"
        "thermo_style    custom step ke %s\n"
        "thermo_modify   norm no format float %%.17g\n"
        "thermo          1\n"
        "%s"
        "run             {steps}\n" % (neighbor, forces, thermo, outputs))


OVERLAP_DECK = spheres_on_floor(0, 10, [(2.5, 5, 0.5), (2.5, 5, 1.3), (7.0, 5, 0.5), (7.8, 5, 0.5)],
                                0.3, "{gravity}", "f_1[2] f_1[7] f_1[4]",
                                "dump            a all custom 1 atoms.dump id mass x y z vx vy vz\n"
                                "dump_modify     a format float %.17g\n")


def overlaps(frame):
    c = frame.columns
    x = np.column_stack([c["x"], c["y"], c["z"]])
    return np.array([1.0 - np.linalg.norm(x[1] - x[0]), 1.0 - np.linalg.norm(x[3] - x[2])])


ROW_DECK = spheres_on_floor(-20, 30, [(x, 5, 0.5) for x in (3.0, 3.8, 4.6, 5.4, 6.2)], 8.0,
                            "fix             g all gravity {g} vector 0 0 -1", "f_1[2] f_1[4]")


def part_d_row(args, known_bugs):
    """Five spheres in a row on the floor, each overlapping the next by 20%, under gravity:
    KE should stay of order m (g h)^2 per atom like the pairs above, while the overlaps clear
    at most h x g h (+ 2 tol size) per step: 0.2 takes about 80 steps."""
    g, dt, steps = 1.0, 0.05, 200
    ke_unit = np.pi / 6.0 * (g * dt) ** 2
    wd = lr.fresh_workdir("%s/d_overlap_row" % args.workdir)
    res = lr.run_deck(args.lmp, ROW_DECK.format(dt=dt, g=g, steps=steps), args.np, wd,
                      timeout=args.timeout)
    th = res.thermo[0]
    per_atom = float(th["KinEng"].max()) / 5
    lr.check(th["f_1[2]"][-1] <= 1e-4, "(d, row) the overlaps are cleared (%.2g)" % th["f_1[2]"][-1])
    # Each contact separates at most at g h (+ the tolerance part): the ends of the row of 5
    # move at up to 2 g h, i.e. about m (g h)^2 per atom on average; twice that is the bound.
    ke = th["KinEng"]
    lr.check(per_atom <= 2 * ke_unit,
             "(d, row) KE per atom stays below 2 m (g h)^2 = %.3g (%.3g)" % (2 * ke_unit, per_atom))
    # Once the overlaps are cleared (f_1[2] <= tol), KE stays below the largest it reached while
    # they cleared: clearing may add energy (f_ID[10], bounded above), a cleared row may not.
    # (The plateau is reached at different steps by different solvers: apgd drops the
    # clearing rows' forces to 0 early, cg keeps tiny ones within tol until the row clears.)
    cleared = int(np.argmax(th["f_1[2]"] <= 1e-4))
    lr.check(cleared > 0 and float(ke[cleared:].max()) <= float(ke[:cleared + 1].max()) * (1 + 1e-9),
             "(d, row) KE does not grow once the overlaps clear at step %d (no feedback): %.12g <= %.12g"
             % (cleared, float(ke[cleared:].max()), float(ke[:cleared + 1].max())))


def part_d(args):
    g, dt, steps = 1.0, 0.05, 200
    mass = np.pi / 6.0
    # at rest, no force
    wd = lr.fresh_workdir("%s/d_overlap_rest" % args.workdir)
    res = lr.run_deck(args.lmp, OVERLAP_DECK.format(dt=dt, gravity="", steps=steps), args.np, wd,
                      timeout=args.timeout)
    warn = [w for w in res.warnings if "overlapping spheres" in w]
    lr.check(len(warn) == 1 and "0.2" in warn[0], "(d) a WARNING about overlapping spheres with "
             "the largest overlap 0.2: %s" % warn[:1])
    th = res.thermo[0]
    # Policy (doc): with no force, an overlap is cleared by at most 2 tol x size per step (plus
    # the tol the solve may leave), so each contact parts at no more than 3 tol size / h, the
    # kinetic energy stays bounded (a column of k contacts: k times that) and stops growing.
    tol, size = 1e-4, 1.0
    v_max = 2 * 3.0 * tol * size / dt    # two contacts in the stacked column
    ke_bound = 4 * 0.5 * mass * v_max ** 2
    ke = th["KinEng"]
    lr.check(float(np.abs(ke).max()) <= ke_bound,
             "(d) at rest: KE stays below 4 x 1/2 m (2 x 3 tol size / h)^2 (%.3g <= %.3g)"
             % (float(np.abs(ke).max()), ke_bound))
    lr.check(float(ke[len(ke) // 2:].max()) <= float(ke[:20].max()) * (1 + 1e-9),
             "(d) at rest: KE does not grow after the first steps (%.3g vs %.3g)"
             % (float(ke[len(ke) // 2:].max()), float(ke[:20].max())))
    ov = th["f_1[2]"]
    lr.check(bool(np.all(np.diff(ov) <= 1e-15)) and ov.max() <= 0.2 + 1e-12,
             "(d) at rest: the overlap never grows (f_1[2] from %.6g to %.6g)" % (ov.max(), ov.min()))
    lr.check(bool(np.all(np.diff(ov) >= -3 * tol * size * (1 + 1e-9))),
             "(d) at rest: it shrinks by at most 3 tol x size per step (2 tol + the solve's tol)")

    # under gravity on the floor
    wd = lr.fresh_workdir("%s/d_overlap_gravity" % args.workdir)
    res = lr.run_deck(args.lmp, OVERLAP_DECK.format(
        dt=dt, gravity="fix             g all gravity %g vector 0 0 -1" % g, steps=steps),
        args.np, wd, timeout=args.timeout)
    lr.check(any("overlapping spheres" in w for w in res.warnings),
             "(d) gravity: the overlap warning again")
    frames = lr.read_dump(wd / "atoms.dump")
    ov = np.maximum(np.array([overlaps(f) for f in frames]), 0.0)
    tol_size = 1e-4    # default tol x contact size (1)
    grow = float(np.diff(ov, axis=0).max())
    lr.check(grow <= tol_size, "(d) gravity: neither overlap grows by more than tol x size "
             "(largest growth %.2g)" % grow)
    lr.check(np.all(np.diff(ov[:20], axis=0) < 0), "(d) gravity: both overlaps shrink every step "
             "at first (%.4g -> %.4g, %.4g -> %.4g in 20 steps)"
             % (ov[0, 0], ov[20, 0], ov[0, 1], ov[20, 1]))
    lr.check(ov[-1].max() <= tol_size, "(d) gravity: both overlaps cleared within %d steps (%s)"
             % (steps, ov[-1]))
    ke_unit = mass * (g * dt) ** 2
    ke = res.thermo[0]["KinEng"]
    lr.check(ke.max() / 4 <= ke_unit, "(d) gravity: KE per atom stays below m (g h)^2 = %.3g "
             "(largest %.3g)" % (ke_unit, ke.max() / 4))
    vmax = max(float(np.sqrt(f.columns["vx"] ** 2 + f.columns["vy"] ** 2
                             + f.columns["vz"] ** 2).max()) for f in frames)
    lr.check(vmax <= 1.5 * g * dt, "(d) gravity: no sphere faster than 1.5 g h = %.3g (%.3g)"
             % (1.5 * g * dt, vmax))


def test():
    argv = [a for a in sys.argv[1:] if a != "--known-bugs"]
    known_bugs = len(argv) != len(sys.argv) - 1
    args = lr.test_args(__doc__, argv)
    part_a(args)
    part_b(args)
    for options in ("solver apgd", "solver uzawa", "solver uzawa warmstart no", "solver pgs"):
        part_c(args, known_bugs, options)
    part_d(args)
    part_d_row(args, known_bugs)
    part_e(args)


if __name__ == "__main__":
    lr.main(test)
