#!/usr/bin/env python3
"""Degenerate geometry: the cases where a gap, a normal or a velocity is exactly zero.

Cases (all default tol 1e-4 unless said, each its own deck, --cases to pick):
  touching:        a 5 x 5 x 5 simple cubic block of spheres (r = 0.5, spacing exactly 1: every
                   neighbour gap is exactly 0 in floating point) with random velocities (seed
                   fixed, mean not removed), no force, no wall, 200 steps of h = 0.05;
  coincident:      two spheres at exactly the same point (one at rest, one moving (0, 1, 0)),
                   and three more at another common point with velocities (1,0,0), (0,0,1), 0;
                   no force, h = 0.05, 200 steps: the normal of a pair at distance 0 is
                   undefined (the fix picks +-x by atom ID); they must separate (all-pairs
                   overlap <= tol in some dump by step 200) without NaN;
  coincident_rest: the same five spheres, everything at rest, no force: doc/fix_hardcontact.md
                   ("Overlaps at the start of a step"): "With no force at all, larger overlaps
                   stay as they are and do not grow": nothing moves, KE stays 0, no NaN;
  walls_touching:  spheres touching the floor and a side wall exactly (centres at r), some
                   also touching each other, sliding along the walls (|v| up to 1) under gravity
                   in a closed box of walls, 300 steps of h = 0.02;
  at_rest:         the touching block of `touching` inside a box of walls touching it exactly,
                   all velocities zero, no force, 100 steps: positions bit-identical, KE exactly
                   0, no contact force;
  chain:           200 spheres of radius 1e-3 touching in a row along x (centres near x = 1:
                   coordinates 500 times the size), the first one moving at 1 into the row,
                   h = 1e-3, 100 steps: all end moving together at m v / M (sticky,
                   restitution 0) within N tol d / h (a solve may leave each of the N
                   contacts off by tol d in predicted gap, i.e. tol d / h in velocity), in
                   order;
  chain_wall:      the same row touching `wall xplane NULL <end>` exactly: everything stops.
Asserted in every case: no lost atom, every thermo and dump value finite, no solve at maxiter,
f_hc[7] <= tol at every step except where the case starts overlapping (coincident*), all-pairs
and wall overlap from the dumps <= tol once separated; where no wall or force acts, momentum
exact (1e-12 of sum m |v|); KE(n) <= KE(0) (1 + 1e-12) without forces (except coincident*:
clearing an initial overlap may add energy by design; its growth is reported, and bounded by
the fastest initial speed: every |v| <= 2 v_max(0)); the case-specific expectations above."""

import sys
from pathlib import Path

import numpy as np

import lammps_run as lr
import stability_common as sc

TOL = 1e-4
ALL = ["touching", "coincident", "coincident_rest", "walls_touching", "at_rest", "chain", "chain_wall"]


def block(n=5, r=0.5):
    return np.array([(i * 2 * r, j * 2 * r, k * 2 * r) for i in range(n) for j in range(n)
                     for k in range(n)], dtype=float), r


