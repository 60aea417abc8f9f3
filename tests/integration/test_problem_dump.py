#!/usr/bin/env python3
"""The developers' problem dump (HARDCONTACT_DUMP_PROBLEMS, src/core/problem_dump.h, used by
bench/studies/spectrum/run.sh) writes the problem the solver was given: 27 spheres with random
velocities in a box with a floor, under gravity, 12 steps at tol 1e-10, serially and under
mpirun (one file per rank, prefix.<step>.<rank>). For every step:
  * the bodies are the dumped atoms: 1/m and u_free = v^n + h g (v^n from the atom dump of the
    step before) to round-off - which also maps each rank's local indices to atom IDs;
  * every row's normal is the unit vector from i to j (the floor: -z), its gap the distance of
    the surfaces at q^n, its size r_i + r_j (r_i for the floor), every scale positive, and a
    row held by two ranks is the same row on both;
  * the problem rebuilt from the files alone (A = h^2 G M^-1 G^T, b = gap + h G u_free), solved
    to round-off here (projected Gauss-Seidel), gives the velocities LAMMPS dumps after the step
    (within 1e-6 of the largest speed: the fix stops at tol 1e-10 of its scales);
  * the rows that push in that solution overlap in nothing (no row missing).
A prefix in a directory that does not exist stops the run with an ERROR that names the file."""

import glob
import re

import numpy as np

import lammps_run as lr
import physics_common as pc

H = 0.05
TOL = 1e-10
STEPS = 12
R = 0.5

DECK = lr.preamble() + """
read_data       data.spheres
pair_style      none
neighbor        0.5 bin
fix             grav all gravity 1.0 vector 0 0 -1
fix             hc all hardcontact tol {tol} wall zplane 0.0 NULL
timestep        {h}
dump            d all custom 1 dump.atoms id radius mass x y z vx vy vz
dump_modify     d format float %.17g sort id
thermo          1
run             {n}
"""


def scene():
    rng = np.random.default_rng(7)
    g = np.arange(3) * 1.06 + 1.0
    x = np.array([[a, b, c] for c in g for b in g for a in g])
    x[:, 2] -= 0.5 - R + 1e-3    # the bottom layer just above the floor
    v = rng.uniform(-0.6, 0.6, size=x.shape)
    return x, v


def load(path):
    with open(path) as f:
        head = f.readline().split()
        lr.check(head[:2] == ["hardcontact-problem", "1"], "%s: header" % path)
        nb, n_owned, nr = (int(t) for t in head[2:5])
        h, tol = float(head[5]), float(head[6])
        bodies = np.array([[float(t) for t in f.readline().split()] for _ in range(nb)]).reshape(nb, 4)
        rows = np.array([[float(t) for t in f.readline().split()] for _ in range(nr)]).reshape(nr, 9)
    return dict(n_owned=n_owned, h=h, tol=tol, bodies=bodies, rows=rows)


def solve(inv_mass, u_free, rows, h, sweeps=20000):
    """Projected Gauss-Seidel on the rebuilt dual to round-off; rows: (i, j, n, gap), j = -1
    for the floor. Returns u after the step and mu."""
    u = u_free.copy()
    mu = np.zeros(len(rows))
    for _ in range(sweeps):
        change = 0.0
        for k, (i, j, n, gap) in enumerate(rows):
            rel = -u[i] + (u[j] if j >= 0 else 0.0)
            g = gap + h * n @ rel
            a = h * h * (inv_mass[i] + (inv_mass[j] if j >= 0 else 0.0))
            new = max(0.0, mu[k] - g / a)
            d = new - mu[k]
            if d != 0.0:
                u[i] -= h * d * inv_mass[i] * n
                if j >= 0:
                    u[j] += h * d * inv_mass[j] * n
                mu[k] = new
                change = max(change, abs(d) * a)
        if change < 1e-17:
            break
    return u, mu


