"""LAMMPS decks of the performance benchmark: hardcontact runs and their soft-sphere twin
(gran/hertz/history, frictionless, fix wall/gran, fix nve/sphere). LJ units, g = 1 along -z."""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "python"))
from hctools import hertz_params  # noqa: E402,F401 - the twin's settings, as decks.hertz_params

HEAD = """units           lj
dimension       3
atom_style      sphere
boundary        f f f
atom_modify     map array
{processors}{start}
"""

HARD = """pair_style      none
neighbor        {skin!r} bin
neigh_modify    delay 0 every 1 check yes
fix             grav all gravity 1.0 vector 0 0 -1
fix             hc all hardcontact solver {solver} tol {tol!r} {fix_extra}{walls}
timestep        {h!r}
compute         zz all property/atom z
compute         zavg all reduce ave c_zz
thermo_style    custom step time cpu ke f_hc[1] f_hc[3] f_hc[4] f_hc[5] f_hc[6] f_hc[7] f_hc[9] c_zavg
thermo_modify   norm no
"""

# Wall-time cap of a run: the elapsed time of the run (thermo keyword cpu) checked every step.
# (fix halt's own tlimit predicts its next check from the first steps' rate, so it overshoots
# by minutes when the steps get dearer, as they do in a settle.) A soft halt leaves the timer
# expired, which would stop every later run at once: hence `timer timeout off` after each run.
HALT = """variable        elapsed equal cpu
fix             halt all halt 1 v_elapsed > {cap!r} error soft message no
"""
UNHALT = """unfix           halt
timer           timeout off
"""
# A phase that ends once the pile is at rest: the kinetic energy per sphere below a threshold
# (in units of m g d, mgd the scene's mean m g d), checked every 10 steps.
CALM = """variable        calm equal ke/atoms/{mgd!r}
fix             calm all halt 10 v_calm < {until!r} error soft message no
"""
UNCALM = """unfix           calm
timer           timeout off
"""


def start_line(start):
    kind, path = start
    return ("read_data       %s" if kind == "data" else "read_restart    %s") % path


def hard(scene, start, solver, tol, phases, h=0.02, skin=0.3, ranks_2d=False, restart_out=None,
         fix_extra=""):
    """A hardcontact run: phases = [(steps, thermo_every, cap_seconds[, until]), ...], each a
    `run` stopped by fix halt after cap_seconds of wall time, or (until) once the kinetic energy
    per sphere is below until x m g d; thermo columns step time cpu ke f_hc[1,3,4,5,6,7,9] and
    the mean height c_zavg. ranks_2d: `processors * * 1` (domains split in x and y only).
    restart_out: written after the first phase. fix_extra: more keywords of the fix (before
    the walls), e.g. 'subspace 10'."""
    text = HEAD.format(processors="processors      * * 1\n" if ranks_2d else "",
                       start=start_line(start))
    text += HARD.format(skin=skin, solver=solver, tol=tol, walls=scene["walls"], h=h,
                        fix_extra=fix_extra + " " if fix_extra else "")
    for k, phase in enumerate(phases):
        steps, every, cap = phase[:3]
        until = phase[3] if len(phase) > 3 else None
        text += HALT.format(cap=float(cap))
        if until is not None:
            text += CALM.format(mgd=scene["mean_mass"] * scene["mean_d"], until=float(until))
        text += "thermo          %d\nrun             %d\n" % (every, steps)
        text += UNHALT
        if until is not None:
            text += UNCALM
        if k == 0 and restart_out:
            text += "write_restart   %s\n" % restart_out
    return text


SOFT = """comm_modify     vel yes
pair_style      gran/hertz/history {kn!r} NULL {gn!r} NULL 0.0 0
pair_coeff      * *
neighbor        {skin!r} bin
neigh_modify    delay 0 every 1 check yes
fix             grav all gravity 1.0 vector 0 0 -1
fix             nve all nve/sphere
fix             wx all wall/gran hertz/history {kn!r} NULL {gw!r} NULL 0.0 0 xplane 0.0 {wx!r}
fix             wy all wall/gran hertz/history {kn!r} NULL {gw!r} NULL 0.0 0 yplane 0.0 {wy!r}
fix             wz all wall/gran hertz/history {kn!r} NULL {gw!r} NULL 0.0 0 zplane 0.0 NULL
timestep        {dt!r}
compute         pl all pair/local force dist cutoff radius
compute         pp all property/local patom1 patom2 cutoff radius
compute         red all reduce max c_pl[1] c_pl[2] c_pp[1] c_pp[2] replace 2 1 replace 3 1 replace 4 1
compute         rad all property/atom radius
variable        wo atom (c_rad-z)/c_rad
compute         wmax all reduce max v_wo
thermo_style    custom step time cpu ke c_red[1] c_red[2] c_red[3] c_red[4] c_wmax
thermo_modify   norm no
"""


def soft(scene, data, p, phases, skin=0.1):
    """The soft twin of a hard run: same data file, walls as fix wall/gran. Thermo: step time
    cpu ke, the pair with the largest force (force, distance, ids: its overlap follows from the
    radii of the data file) and the largest wall overlap relative to the radius (floor)."""
    (_, wx), (_, wy), _ = scene["box"]
    text = HEAD.format(processors="newton          off\n", start=start_line(("data", data)))
    text += SOFT.format(kn=p["kn"], gn=p["gamma_n"], gw=p["gamma_w"], dt=p["dt"], skin=skin,
                        wx=wx, wy=wy)
    for steps, every, cap in phases:
        text += HALT.format(cap=float(cap))
        text += "thermo          %d\nrun             %d\n" % (every, steps)
        text += UNHALT
    return text