def case_setup(case):
    """(x, v, radius, box, boundary, keywords, gravity, h, nsteps, wall_list)"""
    rng = np.random.default_rng(5)
    if case in ("touching", "at_rest"):
        x, r = block()
        n = len(x)
        v = rng.normal(0.0, 1.0, (n, 3)) if case == "touching" else np.zeros((n, 3))
        if case == "touching":
            return x, v, r, ((-3.0, 7.0),) * 3, "s s s", "", 0.0, 0.05, 200, []
        lo, hi = -r, 4 * 2 * r + r    # walls touching the outer spheres exactly
        walls = " ".join("wall %s %r %r" % (p, lo, hi) for p in ("xplane", "yplane", "zplane"))
        wl = [(d, lo, 1) for d in range(3)] + [(d, hi, -1) for d in range(3)]
        return x, v, r, ((lo, hi),) * 3, "f f f", walls, 0.0, 0.05, 100, wl
    if case in ("coincident", "coincident_rest"):
        r = 0.5
        x = np.array([(0.0, 0.0, 0.0), (0.0, 0.0, 0.0), (3.0, 0.5, 0.25), (3.0, 0.5, 0.25),
                      (3.0, 0.5, 0.25)])
        v = np.zeros((5, 3))
        if case == "coincident":
            v[1] = (0.0, 1.0, 0.0)
            v[2] = (1.0, 0.0, 0.0)
            v[3] = (0.0, 0.0, 1.0)
        return x, v, r, ((-5.0, 8.0), (-5.0, 5.0), (-5.0, 5.0)), "s s s", "", 0.0, 0.05, 200, []
    if case == "walls_touching":
        r = 0.5
        # floor z = 0, side walls x = 0 and x = 6, y = 0 and y = 3, lid z = 4
        x = np.array([(r, r, r), (r, 1.0 + r, r), (2.0, r, r), (3.0, 1.5, r), (6.0 - r, 3.0 - r, r),
                      (6.0 - r, 1.5, r), (4.0, 3.0 - r, r), (2.0 + 2 * r, r, r)])
        v = np.array([(0.0, 1.0, 0.0), (0.0, -0.5, 0.0), (1.0, 0.0, 0.0), (-0.7, 0.7, 0.0),
                      (-1.0, 0.0, 0.0), (0.0, -1.0, 0.0), (0.5, 0.0, 0.0), (-1.0, 0.0, 0.0)])
        walls = "wall xplane 0.0 6.0 wall yplane 0.0 3.0 wall zplane 0.0 4.0"
        wl = [(0, 0.0, 1), (0, 6.0, -1), (1, 0.0, 1), (1, 3.0, -1), (2, 0.0, 1), (2, 4.0, -1)]
        return x, v, r, ((0.0, 6.0), (0.0, 3.0), (0.0, 4.0)), "f f f", walls, 1.0, 0.02, 300, wl
    n, r = 200, 1e-3
    x = np.array([(1.0 + k * 2 * r, 0.5, 0.5) for k in range(n)])
    v = np.zeros((n, 3))
    v[0, 0] = 1.0
    end = float(x[-1, 0] + r)
    if case == "chain":
        # y, z fixed (not shrink-wrapped): a shrink-wrapped box of a straight row is 0 thick,
        # which LAMMPS's binning refuses
        return x, v, r, ((0.9, 2.0), (0.4, 0.6), (0.4, 0.6)), "s f f", "", 0.0, 1e-3, 100, []
    return (x, v, r, ((0.9, end), (0.4, 0.6), (0.4, 0.6)), "f f f", "wall xplane NULL %r" % end,
            0.0, 1e-3, 100, [(0, end, -1)])


