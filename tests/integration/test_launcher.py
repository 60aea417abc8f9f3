#!/usr/bin/env python3
"""lmp_hardcontact behaves like lmp: `-h` prints LAMMPS's help (with hardcontact among the fix
styles) and exits 0, serially and under mpirun; and fix style hardcontact is registered (a
deck using it with a bad keyword fails in the fix, not with 'Unrecognized fix style')."""

import os
import subprocess

import lammps_run as lr


def test():
    args = lr.test_args(__doc__)

    cmd = [os.path.abspath(args.lmp), "-h"]
    if args.np > 1:
        cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "--bind-to", "none",
               "-np", str(args.np)] + cmd
    p = subprocess.run(cmd, cwd=args.workdir, stdin=subprocess.DEVNULL, capture_output=True,
                       text=True, timeout=args.timeout)
    lr.check(p.returncode == 0, "-h exits 0 (%d)" % p.returncode)
    lr.check("Large-scale Atomic/Molecular Massively Parallel Simulator" in p.stdout,
             "-h prints the LAMMPS help")
    lr.check(p.stdout.count("Large-scale Atomic/Molecular") == 1, "help printed once")
    fixes = p.stdout.split("* Fix styles", 1)[-1].split("\n\n")[1].split()
    lr.check("nve/sphere" in fixes and "hardcontact" in fixes,
             "help lists hardcontact among the fix styles")
    lr.check(not os.path.exists(os.path.join(args.workdir, "log.lammps")), "-h writes no log")

    deck = """
units           lj
atom_style      sphere
lattice         sc 0.125
region          box block 0 2 0 2 0 2
create_box      1 box
create_atoms    1 box
fix             1 all hardcontact no_such_keyword_xyz
run             0
"""
    res = lr.run_deck(args.lmp, deck, args.np, args.workdir + "/registered", expect_error=True,
                      timeout=args.timeout)
    lr.check(res.errors, "bad fix keyword gives an ERROR: %s" % res.errors)
    lr.check(not any("Unrecognized fix style" in e for e in res.errors),
             "fix style hardcontact is registered")


if __name__ == "__main__":
    lr.main(test)
