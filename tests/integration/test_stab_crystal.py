#!/usr/bin/env python3
"""Dense crystals squeezed by gravity in a box of walls: redundant contacts (the paper's
example of non-unique multipliers, section 4 before Lemma 1).

2d: hexagonal discs (fix enforce2d), r = 0.5, rows of 10 and 9 alternately (the rows of 10
touch each other and both side walls: `wall xplane 0 10`), 12 rows; 3d: FCC spheres stacked as
(100) layers of 4 x 4 and 3 x 3 in a 4 x 4 (diameters) box, 7 layers. Every interior body has
6 (2d) / 12 (3d) contacts for 2 / 3 degrees of freedom. The rows start 0.02 apart vertically at
rest and fall under gravity (g = 1, h = 0.01) onto the floor and onto each other; after
NSETTLE steps the crystal is at rest and is followed for --steps more steps (1000 in CI,
10^4 in the soak variant). tol = 1e-6 (tighter than the default so that "at rest" is sharp).

Asserted after settling (d = 2 r, L = rows or layers):
  at rest: every |v| <= 10 tol d / h (a solve may leave a predicted gap error of tol d per
     step, i.e. a velocity tol d / h);
  the ideal crystal: every centre within L tol d of its ideal lattice site (each of the L
     contacts below it may be off by tol d);
  unique velocities / positions (Lemma 1, Prop. 5: u is unique even when mu is not): the runs
     apgd + warmstart yes, apgd + warmstart no, uzawa (the paper's solver, warm), cg (warm) and exact
     (active set, machine precision; serial only) end at the same positions within L tol d;
  no creep: no centre moves more than L tol d between the end of settling and the end of the
     run (10^3 or 10^4 steps);
  the determinate part of the forces: at every 100th step the floor carries the weight of the
     crystal and the side walls' loads cancel, to L tol m_total g (each of the L rows in series
     may leave a velocity error tol g h, core/residual.h);
  bounded multipliers: no multiplier drifts (the largest force over the last tenth of the run
     <= 1.25 x its value after settling). The split of the load between the wall-to-wall rows
     and the rest is not asserted: two opposite walls are outside Lemma 1, a wall-to-wall row
     can carry any self-stress without changing u, and every solver, the exact one included,
     keeps some (measured and reported as force_over_column: the largest contact force over
     the weight of the column above it, centres higher than the contact point and within 2 d
     horizontally);
  feasibility: f_hc[7] <= tol at every step; no solve stopped at maxiter; no lost atom.
The rows from wall to wall make these crystals the hard case of kept overlaps (without
friction, warm solvers: src/core/kept_overlaps.h): a kept overlap leaves a slack in a tight
loop and solves stall on it, so such a solve goes on with cleared targets after its budget of
iterations (4 x what recent cleared steps took, 50 to maxiter / 10); the checks above hold for
the result, and MEASURED reports how many solves did (kept_undone, f_hc[12]).
On 2 ranks (np 2 registration): the same checks, and the final positions compared with a serial
apgd_cold run of the same data file (within L tol d)."""

from pathlib import Path

import numpy as np

import lammps_run as lr
import stability_common as sc

R = 0.5
D = 2 * R
G = 1.0
H = 0.01
TOL = 1e-6
GAP = 0.02
NSETTLE = 500
VARIANTS = {
    "apgd_warm": "solver apgd warmstart yes",
    "apgd_cold": "solver apgd warmstart no",
    "uzawa_warm": "solver uzawa warmstart yes",
    "cg_warm": "solver cg warmstart yes",
    "exact": "solver exact",    # machine precision, one processor: the reference
}


def geometry(dim):
    if dim == 2:
        ncol, nrow = 10, 12
        x0 = sc.hex_lattice_2d(ncol, nrow, R, GAP)
        ideal = sc.hex_lattice_2d(ncol, nrow, R, 0.0)
        width = D * ncol
        top = x0[:, 1].max() + 5.0
        box = ((0.0, width), (0.0, top), (-0.5, 0.5))
        walls = "wall xplane 0.0 %r wall yplane 0.0 %r" % (width, top)
        return x0, ideal, box, walls, nrow, "f f p"
    n, nlayer = 4, 7
    x0 = sc.fcc_lattice(n, nlayer, R, GAP)
    ideal = sc.fcc_lattice(n, nlayer, R, 0.0)
    width = D * n
    top = x0[:, 2].max() + 5.0
    box = ((0.0, width), (0.0, width), (0.0, top))
    walls = "wall xplane 0.0 %r wall yplane 0.0 %r wall zplane 0.0 %r" % (width, width, top)
    return x0, ideal, box, walls, nlayer, "f f f"


