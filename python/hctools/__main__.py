"""python3 -m hctools thermo ...: see hctools/summary.py (the bench scripts' log summaries)."""

import sys

from . import summary

COMMANDS = {"thermo": summary.main}

if len(sys.argv) < 2 or sys.argv[1] not in COMMANDS:
    sys.exit("usage: python3 -m hctools {%s} ... (-h after the command for its help)"
             % "|".join(COMMANDS))
sys.exit(COMMANDS[sys.argv[1]](sys.argv[2:]))
