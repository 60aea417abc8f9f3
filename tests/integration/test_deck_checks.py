#!/usr/bin/env python3
"""Guard rails for a half-converted soft-sphere deck (src/lammps/deck_checks.h): the lines a
soft deck leaves behind beside fix hardcontact. Each deck runs; checked are its WARNING lines:

  pair_gran    pair_style gran/hertz/history (LIGGGHTS: pair_style gran model hertz) beside the
               fix: one WARNING naming the pair style, 'pair_style none' and what the soft
               damping becomes ('restitution e', e = 0 without it); with restitution on the fix
               line, the note says so instead
  wall_gran    fix wall/gran on the fix's atoms: one WARNING naming that fix's ID and style and
               the fix's 'wall ...' keyword (on LIGGGHTS: plane walls only)
  wall_gran_elsewhere  the same fix wall/gran on a group the fix does not hold: no WARNING
  open_region  a region wall (cylinder) with an open top: one WARNING 'has open faces' (LAMMPS
               hosts; LIGGGHTS has no region walls)
  other_group  fix nve/sphere on a group disjoint from the fix's: no WARNING, no ERROR, and
               the nve atom moves as nve/sphere says (x = x0 + v t)
  bounce_alone `bounce` without restitution: one WARNING that it does nothing (with
               `restitution 0.5`, or `restitution 0` alone: none)
  clean        the converted deck: no WARNING of the fix
Every deck has two runs: each warning comes once (the first run's init), not per run.
The ERROR for a second integrator on the same atoms is a case of test_errors.py
('second_integrator'). Serial and under mpirun (the shared-atom counts are summed over ranks:
every rank decides alike; rank 0 prints)."""

import lammps_run as lr

BASE = """units           lj
atom_style      sphere
dimension       3
boundary        f f f
atom_modify     map array
comm_modify     vel yes
newton          off
region          box block 0 6 0 6 0 6
create_box      1 box
create_atoms    1 single 1.5 1.5 0.5 units box
create_atoms    1 single 4.5 1.5 0.5 units box
create_atoms    1 single 1.5 4.5 0.5 units box
create_atoms    1 single 4.5 4.5 4.5 units box
group           pile id 1 2 3
group           loner id 4
{pair}
neighbor        0.3 bin
{before}
fix             hc {group} hardcontact {fix}
{after}
fix             g pile gravity 1.0 vector 0 0 -1
timestep        0.01
thermo          5
run             5
run             5
"""

LIGGGHTS_MATERIAL = """fix             m1 all property/global youngsModulus peratomtype 5.e6
fix             m2 all property/global poissonsRatio peratomtype 0.45
fix             m3 all property/global coefficientRestitution peratomtypepair 1 0.3
fix             m4 all property/global coefficientFriction peratomtypepair 1 0.0"""


def deck(host, pair="pair_style      none", before="", group="pile", fix="wall zplane 0 NULL", after=""):
    if host == "liggghts":
        before = LIGGGHTS_MATERIAL + "\n" + before
    return BASE.format(pair=pair, before=before, group=group, fix=fix, after=after)


def hc_warnings(res):
    return [w for w in res.warnings if "hardcontact" in w.lower()]


def run(args, name, text):
    res = lr.run_deck(args.lmp, text, args.np, "%s/%s" % (args.workdir, name), timeout=args.timeout)
    return res, hc_warnings(res)


