#!/usr/bin/env python3
"""Twisting resistance (`twisting mut [I J]`, core/laws/twisting.h): a torque about the contact
normal, at most mut R F_n (R = r_i r_j / (r_i + r_j), r_i against a wall), opposing the pair's
relative spin about the normal. At the rank count ctest gives (np 1/2/4), on every host (the
spins start from the data file: LIGGGHTS 3.8's set has no omega).

1. A sphere (r = 0.5, density 1, g = 1, h = 0.01) spinning at w0 = 2 about the vertical on a
   floor, `friction 0.5 twisting 0.1`: the floor's torque mut r m g against I = 2/5 m r^2
   decelerates it at 5/2 mut g / r = 0.5, so omega_z = w0 - 5/2 mut g t / r, and it stops at
   t* = 2 w0 r / (5 mut g) = 4 (step 400), then stays at rest; the energy the contact
   dissipates (f_hc[11] summed over the run) is 1/2 I w0^2; the centre does not move (a spin
   about the normal does not slide the contact point). Without `twisting` the spin stays w0 to
   round-off: Coulomb friction has no torque about the normal.
2. Rolling and twisting together (`friction 0.5 rolling 0.1 twisting 0.1`, the law of three
   discs): a sphere launched rolling at v0 = 0.5 (omega_y = v0 / r) while spinning at w0 about
   the vertical. The rolling torque is about the tangents, the twisting one about the normal,
   so each decelerates as it would alone: v = v0 - 5/7 mur g t until t = 7 v0 / (5 mur g) = 7,
   omega_z as in 1; the centre stays at height r.
3. Two equal spheres meeting head-on along x (no gravity, no wall) at +-v0 = 0.5, spinning at
   -+w0 about x, `friction 0.5 twisting 0.1`: the collision's normal impulse totals m v0 (they
   end at rest, touching), so a twist that slides throughout changes each spin by
   mut R m v0 / I = 5/4 mut v0 / r (R = r / 2): w0 = 2 ends at 1.875. With w0 = 0.05 the impulse
   can stop the twist (it needs I w0 < mut R m v0) and both spins end at 0. At every step the
   angular momentum about x, I (w_1 + w_2), is 0 to round-off; f_hc[11] summed is the
   rotational energy lost, I/2 sum (w0^2 - w1^2), to 1e-9.
Bounds: speeds and spins within 1e-6 plus what the kept overlap (tol / 10 of a contact's size,
doc/fix_hardcontact.md) does to the arms (relative KEPT x TOL); energies within 1e-6
relative; the pair's speeds after the collision within tol x v0 (the solver's stopping test,
core/residual.h: under mpirun the solve is not exact to round-off as it is serially)."""

import math

import numpy as np

import lammps_run as lr
import physics_common as pc

H = 0.01
TOL = 1e-4
KEPT = 0.1
R = 0.5
MU, MUR, MUT = 0.5, 0.1, 0.1
W0 = 2.0

DECK = """read_data       data.spin
pair_style      none
neighbor        0.5 bin
fix             hc all hardcontact tol 0.0001 {keywords}
{gravity}
timestep        {h}
compute         wx all property/atom omegax
compute         wy all property/atom omegay
compute         wz all property/atom omegaz
compute         sx all reduce sum c_wx
compute         sy all reduce sum c_wy
compute         sz all reduce sum c_wz
variable        x equal x[1]
variable        y equal y[1]
variable        z equal z[1]
variable        vx equal vx[1]
thermo_style    custom step v_x v_y v_z v_vx c_sx c_sy c_sz f_hc[11]
thermo_modify   format float %.15g
thermo          1
dump            d all custom {dump_every} dump.atoms id x y z vx vy vz omegax omegay omegaz
dump_modify     d format float %.17g sort id
run             {n}
"""


