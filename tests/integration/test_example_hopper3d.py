#!/usr/bin/env python3
"""examples/hopper3d (conical hopper, 3d, friction mu 0.5), shortened: 600 glass beads
(d = 1.6-2.4 mm) settle for 0.03 s on the frozen floor in the cone (`wall region hopper`), then
drain for 0.1 s through a 10 mm outlet (h = 1 ms), with fix hardcontact and with the soft twin.

Checked:
  * the two decks hold the same scene and runs sections; they differ in the contacts section
    only (fix hardcontact / pair_style granular + fix wall/gran/region);
  * hard: no bead centre ever outside the cone region and none in the floor layer away from the
    outlet (thermo v_outside, v_through = 0 at every output); in every dump frame each bead is
    clear of the cone's surface by its radius (within 2 tol) and every bead centre in the floor
    layer is within the hole (D/2 + 0.5 mm) of the axis; the frozen floor spheres never move;
  * hard: no solve stopped at maxiter; the largest overlap (f_hc[7]) <= 2 tol at every output;
  * hard: energy: at the end of the settling the kinetic + potential energy is below the
    potential energy at the start (gravity's work is dissipated, never created); friction
    dissipates (f_hc[11] >= 0);
  * beads leave through the outlet: the count above the floor decreases, at a rate
    (examples/hopper3d/beverloo3d.py's fit from 0.05 s after opening) within the Beverloo band
    C = 0.4-1.2, k = 1-2.5 (W = C rho_b sqrt(g) (D - k d)^5/2, rho_b = 0.6 x 2500 kg/m^3), and
    steady: the rates of the two halves of the window within 40 % of each other;
  * soft twin: no bead centre outside the cone (soft beads may squeeze past the outlet's
    floor spheres: not checked), its rate within 0.6-1.6 x the hard one."""

import math
import os
import re
import subprocess
import sys

import numpy as np

import lammps_run as lr

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
EX = os.path.join(ROOT, "examples", "hopper3d")
sys.path.insert(0, EX)
sys.path.insert(0, os.path.join(ROOT, "examples", "common"))
import beverloo3d  # noqa: E402
import granular as g  # noqa: E402
import make_data  # noqa: E402

TOL = 1e-3      # in.hopper3d's default
D = 0.010
RUN = {"outlet": D, "tsettle": 0.03, "tflow": 0.1, "thermo_dt": 0.005, "dump_dt": 0.01,
       "pictures": "no"}


def section(text, start):
    """The lines of a deck between a '# --- <start>' line and the next '# ---' line."""
    m = re.search(r"^# --- %s.*?\n(.*?)^# ---\s*$" % re.escape(start), text, re.S | re.M)
    lr.check(m is not None, "deck has a '# --- %s' section" % start)
    return m.group(1)


def flow_rate(th):
    """Beads per second leaving the hopper, over the window of beverloo3d.rate, and over its
    two halves."""
    t = th["Time"] - th["Time"][0]
    n = th["v_inside"]
    sel = t >= beverloo3d.T_SKIP - 1e-9
    tt, nn = t[sel], n[sel]
    half = len(tt) // 2
    q = -np.polyfit(tt, nn, 1)[0]
    q1 = -np.polyfit(tt[:half + 1], nn[:half + 1], 1)[0]
    q2 = -np.polyfit(tt[half:], nn[half:], 1)[0]
    return q, q1, q2


def check_geometry(frames, name):
    """Every bead clear of the cone by its radius (within 2 tol), below the floor only in the
    outlet; the floor spheres where they started."""
    cos = math.cos(math.atan(make_data.TAN))
    floor0 = {int(i): (x, y, z) for i, x, y, z, t in zip(*(frames[0].columns[k] for k in
                                                            ("id", "x", "y", "z", "type"))) if t == 2}
    worst, below_out, moved = np.inf, 0.0, 0.0
    for _, c, _ in frames:
        b = c["type"] == 1
        x, y, z, r = c["x"][b], c["y"][b], c["z"][b], c["radius"][b]
        rho = np.hypot(x, y)
        clear = (make_data.cone_radius(z) - rho) * cos - r     # distance to the cone - radius
        worst = min(worst, float((clear / r).min()))
        under = (z < 0.0) & (z >= -0.001)      # in the floor layer (below it beads spread)
        if under.any():
            below_out = max(below_out, float(rho[under].max()))
        for i, xx, yy, zz, t in zip(c["id"], c["x"], c["y"], c["z"], c["type"]):
            if t == 2:
                x0 = floor0[int(i)]
                moved = max(moved, abs(xx - x0[0]), abs(yy - x0[1]), abs(zz - x0[2]))
    lr.check(worst >= -2 * TOL, "%s: every bead clear of the cone wall by its radius (smallest "
             "clearance %.3g of the radius)" % (name, worst))
    # the hole cut in the frozen floor has radius D/2 + 0.5 mm; its rim is ragged (1 mm spheres),
    # so a bead passing it may have its centre a little beyond D/2 without touching anything,
    # but not beyond the hole: there the floor spheres leave no room
    lr.check(below_out <= 0.5 * D + 0.0005, "%s: beads cross the floor only in the outlet "
             "(largest distance from the axis %.2f mm <= D/2 + 0.5 mm, the hole)"
             % (name, below_out * 1e3))
    return moved