def test():
    args = lr.test_args(__doc__)
    host = args.lmp.name
    ligg = host == "liggghts"
    if ligg:
        pair = "pair_style      gran model hertz tangential history\npair_coeff      * *"
        pair_name = "gran"
        wall = "fix             soft {g} wall/gran model hertz tangential history primitive type 1 zplane 0.0"
    else:
        pair = "pair_style      gran/hertz/history 2000 NULL 50 NULL 0.5 0\npair_coeff      * *"
        pair_name = "gran/hertz/history"
        wall = "fix             soft {g} wall/gran hertz/history 2000 NULL 50 NULL 0.5 0 zplane 0 NULL"

    # a granular pair style
    _, w = run(args, "pair_gran", deck(host, pair=pair))
    lr.check(len(w) == 1 and ("pair_style %s" % pair_name) in w[0] and "'pair_style none'" in w[0]
             and "restitution e" in w[0] and "e = 0" in w[0],
             "pair_gran: one WARNING names the pair style, pair_style none and restitution: %s" % w)
    _, w = run(args, "pair_gran_restitution", deck(host, pair=pair, fix="wall zplane 0 NULL restitution 0.5"))
    lr.check(len(w) == 1 and "the fix's restitution keyword (given)" in w[0],
             "pair_gran with restitution on the fix line: the note says so: %s" % w)

    # fix wall/gran on the fix's atoms, then on atoms the fix does not hold
    _, w = run(args, "wall_gran", deck(host, after=wall.format(g="all")))
    lr.check(len(w) == 1 and "fix soft (wall/gran" in w[0] and "on 3 of its atoms" in w[0]
             and "'wall xplane|yplane|zplane lo hi'" in w[0]
             and (("no region or mesh walls" in w[0]) if ligg else ("'wall region ID'" in w[0])),
             "wall_gran: one WARNING names the fix, its style, the 3 shared atoms and the wall keyword: %s" % w)
    _, w = run(args, "wall_gran_elsewhere", deck(host, after=wall.format(g="loner")))
    lr.check(not w, "wall_gran on a group outside the fix's: no WARNING: %s" % w)

    # a region wall with an open face (LAMMPS hosts: LIGGGHTS has no region walls)
    if not ligg:
        _, w = run(args, "open_region", deck(
            host, before="region          cup cylinder z 3 3 2.9 0 6 side in open 2",
            fix="wall region cup"))
        lr.check(len(w) == 1 and "wall region cup has open faces" in w[0],
                 "open_region: one WARNING 'wall region cup has open faces': %s" % w)
        _, w = run(args, "closed_region", deck(
            host, before="region          cup cylinder z 3 3 2.9 0 6 side in", fix="wall region cup"))
        lr.check(not w, "closed region: no WARNING: %s" % w)

    # another integrator on a disjoint group: runs, and moves its atom as nve/sphere does
    res, w = run(args, "other_group", deck(
        host, after="fix             nve loner nve/sphere\nvelocity        loner set 0.5 0 0 units box\n"
                    "variable        x4 equal x[4]\nthermo_style    custom step v_x4\n"
                    "thermo_modify   format float %.15g"))
    x4 = res.thermo[-1]["v_x4"][-1]
    lr.check(not w and abs(x4 - (4.5 + 0.5 * 0.1)) < 1e-12,
             "other_group: fix nve/sphere on the loner only: no WARNING, x4 = 4.55 after 10 steps "
             "of 0.01 at 0.5 (%.15g): %s" % (x4, w))

    # an effect's shaping keyword without the effect: bounce without restitution does nothing
    _, w = run(args, "bounce_alone", deck(host, fix="wall zplane 0 NULL bounce 0.05"))
    lr.check(len(w) == 1 and "no restitution is above 0, so 'bounce' does nothing" in w[0],
             "bounce_alone: one WARNING that 'bounce' does nothing without restitution: %s" % w)
    _, w = run(args, "bounce_restitution", deck(
        host, fix="wall zplane 0 NULL restitution 0.5 bounce 0.05"))
    lr.check(not w, "bounce with restitution 0.5: no WARNING: %s" % w)
    _, w = run(args, "restitution_zero", deck(host, fix="wall zplane 0 NULL restitution 0"))
    lr.check(not w, "restitution 0 alone (the default's value): no WARNING: %s" % w)

    # the converted deck
    _, w = run(args, "clean", deck(host))
    lr.check(not w, "clean deck: no WARNING of the fix: %s" % w)


if __name__ == "__main__":
    lr.main(test)