def run(args, name, keywords, x, v, w, n, floor=True):
    """The deck with spheres of radius R at x (velocities v, spins w); a floor at z = 0 under
    g = 1 (periodic in x, y) or free space (boundary f)."""
    wd = lr.fresh_workdir("%s/%s" % (args.workdir, name))
    box = ((-4.0, 4.0), (-2.0, 2.0), (0.0, 4.0)) if floor else ((-3.0, 3.0), (-2.0, 2.0), (-2.0, 2.0))
    pc.write_sphere_data(wd / "data.spin", box, [R] * len(x), 1.0, x, v, host=args.lmp,
                         title="twisting test", omega=w)
    deck = lr.preamble("p p f" if floor else "f f f", ghost_velocities=True) + DECK.format(
        keywords=keywords + (" wall zplane 0 NULL" if floor else ""),
        gravity="fix             g all gravity 1.0 vector 0 0 -1" if floor else "",
        h=H, n=n, dump_every=1 if not floor else n)
    res = lr.run_deck(args.lmp, deck, args.np, wd, timeout=args.timeout)
    th = res.thermo[-1]
    return wd, th, np.asarray(th["Step"], dtype=float) * H


def inertia(r=R):
    return 0.4 * pc.sphere_mass(r, 1.0) * r * r


def spin_stop(args):
    t_stop = 2.0 * W0 * R / (5.0 * MUT)
    _, th, t = run(args, "spin_stop", "friction %g twisting %g" % (MU, MUT),
                   [[0.0, 0.0, R]], [[0.0, 0.0, 0.0]], [[0.0, 0.0, W0]], n=600)
    wz = np.asarray(th["c_sz"])
    want = np.maximum(W0 - 2.5 * MUT * t / R, 0.0)
    err = float(np.abs(wz - want).max())
    bound = 1e-6 + W0 * KEPT * TOL
    lr.check(err <= bound,
             "spin_stop: omega_z = w0 - 5/2 mut g t / r, at rest from t* = %g (largest error "
             "%.3g, bound %.3g; omega_z %.6g at t = 3.9, %.3g at the end)"
             % (t_stop, err, bound, wz[int(round(3.9 / H))], wz[-1]))
    dissipated = float(np.sum(th["f_hc[11]"]))
    want_e = 0.5 * inertia() * W0 * W0
    lr.check(abs(dissipated - want_e) <= 1e-6 * want_e,
             "spin_stop: the contact dissipates 1/2 I w0^2 = %.9g (f_hc[11] summed: %.9g)"
             % (want_e, dissipated))
    moved = max(float(np.abs(th["v_x"]).max()), float(np.abs(th["v_y"]).max()))
    lr.check(moved <= 1e-9, "spin_stop: the centre stays put (largest |x|, |y| %.3g)" % moved)
    dz = float(np.abs(np.asarray(th["v_z"]) - R).max())
    lr.check(dz <= 1e-6 + KEPT * TOL * R, "spin_stop: centre at height r (error %.3g)" % dz)
    # without the keyword: nothing resists the spin
    _, th0, _ = run(args, "spin_free", "friction %g" % MU, [[0.0, 0.0, R]], [[0.0, 0.0, 0.0]],
                    [[0.0, 0.0, W0]], n=200)
    drift = float(np.abs(np.asarray(th0["c_sz"]) - W0).max())
    lr.check(drift <= 1e-12, "spin_free: without twisting the spin stays w0 (drift %.3g)" % drift)


