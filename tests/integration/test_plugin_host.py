#!/usr/bin/env python3
"""The fix in a modern LAMMPS through `plugin load` (registered with HOSTS modern).

1. `plugin load` registers fix hardcontact (`plugin list` names it); so does
   LAMMPS_PLUGIN_PATH=<folder of the plugin> with a deck that does not mention the plugin.
2. The same decks give the same results in the modern LAMMPS and in build/lmp_hardcontact
   (Debian's LAMMPS 29 Sep 2021, the fix built in), at this test's rank count:
     - a random packing of 60 polydisperse spheres falling into a walled box (pair_style none),
     - the same with a soft pair style beside the fix (lj/cut, repulsive WCA: the pair forces
       are the external force f of the scheme),
     - a sphere dropped onto a zplane wall (rests on it).
   The hosts differ only in LAMMPS around the fix (neighbour list order, ghost range), so the
   solves differ within the solver's tolerance: positions within 1e-6 diameters (tol 1e-10).
   No overlap beyond tolerance on either host.
3. `plugin unload fix hardcontact` removes the fix (and its instance); `clear` then leaves a
   LAMMPS that runs a deck without the fix, and one with the fix after a new `plugin load`.
"""

import os

import numpy as np

import lammps_run as lr
import physics_common as pc

TOL = 1e-10

BOX_DECK = lr.preamble(ghost_velocities=True) + """
read_data       data.box
{pair}
neighbor        0.3 bin
fix             hc all hardcontact tol {tol} wall xplane 0 6 wall yplane 0 6 wall zplane 0 NULL
fix             g all gravity 1.0 vector 0 0 -1
timestep        0.02
thermo_style    custom step atoms ke f_hc[1] f_hc[2] f_hc[4]
thermo_modify   format float %.16g
thermo          50
dump            d all custom 300 dump.atoms id type radius mass x y z vx vy vz
dump_modify     d format float %.16g sort id
run             300
"""

DROP_DECK = pc.DROP_ON_FLOOR.format(
    x=0.1, y=-0.2, z=4.0, fix_extra="tol {tol}", h=0.05, n=200,
    output="thermo          20\n"
           "dump            d all custom 200 dump.atoms id type radius mass x y z vx vy vz\n"
           "dump_modify     d format float %.17g sort id")


def box_data(path):
    rng = np.random.default_rng(7)
    pts = []
    for k in range(5):
        for j in range(4):
            for i in range(3):
                pts.append([1.0 + 1.6 * i + rng.uniform(-0.2, 0.2),
                            0.9 + 1.4 * j + rng.uniform(-0.2, 0.2),
                            0.8 + 1.3 * k])
    x = np.array(pts)
    radius = rng.uniform(0.35, 0.5, len(x))
    v = np.column_stack([rng.uniform(-0.3, 0.3, len(x)), rng.uniform(-0.3, 0.3, len(x)),
                         np.zeros(len(x))])
    pc.write_sphere_data(path, ((0, 6), (0, 6), (0, 10)), radius, 1.0, x, v)


def last_frame(res):
    return lr.read_dump(res.path("dump.atoms"))[-1]


def compare_hosts(args, launcher, name, deck, files_fn=None):
    """Run `deck` on both hosts at args.np ranks; return the two last frames."""
    frames = {}
    for host in (args.lmp, launcher):
        wd = os.path.join(args.workdir, "%s_%s" % (name, host.name))
        lr.fresh_workdir(wd)
        if files_fn:
            files_fn(wd)
        res = lr.run_deck(host, deck, args.np, wd, timeout=args.timeout)
        lr.check(not res.errors, "%s on the %s host: no ERROR" % (name, host.name))
        frames[host.name] = last_frame(res)
    a, b = frames["modern"], frames["launcher"]
    lr.check(np.array_equal(a.columns["id"], b.columns["id"]), "%s: same atoms on both hosts" % name)
    d = np.abs(pc.positions(a) - pc.positions(b)).max() / (2.0 * a.columns["radius"].min())
    lr.check(d < 1e-6, "%s: positions agree across hosts within 1e-6 diameters (%.3g)" % (name, d))
    for host, f in frames.items():
        worst, _ = pc.pair_overlaps(pc.positions(f), f.columns["radius"])
        lr.check(worst < 10 * TOL, "%s on the %s host: no pair overlap (%.3g of r_i + r_j)"
                 % (name, host, worst))
    return a, b


