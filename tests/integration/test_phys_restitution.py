#!/usr/bin/env python3
"""Restitution (keywords `restitution e [I J]`, `bounce vmin`): Newton's law at velocity level
as a target term (core/targets.cpp), on decks whose answer mechanics gives.

1. Head-on pair (two masses, e = 0.5, with a common tangential velocity): at the step where
   the free motion would close the gap, the pair leaves with relative normal speed exactly
   e V (V the approach speed), momentum exact, tangential velocity unchanged, never an overlap;
   then free flight. Type-pair coefficients: with two types, `restitution 0.2` then
   `restitution 0.5 1 2` gives the (1, 2) pair 0.5.
2. e = 0 given explicitly runs the paper's scheme: the same output, to the last bit, as no
   keyword.
3. A ball dropped from height H onto a floor (e = 0.8, g = 1, h = 0.001): its apexes are
   e^2, e^4, e^6 times H within 1 % (the impact's position within a step is not resolved: an
   error of order h V / H); with `bounce 0.9` it bounces exactly as long as its impact speed
   sqrt(2 g H_k) exceeds 0.9 (four times from H = 2), then rests on the floor.
Runs at the rank count ctest gives (np 1/2/4), the pair centred where sub-domains meet.
"""

import math

import numpy as np

import lammps_run as lr
import physics_common as pc
import test_phys_head_on as head_on

TOL = 1e-10
H = 0.1
E = np.array([1.0, 2.0, 2.0]) / 3.0
T = np.array([0.2, -0.1, 0.0])
NSTEPS = 30

# the head-on test's deck, with the keywords under test and an optional type change
PAIR_DECK = head_on.DECK.replace("tol {tol}", "tol {tol} {keywords}").replace(
    "read_data       data.two", "read_data       data.two\n{types}")

BALL_DECK = pc.DROP_ON_FLOOR.format(
    x=0.0, y=0.0, z="{z0}", fix_extra="restitution {e} bounce {vmin}", h=0.001, n="{n}",
    output="variable        z equal z[1]\n"
           "variable        vz equal vz[1]\n"
           "thermo_style    custom step v_z v_vz\n"
           "thermo_modify   format float %.12g\n"
           "thermo          1")


def pair_run(args, name, keywords, e_pair, dens=(1.0, 3.0), types=""):
    r1 = r2 = 0.5
    a1, a2 = 1.0, -0.5
    m1, m2 = pc.sphere_mass(r1, dens[0]), pc.sphere_mass(r2, dens[1])
    x0 = np.array([-1.5 * E, 1.5 * E])
    v0 = np.array([a1 * E + T, a2 * E + T])
    wd = "%s/%s" % (args.workdir, name)
    lr.fresh_workdir(wd)
    pc.write_sphere_data(wd + "/data.two", ((-10, 10), (-10, 10), (-10, 10)), (r1, r2), dens, x0, v0)
    if types:
        # the data file has one type; a second one is made for atom 2
        text = open(wd + "/data.two").read().replace("1 atom types", "2 atom types")
        open(wd + "/data.two", "w").write(text)
    res = lr.run_deck(args.lmp, PAIR_DECK.format(tol=TOL, keywords=keywords, h=H, n=NSTEPS,
                                                  cols=pc.DUMP_COLUMNS, types=types),
                      args.np, wd, timeout=args.timeout)
    frames = lr.read_dump(res.path("dump.atoms"))
    if e_pair is None:
        return res, frames
    size = r1 + r2
    closing = a1 - a2
    D0 = 3.0 - size
    n_c = next(n for n in range(1, 10 ** 6) if D0 - closing * H * (n - 1) < closing * H)
    P = m1 * a1 + m2 * a2
    a1c = (P - m2 * e_pair * closing) / (m1 + m2)
    a2c = a1c + e_pair * closing
    vtol = 10.0 * TOL * size / H
    p0 = m1 * v0[0] + m2 * v0[1]
    worst_v = worst_p = 0.0
    for f in frames:
        x, v = pc.positions(f), pc.velocities(f)
        worst_p = max(worst_p, float(np.abs(m1 * v[0] + m2 * v[1] - p0).max()) / float(np.linalg.norm(p0)))
        dist = float(np.linalg.norm(x[1] - x[0]))
        lr.check((size - dist) / size <= TOL, "%s step %d: no overlap" % (name, f.timestep))
        want = v0 if f.timestep < n_c else np.array([a1c * E + T, a2c * E + T])
        worst_v = max(worst_v, float(np.abs(v - want).max()))
    lr.check(n_c + 3 < NSTEPS, "%s: contact at step %d, within the run" % (name, n_c))
    rel = float(np.dot(pc.velocities(frames[-1])[1] - pc.velocities(frames[-1])[0], E))
    lr.check(worst_v <= vtol, "%s: free flight, then at step %d normal speeds %.6g, %.6g (relative "
             "%.6g = e V with e = %g), tangential unchanged (largest error %.3g <= %.3g)"
             % (name, n_c, a1c, a2c, rel, e_pair, worst_v, vtol))
    lr.check(worst_p <= 1e-13, "%s: momentum exact at every step (%.3g)" % (name, worst_p))
    return res, frames