def run(args):
    x, v = scene()
    n = len(x)
    box = ((0.0, 5.0), (0.0, 5.0), (0.0, 5.0))
    wd = args.workdir + "/dump"
    lr.fresh_workdir(wd)
    pc.write_sphere_data(wd + "/data.spheres", box, R, 1.0, x, v)
    prefix = wd + "/problem"
    res = lr.run_deck(args.lmp, DECK.format(tol=TOL, h=H, n=STEPS), args.np, wd,
                      env={"HARDCONTACT_DUMP_PROBLEMS": prefix}, timeout=args.timeout)
    lr.check("HARDCONTACT_DUMP_PROBLEMS is set" in res.stdout, "the run warns that it dumps")
    frames = lr.read_dump(res.path("dump.atoms"))
    mass = frames[0].columns["mass"]
    pushing_steps = 0
    for step in range(1, STEPS + 1):
        files = sorted(glob.glob("%s.%d" % (prefix, step)) + glob.glob("%s.%d.*" % (prefix, step)))
        lr.check(len(files) == (1 if args.np == 1 else args.np),
                 "step %d: one file per rank (%s)" % (step, [f.rsplit("/", 1)[1] for f in files]))
        before, after = frames[step - 1], frames[step]
        xb, vb = pc.positions(before), pc.velocities(before)
        u_want = vb + H * np.array([0.0, 0.0, -1.0])
        rows = {}
        for f in files:
            P = load(f)
            lr.check(P["h"] == H and P["tol"] == TOL, "%s: h and tol of the deck" % f)
            # bodies -> atoms by u_free (random velocities: one match each)
            ids = []
            for b in P["bodies"]:
                dist = np.abs(u_want - b[1:4]).max(axis=1)
                k = int(np.argmin(dist))
                lr.check(dist[k] <= 1e-13 and abs(b[0] * mass[k] - 1.0) <= 1e-13,
                         "%s: a body is atom %d (u_free = v^n + h g, 1/m)" % (f, k + 1))
                ids.append(k)
            lr.check(len(set(ids[:P["n_owned"]])) == P["n_owned"], "%s: owned bodies distinct" % f)
            for r in P["rows"]:
                i, j = ids[int(r[0])], (ids[int(r[1])] if r[1] >= 0 else -1)
                nrm, gap, size, scale = r[2:5], r[5], r[6], r[7]
                if j >= 0:
                    d = xb[j] - xb[i]
                    want_n, want_gap, want_size = d / np.linalg.norm(d), np.linalg.norm(d) - 2 * R, 2 * R
                else:
                    want_n, want_gap, want_size = np.array([0.0, 0.0, -1.0]), xb[i, 2] - R, R
                lr.check(np.abs(nrm - want_n).max() <= 1e-12 and abs(gap - want_gap) <= 1e-12
                         and size == want_size and scale > 0,
                         "step %d: row (%d, %s): normal, gap %.6g, size, scale" % (step, i + 1, j + 1, gap))
                key = (min(i, j), max(i, j)) if j >= 0 else (i, -1)
                row = (i, j, nrm, gap)
                if key in rows:
                    lr.check(np.abs(rows[key][2] - (nrm if rows[key][0] == i else -nrm)).max() <= 1e-15
                             and abs(rows[key][3] - gap) <= 1e-15,
                             "step %d: row %s the same on both ranks" % (step, key))
                rows[key] = row
        u, mu = solve(1.0 / mass, u_want, list(rows.values()), H)
        vmax = np.abs(u).max()
        err = np.abs(u - pc.velocities(after)).max()
        lr.check(err <= 1e-6 * vmax, "step %d: %d rows; the rebuilt problem's velocities are "
                 "LAMMPS's after the step (largest difference %.3g of %.3g)" % (step, len(rows), err, vmax))
        pushing_steps += int((mu > 0).sum() > 0)
    lr.check(pushing_steps >= STEPS // 2, "contacts pushed in %d of %d steps" % (pushing_steps, STEPS))

    # a prefix nobody can write
    wd2 = args.workdir + "/bad"
    lr.fresh_workdir(wd2)
    pc.write_sphere_data(wd2 + "/data.spheres", box, R, 1.0, x, v)
    res = lr.run_deck(args.lmp, DECK.format(tol=TOL, h=H, n=2), args.np, wd2, expect_error=True,
                      env={"HARDCONTACT_DUMP_PROBLEMS": wd2 + "/no/such/dir/p"}, timeout=args.timeout)
    out = res.stdout + res.stderr
    lr.check(re.search(r"ERROR.*cannot write .*no/such/dir/p\.1.*HARDCONTACT_DUMP_PROBLEMS", out)
             is not None, "an unwritable prefix: an ERROR naming the file")


if __name__ == "__main__":
    lr.main(lambda: run(lr.test_args(__doc__)))