def roll_and_spin(args):
    v0 = 0.5
    _, th, t = run(args, "roll_and_spin",
                   "friction %g rolling %g twisting %g" % (MU, MUR, MUT),
                   [[-3.0, 0.0, R]], [[v0, 0.0, 0.0]], [[0.0, v0 / R, W0]], n=800)
    vx, wy, wz = np.asarray(th["v_vx"]), np.asarray(th["c_sy"]), np.asarray(th["c_sz"])
    want_v = np.maximum(v0 - 5.0 / 7.0 * MUR * t, 0.0)
    want_w = np.maximum(W0 - 2.5 * MUT * t / R, 0.0)
    ev = float(np.abs(vx - want_v).max())
    ew = float(np.abs(wz - want_w).max())
    roll = float(np.abs(wy * R - vx).max())
    bound_v = 1e-6 + v0 * KEPT * TOL
    bound_w = 1e-6 + W0 * KEPT * TOL
    lr.check(ev <= bound_v and ew <= bound_w,
             "roll_and_spin: rolling decelerates at 5/7 mur g (stops at t = %g) and the spin at "
             "5/2 mut g / r (stops at t = %g), each as alone (errors %.3g, %.3g; bounds %.3g, %.3g)"
             % (7.0 * v0 / (5.0 * MUR), 2.0 * W0 * R / (5.0 * MUT), ev, ew, bound_v, bound_w))
    lr.check(roll <= 1e-5, "roll_and_spin: it rolls without slipping (|omega_y r - v| %.3g)" % roll)
    dz = float(np.abs(np.asarray(th["v_z"]) - R).max())
    lr.check(dz <= 1e-6 + KEPT * TOL * R, "roll_and_spin: centre at height r (error %.3g)" % dz)


def pair(args, name, w0):
    v0 = 0.5
    wd, th, _ = run(args, name, "friction %g twisting %g" % (MU, MUT),
                    [[-1.0, 0.1, 0.2], [1.0, 0.1, 0.2]], [[v0, 0.0, 0.0], [-v0, 0.0, 0.0]],
                    [[w0, 0.0, 0.0], [-w0, 0.0, 0.0]], n=250, floor=False)
    frames = lr.read_dump(wd / "dump.atoms")
    inert = inertia()
    worst_l = 0.0
    for f in frames:
        wx = np.asarray(f.columns["omegax"])
        worst_l = max(worst_l, abs(inert * float(wx.sum())))
    lr.check(worst_l <= 1e-14 * inert * w0,
             "%s: angular momentum about x exact at every step (|I (w1 + w2)| %.3g)" % (name, worst_l))
    last = frames[-1]
    wx = np.asarray(last.columns["omegax"])
    speed = float(np.abs(pc.velocities(last)).max())
    gap = float(np.linalg.norm(pc.positions(last)[1] - pc.positions(last)[0])) - 2.0 * R
    # the solve that ends the collision leaves the normal speed within tol of the free speed
    # scale (core/residual.h); nothing acts after it, so a residual speed opens the gap
    t_end = frames[-1].timestep * H
    lr.check(speed <= TOL * v0 and -TOL * 2.0 * R <= gap <= TOL * v0 * t_end,
             "%s: the spheres end at rest, touching (speed %.3g, bound %.3g; gap %.3g, bound %.3g)"
             % (name, speed, TOL * v0, gap, TOL * v0 * t_end))
    dw = 1.25 * MUT * v0 / R
    want = max(w0 - dw, 0.0)
    err = float(np.abs(np.abs(wx) - want).max())
    lr.check(err <= 1e-6 + w0 * KEPT * TOL,
             "%s: spins end at %.6g (%s; got %s, error %.3g)"
             % (name, want, "w0 - 5/4 mut v0 / r: the twist slides" if want > 0 else
                "the impulse stops the twist", np.array2string(wx, precision=9), err))
    # the rotational energy lost, from the spins the run ends with (the normal impulse is the
    # solver's, within tol of m v0 under mpirun): what the twisting torque did
    lost = float(np.sum(th["f_hc[11]"]))
    want_e = 0.5 * inert * float(np.sum(w0 * w0 - wx * wx))
    lr.check(abs(lost - want_e) <= 1e-9 * want_e + 1e-15,
             "%s: f_hc[11] summed = the rotational energy lost, I/2 sum (w0^2 - w1^2) = %.9g (%.9g)"
             % (name, want_e, lost))


def test():
    args = lr.test_args(__doc__)
    spin_stop(args)
    roll_and_spin(args)
    pair(args, "pair_slides", W0)
    pair(args, "pair_sticks", 0.05)


if __name__ == "__main__":
    lr.main(test)
