"""The integration tests' harness: their command line, work folders and checks, on top of the
project's toolkit (python/hctools: running decks on any host and rank count, reading logs,
dumps and data files), which this module re-exports so that a test needs one import:

    import lammps_run as lr

    args = lr.test_args(__doc__)            # --lmp, --np, --workdir (what ctest passes)
    res = lr.run_deck(args.lmp, DECK, args.np, args.workdir, variables={"seed": 42})
    lr.check(res.thermo[-1]["Step"][-1] == 100, "run reached step 100")
    frames = lr.read_dump(res.path("dump.atoms"))
"""

import argparse
import shutil
import sys
from pathlib import Path

_REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(_REPO / "python"))

from hctools import (DEFAULT_TIMEOUT, DumpFrame, Host, LammpsRunError, RunResult,  # noqa: E402
                     liggghts_deck, parse_thermo, preamble, read_dump, read_dump_local,
                     run_deck)
from hctools.run import WORKDIR_MARKER as _MARKER  # noqa: E402

__all__ = [
    "Host", "liggghts_deck", "RunResult", "LammpsRunError", "run_deck", "parse_thermo", "read_dump", "read_dump_local",
    "DumpFrame", "preamble", "test_args", "fresh_workdir", "check", "main",
]


# ----------------------------------------------------------------------------------- scripts

def test_args(description=None, argv=None, extra=()):
    """Command line of a deck test, as registered by hardcontact_deck_test() in
    tests/CMakeLists.txt: --lmp <exe> --np <N> --workdir <dir> (plus --timeout, and --host
    modern --plugin <so> for a modern LAMMPS that loads the fix as a plugin), and the test's
    own options: extra = [(flag, argparse keywords), ...]. args.lmp is a Host: pass it to
    run_deck as it is."""
    p = argparse.ArgumentParser(description=description)
    for flag, keywords in extra:
        p.add_argument(flag, **keywords)
    p.add_argument("--lmp", default=None,
                   help="LAMMPS executable: with fix hardcontact (launcher host, default "
                        "build/lmp_hardcontact) or with the PLUGIN package (modern host)")
    p.add_argument("--host", choices=("launcher", "modern", "liggghts"), default="launcher",
                   help="launcher: the fix is built in; modern: every deck starts with "
                        "'plugin load <--plugin>'; liggghts: LIGGGHTS with the fix built in "
                        "(--lmp build/liggghts_hardcontact), decks rewritten where it differs")
    p.add_argument("--plugin", default=None,
                   help="hardcontactplugin.so built against the modern LAMMPS (--host modern)")
    p.add_argument("--np", type=int, default=1, help="MPI ranks (default 1: no mpirun)")
    p.add_argument("--workdir", default=None,
                   help="where the decks run (default: build/tests/work/<script name>)")
    p.add_argument("--timeout", type=float, default=DEFAULT_TIMEOUT, help="seconds per LAMMPS run")
    a = p.parse_args(argv)
    if a.host == "modern":
        if not a.lmp or not a.plugin:
            p.error("--host modern needs --lmp <modern lmp> and --plugin <hardcontactplugin.so>")
        a.lmp = Host(a.lmp, "modern", a.plugin)
    elif a.host == "liggghts":
        a.lmp = Host(a.lmp or _REPO / "build" / "liggghts_hardcontact", "liggghts")
    else:
        a.lmp = Host(a.lmp or _REPO / "build" / "lmp_hardcontact", "launcher")
    if a.workdir is None:
        a.workdir = str(_REPO / "build" / "tests" / "work" / Path(sys.argv[0]).stem)
    fresh_workdir(a.workdir)
    return a


def fresh_workdir(path):
    """Empty a work directory from an earlier run (only one that run_deck created, or an empty
    one) and create it."""
    path = Path(path)
    if path.exists():
        if (path / _MARKER).exists():
            shutil.rmtree(str(path))
        elif any(path.iterdir()):
            raise LammpsRunError("refusing to clear %s: not a lammps_run work directory" % path)
    path.mkdir(parents=True, exist_ok=True)
    (path / _MARKER).touch()
    return path


def check(condition, message):
    """assert that survives python -O; message says what should hold."""
    if not condition:
        raise AssertionError(message)
    print("ok:", message)


def main(test):
    """Run test() and turn the outcome into an exit status with a short report."""
    try:
        test()
    except (AssertionError, LammpsRunError) as e:
        print("FAIL: %s" % e, file=sys.stderr)
        sys.exit(1)
    print("PASS")
