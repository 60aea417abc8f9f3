#!/usr/bin/env python3
"""Harness self-test: a small granular-style deck WITHOUT fix hardcontact (atom_style sphere,
27 spheres on a periodic cubic lattice, fix nve/sphere, run 10) through lmp_hardcontact, serially
or under mpirun. Checks the step count, that no atom is lost, the thermo parser, and both dump
readers (dump custom, and dump local gathered over all ranks)."""

import lammps_run as lr

N_SIDE = 3
N_ATOMS = N_SIDE ** 3
SPACING = 2.0

DECK = """
units           lj
atom_style      sphere
dimension       3
boundary        p p p
lattice         sc {rho}
region          box block 0 {n} 0 {n} 0 {n}
create_box      1 box
create_atoms    1 box
set             type 1 diameter 1.0
set             type 1 density 1.0
velocity        all create 0.01 4928459 loop geom

# a zero pair style only so that compute property/local has a neighbour list
pair_style      zero 2.5
pair_coeff      * *
neighbor        0.3 bin
compute         nb all property/local patom1 patom2

fix             1 all nve/sphere
thermo_style    custom step atoms ke
thermo          5
dump            atoms all custom 5 dump.atoms id type x y z vx vy vz radius
dump            pairs all local 10 dump.pairs c_nb[1] c_nb[2]
run             10
""".format(rho=1.0 / SPACING ** 3, n=N_SIDE)


def test():
    args = lr.test_args(__doc__)
    res = lr.run_deck(args.lmp, DECK, args.np, args.workdir, timeout=args.timeout)

    lr.check(res.returncode == 0 and not res.errors, "deck ran without ERROR")
    lr.check("Loop time of" in res.log, "log.lammps has the 'Loop time' line")
    loop = [l for l in res.log.splitlines() if l.startswith("Loop time of")][-1]
    lr.check(" on %d procs for 10 steps with %d atoms" % (args.np, N_ATOMS) in loop,
             "log reports %d procs, 10 steps, %d atoms: %s" % (args.np, N_ATOMS, loop))

    lr.check(len(res.thermo) == 1, "one thermo block")
    th = res.thermo[0]
    lr.check(list(th) == ["Step", "Atoms", "KinEng"], "thermo columns %s" % list(th))
    lr.check(list(th["Step"]) == [0, 5, 10], "thermo steps 0 5 10")
    lr.check(all(th["Atoms"] == N_ATOMS), "atom count preserved in thermo")
    lr.check(th["KinEng"].dtype.kind == "f" and th["KinEng"][0] > 0, "kinetic energy parsed")

    frames = lr.read_dump(res.path("dump.atoms"))
    lr.check([f.timestep for f in frames] == [0, 5, 10], "dump custom frames at 0 5 10")
    for f in frames:
        lr.check(list(f.columns["id"]) == list(range(1, N_ATOMS + 1)),
                 "step %d: all %d atoms in the dump, sorted by id" % (f.timestep, N_ATOMS))
        lr.check(f.box.shape == (3, 2) and abs(f.box[0, 1] - f.box[0, 0] - N_SIDE * SPACING) < 1e-9,
                 "step %d: box bounds" % f.timestep)
    lr.check(float(abs(frames[-1].columns["radius"] - 0.5).max()) == 0.0, "radius column")

    local = lr.read_dump_local(res.path("dump.pairs"))
    lr.check([f.timestep for f in local] == [0, 10], "dump local frames at 0 and 10")
    # each atom of the periodic 3x3x3 lattice has 6 neighbours at SPACING < 2.5: 81 pairs
    for f in local:
        lr.check(len(f.columns["c_nb[1]"]) == N_ATOMS * 6 // 2,
                 "step %d: %d neighbour pairs gathered from all ranks" % (f.timestep, N_ATOMS * 3))

    # an ERROR ends the run with a non-zero exit status, also under mpirun
    bad = lr.run_deck(args.lmp, "units lj\nno_such_command 1 2\n", args.np,
                      args.workdir + "/error", expect_error=True, timeout=args.timeout)
    lr.check(bad.returncode != 0, "ERROR deck exits non-zero (%s)" % bad.returncode)
    lr.check(any("Unknown command" in e for e in bad.errors), "ERROR line parsed: %s" % bad.errors)


if __name__ == "__main__":
    lr.main(test)
