"""Runs the scenes of the spectrum study (bench/studies/spectrum/run.sh): each settles with the default
solver (cg, tol 1e-4, warm start) from bench/perf's data, writes a restart, then runs a window
at rest with HARDCONTACT_DUMP_PROBLEMS set, so that every step's problem is written."""

import argparse
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[1] / "perf"))    # bench/perf: scenes, decks
sys.path.insert(0, str(HERE.parents[2] / "python"))
import decks  # noqa: E402
import hctools as hc  # noqa: E402
import scenes  # noqa: E402

# name: (scene, settle steps); the piles settle as in bench/perf (200 + 20 x layers steps)
SCENES = dict(pile5=(lambda: scenes.pile(10, 10, 5), 300),
              pile10=(lambda: scenes.pile(10, 10, 10), 400),
              pile20=(lambda: scenes.pile(10, 10, 20), 600),
              tray1000=(lambda: scenes.tray(1000), 200))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--lmp", required=True)
    ap.add_argument("--work", required=True)
    ap.add_argument("--window", type=int, default=12)
    ap.add_argument("names", nargs="+")
    a = ap.parse_args()
    for name in a.names:
        make, settle = SCENES[name]
        sc = make()
        d = Path(a.work) / name
        d.mkdir(parents=True, exist_ok=True)
        data = d / "scene.data"
        scenes.write(sc, str(data))
        restart = d / "settled.restart"
        deck = decks.hard(sc, ("data", str(data)), "cg", 1e-4, [(settle, 50, 600.0)])
        hc.run_deck(a.lmp, deck + "write_restart   %s\n" % restart, workdir=d, timeout=7200,
                    deck_name="in.settle", log_name="log.settle", args=["-echo", "none"])
        hc.run_deck(a.lmp, decks.hard(sc, ("restart", str(restart)), "cg", 1e-4,
                                      [(a.window, 1, 600.0)]),
                    workdir=d, timeout=7200, deck_name="in.rest", log_name="log.rest",
                    args=["-echo", "none"], env=dict(HARDCONTACT_DUMP_PROBLEMS=str(d / "problem")))
        print("%s: settled %d steps, %d problems dumped" % (
            name, settle, len(list(d.glob("problem.*")))), flush=True)


if __name__ == "__main__":
    main()