def run_case(args, case, chk):
    x, v, r, box, boundary, walls, g, h, nsteps, wall_list = case_setup(case)
    n = len(x)
    wd = Path(args.workdir) / case
    wd.mkdir(parents=True, exist_ok=True)
    data = wd / "data.case"
    sc.write_data(data, box, r, 1.0, x, v)
    vmax0 = float(np.linalg.norm(v, axis=1).max())
    skin = max(4.0 * h * max(vmax0, 1e-9) * 2.0, 10 * r * 0.02)
    text = sc.deck("data.case", nsteps, h, skin, "tol %g %s" % (TOL, walls), boundary=boundary,
                   gravity=g, dump_every=max(nsteps // 20, 1), local_every=nsteps)
    res = lr.run_deck(args.lmp, text, args.np, str(wd / "run"), files=[data], timeout=args.timeout)
    label = "%s (%d bodies)" % (case, n)
    chk(not res.errors and len(res.thermo) == 1, "%s: ran without ERROR" % label)
    th = res.thermo[0]
    overlapping_start = case.startswith("coincident")
    frames = lr.read_dump(res.path("dump.atoms"))
    chk(all(sc.all_finite(f) and len(f.columns["id"]) == n for f in frames),
        "%s: every dump frame has %d atoms, all values finite" % (label, n))
    if overlapping_start:
        chk(bool(np.all(th["Atoms"] == n)), "%s: no lost atom" % label)
        chk(all(np.all(np.isfinite(th[c])) for c in th), "%s: every thermo value finite" % label)
        chk(float(th["f_hc[6]"][-1]) == 0.0, "%s: no solve stopped at maxiter" % label)
        ov = float(th["f_hc[7]"].max())
    else:
        ov = sc.check_common(th, n, TOL, label, check=chk)
    ke = th["c_ke"]
    out = dict(overlap=ov, seconds=round(res.seconds, 1))
    if g == 0.0 and not wall_list:
        drift = sc.momentum_drift(th)
        chk(drift <= 1e-12, "%s: momentum exact: drift %.3g of sum m|v| <= 1e-12" % (label, drift))
        out["p_drift"] = drift
    fe = frames[-1]
    xe = sc.positions(fe)
    ovp = sc.pair_overlap(xe, fe.columns["radius"])[0]
    ovw = sc.wall_overlap(xe, fe.columns["radius"], wall_list) if wall_list else 0.0
    if case != "coincident_rest":
        chk(max(ovp, ovw) <= TOL * (1 + 1e-9), "%s: final dump (step %d): all-pairs overlap %.3g, "
            "walls %.3g <= tol" % (label, fe.timestep, ovp, ovw))
    out.update(final_overlap=ovp, final_wall_overlap=ovw)
    if g == 0.0 and not overlapping_start:
        kmax = float(ke.max())
        chk(kmax <= ke[0] * (1 + 1e-12), "%s: KE(n) <= KE(0): max %.17g, KE(0) %.17g" % (label, kmax, ke[0]))
        out["ke_rise_step"] = sc.energy_rises(ke) if ke[0] > 0 else float(ke.max())
    if case == "walls_touching":
        e = ke + th["c_P[5]"]
        m = fe.columns["mass"]
        scale = float(ke[0] + g * (m * fe.columns["radius"]).sum())
        excess = float((e - e[0]).max()) / scale
        chk(excess <= 1e-9, "%s: KE + PE <= its initial value: excess %.3g of scale" % (label, excess))
        ve = sc.velocities(fe)
        chk(float(np.abs(ve[:, 2]).max()) <= 10 * TOL * r / h,
            "%s: all resting on the floor at the end: max |v_z| %.3g <= 10 tol r / h" % (label, np.abs(ve[:, 2]).max()))
        lf = lr.read_dump_local(res.path("dump.local"))[-1]
        wall_no = lf.columns["f_hc[7]"]
        floor = lf.columns["f_hc[3]"][wall_no == 5]
        chk(len(floor) == n and float(np.abs(floor / (m[0] * g) - 1).max()) <= 1e-6,
            "%s: the floor (wall 5) carries every sphere's weight m g: %d rows, rel err %.3g" %
            (label, len(floor), float(np.abs(floor / (m[0] * g) - 1).max()) if len(floor) else -1))
        out["e_excess"] = excess
    if case == "at_rest":
        x0 = sc.positions(frames[0])
        same = all(np.array_equal(sc.positions(f), x0) for f in frames)
        chk(same, "%s: positions bit-identical over %d steps" % (label, nsteps))
        chk(float(np.abs(th["c_ke"]).max()) == 0.0, "%s: KE exactly 0 at every step" % label)
        chk(float(th["f_hc[4]"].max()) == 0.0, "%s: no active contact (f_hc[4] = 0)" % label)
        out["rows"] = int(th["f_hc[3]"].max())
    if overlapping_start:
        vmax = float(th["c_vmax"].max())
        chk(vmax <= 2 * max(vmax0, 0.0) + 1e-12, "%s: every speed <= 2 v_max(0): max %.3g, v_max(0) %.3g"
            % (label, vmax, vmax0))
        if case == "coincident":
            sep = [int(f.timestep) for f in frames if sc.pair_overlap(sc.positions(f), f.columns["radius"])[0] <= TOL]
            first = min(sep) if sep else None
            chk(first is not None, "%s: the coincident spheres separate (all-pairs overlap <= tol "
                "from step %s on)" % (label, first))
            out.update(separated_by_step=first, ke_end_over_ke0=float(ke[-1] / ke[0]), vmax=vmax)
        else:
            x0 = sc.positions(frames[0])
            chk(all(np.array_equal(sc.positions(f), x0) for f in frames),
                "%s: nothing moves (positions bit-identical)" % label)
            chk(float(th["c_ke"].max()) == 0.0, "%s: KE stays exactly 0" % label)
    if case in ("chain", "chain_wall"):
        ve = sc.velocities(fe)
        m = fe.columns["mass"]
        vexp = 0.0 if case == "chain_wall" else float(m[0] * 1.0 / m.sum())
        err = float(np.abs(ve[:, 0] - vexp).max())
        # a solve may leave a predicted gap error of tol (2 r) per contact: a velocity error of
        # tol 2 r / h per contact along the row
        bound = n * TOL * 2 * r / h
        chk(err <= bound, "%s: all move together at %.6g: max |v_x - that| %.3g <= N tol d / h = %.3g"
            % (label, vexp, err, bound))
        ordered = all(bool(np.all(np.diff(f.columns["x"]) > 0)) for f in frames)
        chk(ordered, "%s: the row keeps its order (no sphere passes through another)" % label)
        out.update(v_err=err, v_expected=vexp)
    out["max_iter"] = int(th["f_hc[1]"].max())
    sc.report("degenerate_%s_np%d" % (case, args.np), **out)


def test():
    argv = list(sys.argv[1:])
    cases = ALL
    if "--cases" in argv:
        k = argv.index("--cases")
        cases = argv[k + 1].split(",")
        del argv[k:k + 2]
    args = lr.test_args(__doc__, argv)
    chk = sc.Checks()
    for case in cases:
        try:
            run_case(args, case, chk)
        except lr.LammpsRunError as e:
            chk(False, "%s: LAMMPS failed: %s" % (case, " | ".join(
                l.strip() for l in str(e).splitlines() if "ERROR" in l or "exit status" in l)[:800]))
    chk.finish()


if __name__ == "__main__":
    lr.main(test)