def column_weight_bound(x, mass, dim, rows):
    """For each contact row [i, j, f, nx, ny, nz, wall] the weight G sum m of the column above
    it: the bodies whose centre is higher than (contact point - r), i.e. the contact's own
    bodies and everything above them, and within 2 d of it horizontally."""
    up = 1 if dim == 2 else 2
    hor = [0] if dim == 2 else [0, 1]
    out = []
    for i, j, _, nx, ny, nz, _w in rows:
        xi = x[i - 1]
        n = np.array([nx, ny, nz])
        c = xi + R * n    # the contact point (from i towards j or the wall)
        above = x[:, up] >= c[up] - R - 1e-9    # the contact's own bodies and all above
        near = np.sqrt(((x[:, hor] - c[hor]) ** 2).sum(axis=1)) <= 2 * D
        out.append(G * float(mass[above & near].sum()))
    return np.array(out)


def test():
    args = lr.test_args(__doc__, extra=[
        ("--dim", dict(type=int, default=2, choices=(2, 3))),
        ("--steps", dict(type=int, default=1000, help="steps at rest after settling")),
        ("--variants", dict(default=",".join(VARIANTS), help="comma-separated, of %s" % ",".join(VARIANTS)))])
    dim, nsteps, variants = args.dim, args.steps, args.variants.split(",")
    x0, ideal, box, walls, layers, boundary = geometry(dim)
    natoms = len(x0)
    data = Path(args.workdir) / "data.crystal"
    sc.write_data(data, box, R, 1.0, x0)
    total = NSETTLE + nsteps
    bound_pos = layers * TOL * D
    bound_v = 10 * TOL * D / H
    finals = {}
    chk = sc.Checks()
    for name in variants:
        label = "%dd crystal (%d bodies, %s)" % (dim, natoms, name)
        text = sc.deck("data.crystal", total, H, 0.3, "tol %g %s %s" % (TOL, VARIANTS[name], walls),
                       dim=dim, boundary=boundary, gravity=G, dump_every=100, local_every=100)
        res, th = sc.run(args, text, "%s/%s" % (args.workdir, name), data)
        ov = sc.check_common(th, natoms, TOL, label, check=chk)

        frames = [f for f in lr.read_dump(res.path("dump.atoms")) if f.timestep >= NSETTLE]
        local = {f.timestep: f for f in lr.read_dump_local(res.path("dump.local"))}
        vmax = max(float(np.linalg.norm(sc.velocities(f), axis=1).max()) for f in frames)
        chk(vmax <= bound_v, "%s: at rest after settling: max |v| %.3g <= 10 tol d / h = %.3g"
                 % (label, vmax, bound_v))
        x_settled = sc.positions(frames[0])
        x_end = sc.positions(frames[-1])
        dev = float(np.linalg.norm(x_end - ideal, axis=1).max())
        chk(dev <= bound_pos, "%s: the ideal crystal: max |x - site| %.3g <= L tol d = %.3g"
                 % (label, dev, bound_pos))
        creep = max(float(np.linalg.norm(sc.positions(f) - x_settled, axis=1).max()) for f in frames)
        chk(creep <= bound_pos, "%s: no creep over %d steps: max |x(t) - x(%d)| %.3g <= %.3g"
                 % (label, nsteps, NSETTLE, creep, bound_pos))
        mass = frames[0].columns["mass"]
        weight = float(mass.sum()) * G
        up = dim - 1    # gravity acts along -y (2d) or -z (3d)
        bound_eq = layers * TOL * weight
        worst_ratio, worst_row, worst_step, fmax, worst_eq = 0.0, None, None, [], (0.0, None, "")
        for f in frames:
            lf = local.get(f.timestep)
            chk(lf is not None, "%s: dump local frame at step %d" % (label, f.timestep))
            if lf is None:
                continue
            cols = [lf.columns["f_hc[%d]" % k] for k in range(1, 8)]
            rows = [[int(cols[0][r]), int(cols[1][r])] + [float(cols[k][r]) for k in range(2, 6)]
                    + [int(cols[6][r])] for r in range(len(cols[0]))]
            forces = np.array([r_[2] for r_ in rows])
            fmax.append(float(forces.max()))
            ratio = forces / column_weight_bound(sc.positions(f), mass, dim, rows)
            k = int(np.argmax(ratio))
            if ratio[k] > worst_ratio:
                worst_ratio, worst_row, worst_step = float(ratio[k]), rows[k], f.timestep
            # the wall loads: force times the normal (body -> wall) is the push on the wall
            load = np.zeros(3)
            for r_ in rows:
                if r_[6] > 0:
                    load += r_[2] * np.array(r_[3:6])
            err = [abs(load[up] + weight)] + [abs(load[a]) for a in range(dim) if a != up]
            if max(err) > worst_eq[0]:
                worst_eq = (max(err), f.timestep, "floor %.9g vs weight %.9g, side balance %s"
                            % (-load[up], weight, ["%.3g" % load[a] for a in range(dim) if a != up]))
        chk(worst_eq[0] <= bound_eq,
            "%s: the walls carry the weight: floor load = weight and the side walls balance, to "
            "L tol m_total g: largest error %.3g <= %.3g (step %s: %s)"
            % (label, worst_eq[0], bound_eq, worst_eq[1], worst_eq[2]))
        tail = fmax[-max(1, len(fmax) // 10):]
        chk(max(tail) <= 1.25 * fmax[0],
            "%s: no multiplier drift: largest contact force over the last tenth of the run "
            "%.4g <= 1.25 x its value after settling %.4g" % (label, max(tail), fmax[0]))
        finals[name] = x_end
        sc.report("crystal_%dd_np%d_%s" % (dim, args.np, name), bodies=natoms, steps=nsteps,
                  overlap=ov, vmax=vmax, dev_ideal=dev, creep=creep, force_over_column=worst_ratio, wall_load_err=worst_eq[0], fmax_settled=fmax[0], fmax_end=fmax[-1],
                  active_contacts=int(th["f_hc[4]"][-1]), dof=dim * natoms,
                  max_iter_settled=int(th["f_hc[1]"][NSETTLE:].max()),
                  mean_iter_settled=float(th["f_hc[1]"][NSETTLE:].mean()),
                  kept_undone=int(th["f_hc[12]"][-1]),
                  seconds=round(res.seconds, 1))
    if args.np > 1:
        # the same scene on one rank (apgd, cold: deterministic): the settled crystal does not
        # depend on the number of ranks beyond the tolerance
        text = sc.deck("data.crystal", total, H, 0.3, "tol %g %s %s" % (TOL, VARIANTS["apgd_cold"], walls),
                       dim=dim, boundary=boundary, gravity=G, dump_every=total)
        res, th = sc.run(args, text, "%s/serial_reference" % args.workdir, data, np_=1)
        x1 = sc.positions(lr.read_dump(res.path("dump.atoms"))[-1])
        for name, x_end in finals.items():
            diff = float(np.linalg.norm(x_end - x1, axis=1).max())
            chk(diff <= bound_pos, "%dd crystal: %s on %d ranks and apgd_cold on 1 rank end at the "
                "same positions: max diff %.3g <= L tol d = %.3g" % (dim, name, args.np, diff, bound_pos))
            sc.report("crystal_%dd_np%d_vs_np1_%s" % (dim, args.np, name), diff=diff)
    names = list(finals)
    for a in names[1:]:
        diff = float(np.linalg.norm(finals[a] - finals[names[0]], axis=1).max())
        chk(diff <= bound_pos, "%dd crystal: %s and %s end at the same positions: max diff "
                 "%.3g <= L tol d = %.3g" % (dim, names[0], a, diff, bound_pos))
        sc.report("crystal_%dd_np%d_unique_%s_vs_%s" % (dim, args.np, names[0], a), diff=diff)
    chk.finish()


if __name__ == "__main__":
    lr.main(test)
