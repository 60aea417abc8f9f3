"""hctools: what the tests, examples and benchmarks of hardcontact share.

    run     run_deck(lmp, deck, np, workdir, ...) on any host (Host: the launcher, a modern
            LAMMPS loading the plugin, LIGGGHTS) and rank count; RunResult, LammpsRunError
    logs    parse_thermo / read_thermo (thermo blocks), loop_times / read_loop_times
    dumps   read_dump, read_dump_local (DumpFrame: timestep, columns, box)
    data    write_data (atom_style sphere data files), write_stl, sphere_mass
    soft    hertz_params (the soft twin's gran/hertz/history settings)
    decks   preamble (the first lines of a deck of spheres)
    summary window_values: a thermo block as numbers for a CSV row; from a shell,
            python3 -m hctools thermo LOG rows mean:f_hc[1] loop ... (bench/common.sh's bench_thermo)

Standard library and numpy only. A script outside python/ puts this folder on sys.path:
    sys.path.insert(0, os.path.join(<repository>, "python"))
"""

import os

from .data import sphere_mass, write_data, write_stl
from .decks import preamble
from .dumps import DumpFrame, read_dump, read_dump_local
from .logs import loop_times, parse_thermo, read_loop_times, read_thermo
from .run import DEFAULT_TIMEOUT, Host, LammpsRunError, RunResult, liggghts_deck, run_deck
from .soft import hertz_params

# the repository this package sits in
ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

__all__ = [
    "ROOT", "DEFAULT_TIMEOUT", "Host", "LammpsRunError", "RunResult", "liggghts_deck", "run_deck",
    "parse_thermo", "read_thermo", "loop_times", "read_loop_times", "DumpFrame", "read_dump",
    "read_dump_local", "write_data", "write_stl", "sphere_mass", "hertz_params", "preamble",
]