def ball_apexes(res):
    th = res.thermo[-1]
    z, vz = th["v_z"], th["v_vz"]
    # the top of each flight (resting on the floor, vz is round-off: no flight)
    apex = [float(z[k]) - 0.5 for k in range(1, len(z))
            if vz[k - 1] > 0.0 >= vz[k] and z[k] - 0.5 > 1e-6]
    return apex, float(z[-1]), float(vz[-1])


def test():
    args = lr.test_args(__doc__)

    # 1. head-on pair, then per type pair
    pair_run(args, "pair_e05", "restitution 0.5", 0.5)
    pair_run(args, "pair_types", "restitution 0.2 restitution 0.5 1 2", 0.5,
             types="set atom 2 type 2")

    # 2. e = 0 is the paper's scheme, to the last bit
    _, plain = pair_run(args, "plain", "", None)
    _, zero = pair_run(args, "e0", "restitution 0", None)
    same = all(np.array_equal(pc.positions(a), pc.positions(b)) and
               np.array_equal(pc.velocities(a), pc.velocities(b)) for a, b in zip(plain, zero))
    lr.check(same and len(plain) == len(zero), "restitution 0: the same dump as no keyword, bit for bit")

    # 3. the bouncing ball (serial: one atom)
    if args.np == 1:
        e, H0 = 0.8, 2.0
        res = lr.run_deck(args.lmp, BALL_DECK.format(z0=H0 + 0.5, e=e, vmin=0.0, n=12000), 1,
                          "%s/ball" % args.workdir, timeout=args.timeout)
        apex, _, _ = ball_apexes(res)
        lr.check(len(apex) >= 3, "ball: at least three rebounds (%d)" % len(apex))
        for k in range(3):
            want = e ** (2 * (k + 1)) * H0
            lr.check(abs(apex[k] - want) <= 0.01 * want,
                     "ball: apex %d at %.5g = e^%d H = %.5g within 1 %%" % (k + 1, apex[k], 2 * (k + 1), want))
        vmin = 0.9
        speeds = [math.sqrt(2.0 * H0) * e ** k for k in range(10)]
        expected = sum(1 for s in speeds if s > vmin)
        res = lr.run_deck(args.lmp, BALL_DECK.format(z0=H0 + 0.5, e=e, vmin=vmin, n=14000), 1,
                          "%s/ball_vmin" % args.workdir, timeout=args.timeout)
        apex, z_end, vz_end = ball_apexes(res)
        lr.check(len(apex) == expected, "ball with bounce %g: %d rebounds (impact speeds above "
                 "vmin), got %d" % (vmin, expected, len(apex)))
        lr.check(abs(z_end - 0.5) <= 1e-6 and abs(vz_end) <= 1e-6,
                 "ball with bounce %g: then at rest on the floor (z = %.9g, vz = %.3g)" % (vmin, z_end, vz_end))


if __name__ == "__main__":
    lr.main(test)