def test():
    args = lr.test_args(__doc__)
    hard_deck = open(os.path.join(EX, "in.hopper3d")).read()
    soft_deck = open(os.path.join(EX, "in.hopper3d.soft")).read()
    for part in ("the scene", "the runs"):
        lr.check(section(hard_deck, part) == section(soft_deck, part),
                 "in.hopper3d and in.hopper3d.soft hold the same '%s' lines" % part)
    lr.check("hardcontact" in section(hard_deck, "contacts") and
             "wall/gran/region" in section(soft_deck, "contacts"),
             "the decks differ in their contacts: fix hardcontact / pair granular + wall/gran/region")

    data = os.path.join(args.workdir, "data.hopper3d")
    subprocess.check_call([sys.executable, os.path.join(EX, "make_data.py"), data, "600"])
    runs = {}
    for name, deck in (("hard", "in.hopper3d"), ("soft", "in.hopper3d.soft")):
        res = lr.run_deck(args.lmp, os.path.join(EX, deck), args.np, os.path.join(args.workdir, name),
                          variables=dict(RUN, data=data), timeout=args.timeout)
        print("%s: %.1f s" % (deck, res.seconds))
        settle, flow = res.thermo[0], res.thermo[-1]
        for blk in res.thermo:
            lr.check(float(np.abs(blk["v_outside"]).max()) == 0.0,
                     "%s: no bead centre outside the cone" % name)
            # soft beads may squeeze past the rim's floor spheres (seen once on the modern host)
            lr.check(name == "soft" or float(np.abs(blk["v_through"]).max()) == 0.0,
                     "%s: no bead centre in the floor layer beside the outlet" % name)
        lr.check(flow["v_inside"][0] == 600 and flow["v_inside"][-1] < 600,
                 "%s: beads leave through the outlet (%d of 600 left)" % (name, flow["v_inside"][-1]))
        runs[name] = res, flow_rate(flow)
        if name == "soft":
            continue
        for blk in res.thermo:
            lr.check(int(blk["f_hc[6]"][-1]) == 0 and float(blk["f_hc[7]"].max()) <= 2 * TOL,
                     "hard: no maxiter, f_hc[7] <= 2 tol (max %.3g)" % float(blk["f_hc[7]"].max()))
            lr.check(float(blk["f_hc[11]"].min()) >= 0.0, "hard: friction only dissipates")
        e0 = settle["c_pe"][0] + settle["c_ke"][0] + settle["c_rot"][0]
        e1 = settle["c_pe"][-1] + settle["c_ke"][-1] + settle["c_rot"][-1]
        lr.check(e1 < e0, "hard: settling loses energy (kinetic + potential %.4g -> %.4g J)"
                 % (e0, e1))
        print("hard: %.0f iterations per step (mean over the discharge)"
              % float(np.mean(flow["f_hc[1]"][1:])))
        moved = check_geometry(g.read_dump(res.path("hopper3d.dump")), "hard")
        lr.check(moved == 0.0, "hard: the frozen floor spheres never move")

    (q, q1, q2) = runs["hard"][1]
    d, m = 0.002, math.pi / 6 * 8.32e-9 * 2500.0    # mean diameter, mean mass (E[d^3] = 8.32 mm^3)

    def beverloo(C, k):
        return C * 0.6 * 2500.0 * math.sqrt(9.81) * (D - k * d) ** 2.5 / m

    lo, hi = beverloo(0.4, 2.5), beverloo(1.2, 1.0)
    lr.check(lo <= q <= hi, "hard: discharge rate %.0f beads/s within the Beverloo band "
             "%.0f-%.0f" % (q, lo, hi))
    lr.check(abs(q1 - q2) <= 0.4 * max(q1, q2), "hard: steady flow (%.0f and %.0f beads/s over "
             "the two halves)" % (q1, q2))
    qs = runs["soft"][1][0]
    lr.check(0.6 * q <= qs <= 1.6 * q, "soft twin: rate %.0f beads/s, %.2f x the hard one"
             % (qs, qs / q))


if __name__ == "__main__":
    lr.main(test)