def test():
    args = lr.test_args(__doc__)
    lr.check(args.lmp.name == "modern", "this test runs on the modern host (--host modern)")
    launcher = lr.Host(os.environ.get("HARDCONTACT_LAUNCHER",
                                      str(lr._REPO / "build" / "lmp_hardcontact")), "launcher")

    # 1. registered by plugin load
    res = lr.run_deck(args.lmp, "plugin list\n", args.np, os.path.join(args.workdir, "list"),
                      timeout=args.timeout)
    lr.check("fix style plugin hardcontact" in res.stdout,
             "plugin list names fix style hardcontact after plugin load")

    # 1b. or without a line in the deck: LAMMPS loads every *plugin.so in LAMMPS_PLUGIN_PATH
    res = lr.run_deck(str(args.lmp), DROP_DECK.format(tol=TOL), args.np,
                      os.path.join(args.workdir, "plugin_path"), timeout=args.timeout,
                      env={"LAMMPS_PLUGIN_PATH": os.path.dirname(args.lmp.plugin)})
    z = float(pc.positions(last_frame(res))[0, 2])
    lr.check(abs(z - 0.5) < 1e-8, "LAMMPS_PLUGIN_PATH loads the fix into an unchanged deck")

    # 2. same results on both hosts
    write_box = lambda wd: box_data(os.path.join(wd, "data.box"))
    a, _ = compare_hosts(args, launcher, "box_pair_none",
                         BOX_DECK.format(pair="pair_style none", tol=TOL), write_box)
    lr.check(float(pc.positions(a)[:, 2].max()) < 6.0, "box: the spheres fell and settled")
    wca = ("pair_style lj/cut 0.8908987\npair_coeff * * 0.1 0.8 0.8908987\n"
           "pair_modify shift yes")
    compare_hosts(args, launcher, "box_pair_lj", BOX_DECK.format(pair=wca, tol=TOL), write_box)
    a, _ = compare_hosts(args, launcher, "drop", DROP_DECK.format(tol=TOL))
    z = float(pc.positions(a)[0, 2])
    lr.check(abs(z - 0.5) < 1e-8, "drop: the sphere rests on the wall at z = r (%.12g)" % z)

    # 3. unload, clear, reload
    deck = DROP_DECK.format(tol=TOL).replace("run             200", "run             20") + """
plugin          unload fix hardcontact
print           "FIXES AFTER UNLOAD: $(count(all)) atoms"
clear
units           lj
atom_style      atomic
region          b block 0 4 0 4 0 4
create_box      1 b
create_atoms    1 random 20 4321 NULL
mass            1 1.0
pair_style      lj/cut 2.5
pair_coeff      1 1 1.0 1.0
velocity        all create 1.0 87287 loop geom
fix             nve all nve
minimize        1e-4 1e-6 100 1000
run             20
print           "PLAIN RUN AFTER CLEAR DONE"
clear
plugin          load {plugin}
""".format(plugin=args.lmp.plugin) + DROP_DECK.format(tol=TOL).replace(
        "dump.atoms", "dump2.atoms")
    wd = os.path.join(args.workdir, "unload")
    res = lr.run_deck(args.lmp, deck, args.np, wd, timeout=args.timeout)
    lr.check("Unloading fix style hardcontact" in res.stdout or "unload" in res.log,
             "plugin unload fix hardcontact ran")
    lr.check("PLAIN RUN AFTER CLEAR DONE" in res.stdout, "after unload + clear a plain deck runs")
    f = lr.read_dump(res.path("dump2.atoms"))[-1]
    lr.check(abs(float(pc.positions(f)[0, 2]) - 0.5) < 1e-8,
             "after a new plugin load the fix runs again (sphere rests at z = r)")
    bad = lr.run_deck(args.lmp, "plugin unload fix hardcontact\nunits lj\natom_style sphere\n"
                      "region b block 0 2 0 2 0 2\ncreate_box 1 b\nfix 1 all hardcontact\n",
                      args.np, os.path.join(args.workdir, "unloaded"), expect_error=True,
                      timeout=args.timeout)
    lr.check(any("hardcontact" in e for e in bad.errors),
             "after plugin unload the fix style is gone: %s" % bad.errors[:1])


if __name__ == "__main__":
    lr.main(test)
