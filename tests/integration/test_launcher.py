#!/usr/bin/env python3
"""lmp_hardcontact behaves like lmp, and liggghts_hardcontact like liggghts (--host liggghts):
`-h` prints the host's help (with hardcontact among the fix styles) and exits as the host does
(0; LIGGGHTS: 1), serially and under mpirun; -in, -var, -log, -echo and -screen do what they
do in the host; and fix style hardcontact is registered (a deck using it with a bad keyword fails in the fix, not with
'Unrecognized fix style' / 'Invalid fix style')."""

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
    # LIGGGHTS ends -h with Error::done(), exit status 1 (Debian's liggghts -h too)
    want = 1 if args.lmp.name == "liggghts" else 0
    lr.check(p.returncode == want, "-h exits %d, as the host's own executable (%d)" % (want, p.returncode))
    # a line of each host's own help text
    marker = ("-echo none/screen/log/both  : echoing of input script" if args.lmp.name == "liggghts"
              else "Large-scale Atomic/Molecular Massively Parallel Simulator")
    lr.check(marker in p.stdout, "-h prints the %s help" % args.lmp.name)
    lr.check(p.stdout.count(marker) == 1, "help printed once")
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
    lr.check(not any("Unrecognized fix style" in e or "Invalid fix style" in e for e in res.errors),
             "fix style hardcontact is registered")
    lr.check(any("no_such_keyword_xyz" in e for e in res.errors), "the fix names the bad keyword")

    # the usual flags: -var sets an index variable, -log names the log, -echo screen echoes the
    # commands, -screen sends the screen output to a file
    flags = "variable answer index 1\nprint \"ANSWER ${answer}\"\n"
    wd = args.workdir + "/flags"
    res = lr.run_deck(args.lmp, flags, args.np, wd, variables={"answer": 42},
                      args=["-echo", "screen"], log_name="custom.log", timeout=args.timeout)
    lr.check("ANSWER 42" in res.stdout and "ANSWER 42" in res.log,
             "-var answer 42 reaches the deck (screen and -log custom.log)")
    lr.check('print "ANSWER ${answer}"' in res.stdout, "-echo screen echoes the commands")
    res = lr.run_deck(args.lmp, flags, args.np, wd, args=["-screen", "screen.txt"],
                      timeout=args.timeout)
    screen = open(os.path.join(wd, "screen.txt"), errors="replace").read()
    lr.check("ANSWER 1" in screen and "ANSWER 1" not in res.stdout,
             "-screen screen.txt takes the screen output")


if __name__ == "__main__":
    lr.main(test)
