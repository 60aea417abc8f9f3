#!/usr/bin/env python3
"""Error handling of fix hardcontact: a table of small bad decks, each run serially or under
mpirun (--np; with --np 4 only the cases marked for it). Every case must

  * exit non-zero (a clean error->all: no MPI_ABORT, no crash, no hang),
  * print an 'ERROR: ...' line (rank 0's error->all line, not 'ERROR on proc N') containing
    the expected phrases, which say what to change,
  * print no 'nan' (outside the echo of the deck and quoted user input),
  * finish well under its timeout.

The cases whose offending atom matters put it on the highest-ID atom, which sits in the far
corner of the box and hence on the last rank under mpirun: an error detected on one rank only
must still end every rank cleanly.

The skin case also checks that the skin the ERROR suggests is enough: the same deck with
'neighbor <suggested> bin' runs without error.

KNOWN_BUGS holds decks where the fix currently does the wrong thing (see each entry's 'bug');
they run only with --known-bugs and are not registered in ctest."""

import os
import re
import sys
import tempfile
from collections import namedtuple

import lammps_run as lr
import scene_data as sd

# seconds per LAMMPS run before it is killed and counts as a hang (a liveness bound, not a
# timing: a failing deck of 4 atoms stops within a second or two; no test asserts a time)
CASE_TIMEOUT = 90.0

# four spheres of diameter 1 in a 6^3 box; atom 4 is alone in the far corner (last rank)
BASE = """units           lj
atom_style      {style}
dimension       3
boundary        {boundary}
region          box block 0 6 0 6 0 6
create_box      1 box
create_atoms    1 single 1.5 1.5 1.5 units box
create_atoms    1 single 4.5 1.5 1.5 units box
create_atoms    1 single 1.5 4.5 1.5 units box
create_atoms    1 single 4.5 4.5 4.5 units box
{setup}
pair_style      none
neighbor        0.3 bin
{before_fix}
fix             1 all hardcontact {fix}
{after_fix}
thermo          1
run             5
"""


def deck(fix="", style="sphere", boundary="f f f", setup="", before_fix="", after_fix=""):
    return BASE.format(fix=fix, style=style, boundary=boundary, setup=setup,
                       before_fix=before_fix, after_fix=after_fix)


DATA_BAD_VELOCITY = """hardcontact test: atom 4 has a velocity that overflows to inf

4 atoms
1 atom types

0 6 xlo xhi
0 6 ylo yhi
0 6 zlo zhi

Atoms # sphere

1 1 1.0 1.0 1.5 1.5 1.5
2 1 1.0 1.0 4.5 1.5 1.5
3 1 1.0 1.0 1.5 4.5 1.5
4 1 1.0 1.0 4.5 4.5 4.5

Velocities

1 0 0 0 0 0 0
2 0 0 0 0 0 0
3 0 0 0 0 0 0
4 1e999 0 0 0 0 0
"""

DATA_DECK = """units           lj
atom_style      sphere
boundary        f f f
read_data       bad.data
pair_style      none
fix             1 all hardcontact
run             5
"""

TRICLINIC_DECK = """units           lj
atom_style      sphere
boundary        f f f
region          box prism 0 6 0 6 0 6 0.5 0 0
create_box      1 box
create_atoms    1 single 1.5 1.5 1.5 units box
create_atoms    1 single 4.5 4.5 4.5 units box
pair_style      none
fix             1 all hardcontact
run             5
"""

TWOD_DECK = """units           lj
atom_style      sphere
dimension       2
boundary        f f p
region          box block 0 6 0 6 -0.5 0.5
create_box      1 box
create_atoms    1 single 1.5 1.5 0 units box
create_atoms    1 single 4.5 4.5 0 units box
pair_style      none
fix             1 all hardcontact wall zplane 0 1
run             5
"""

# atom 4 alone moves 0.1 per step; a skin of 0.001 cannot hold that
SKIN_DECK = deck(setup="group fast id 4\nvelocity fast set 1 0 0 units box",
                 before_fix="neighbor 0.001 bin\ntimestep 0.1")

# name, deck, phrases the ERROR line must hold (case-insensitive), run with np 4 too,
# files to write into the work directory {name: text}
# (min_np: run only with at least that many ranks)
Case = namedtuple("Case", "name deck phrases np4 files min_np modern liggghts liggghts_setup_nan "
                         "hosts")

# LIGGGHTS 3.8 has no region walls (lammps_compat.h: its regions do not number their faces):
# every 'wall region ID' deck stops with this error there instead
LIGGGHTS_NO_REGION_WALLS = ["not available on this host", "LIGGGHTS 3.8 regions", "use plane walls"]


def case(name, deck_text, phrases, np4=False, files=None, min_np=1, modern=None, liggghts=None,
         liggghts_setup_nan=False, hosts=None):
    """modern: phrases of the error that a modern LAMMPS gives itself before the fix sees the
    bad input (its own check, possibly with error->one); None: the fix's error on every host.
    liggghts: the same for LIGGGHTS 3.8 (its own error, or the fix's where it must differ there).
    liggghts_setup_nan: LIGGGHTS prints a NaN of its own in the thermo row of step 0, before
    the fix sees the bad value (that row is left out of the NaN check on that host).
    hosts: the hosts where the deck is bad input (None: all)."""
    return Case(name, deck_text, phrases, np4, files or {}, min_np, modern, liggghts,
                liggghts_setup_nan, hosts)


# a floor of two triangles under the four spheres of BASE (z = 0, the box's bottom)
FLOOR_STL = ("solid floor\n"
             "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 6 0 0\nvertex 6 6 0\n"
             "endloop\nendfacet\n"
             "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 6 6 0\nvertex 0 6 0\n"
             "endloop\nendfacet\nendsolid floor\n")

CASES = [
    # atom style and atom IDs
    case("atom_style_atomic", deck(style="atomic", setup="mass 1 1.0"),
         ["radius and rmass", "use atom_style sphere"], np4=True),
    case("atom_ids_off", deck().replace("atom_style      sphere",
                                        "atom_style      sphere\natom_modify     id no"),
         ["requires atom IDs", "atom_modify id no"],
         liggghts=["Illegal atom_modify command"]),    # LIGGGHTS atoms always have IDs
    # a half-converted soft deck: its integrator left beside the fix (deck_checks.h)
    case("second_integrator", deck(after_fix="fix             2 all nve/sphere"),
         ["fix 2 (nve/sphere) also integrates 4 of its atoms", "twice per step",
          "delete the line 'fix 2 ... nve/sphere'"], np4=True),
    # fix_modify options of the fix (output only)
    case("fix_modify_contacts_value", deck(after_fix="fix_modify 1 contacts bonds"),
         ["fix hardcontact contacts takes pairs, walls or all", "not 'bonds'"], np4=True),
    case("fix_modify_contacts_missing", deck(after_fix="fix_modify 1 contacts"),
         ["fix hardcontact contacts takes pairs, walls or all"]),
    # keyword syntax
    case("unknown_keyword", deck("frobnicate 3"),
         ["keyword 'frobnicate' is unknown", "use solver, tol, maxiter, rho", "wall"], np4=True),
    case("tol_without_value", deck("tol"), ["tol needs 1 value"]),
    case("tol_without_value_after_other", deck("maxiter 10 tol"), ["tol needs 1 value"]),
    case("solver_without_value", deck("solver"), ["solver needs 1 value"]),
    case("wall_too_few_values", deck("wall zplane 0"), ["wall needs 3 value"]),
    # tol
    case("tol_abc", deck("tol abc"), ["tol", "expected a number", "'abc'"]),
    case("tol_negative", deck("tol -1"), ["tol must be in (0, 1)", "got -1"]),
    case("tol_zero", deck("tol 0"), ["tol must be in (0, 1)", "got 0"]),
    case("tol_one", deck("tol 1"), ["tol must be in (0, 1)", "got 1"]),
    case("tol_two", deck("tol 2"), ["tol must be in (0, 1)", "got 2"]),
    case("tol_nan", deck("tol nan"), ["tol", "expected a number", "'nan'"], np4=True),
    case("tol_inf", deck("tol inf"), ["tol", "expected a number", "'inf'"]),
    case("tol_overflow", deck("tol 1e999"), ["tol", "not a finite number"]),
    # maxiter
    case("maxiter_zero", deck("maxiter 0"), ["maxiter must be at least 1", "got 0"]),
    case("maxiter_fraction", deck("maxiter 1.5"), ["maxiter", "expected an integer", "'1.5'"]),
    case("maxiter_negative", deck("maxiter -5"), ["maxiter must be at least 1", "got -5"]),
    # subspace
    case("subspace_negative", deck("subspace -1"), ["subspace must be from 0 to 100", "got -1"]),
    case("subspace_too_many", deck("subspace 101"), ["subspace must be from 0 to 100", "got 101"]),
    case("subspace_fraction", deck("subspace 2.5"), ["subspace", "expected an integer", "'2.5'"]),
    case("subspace_pgs", deck("solver pgs subspace 10"),
         ["subspace applies to solvers cg and apgd", "not pgs", "remove subspace or use cg or apgd"],
         np4=True),
    case("subspace_uzawa", deck("solver uzawa subspace 10"),
         ["subspace applies to solvers cg and apgd", "not uzawa"]),
    # cone
    case("cone_unknown", deck("friction 0.5 cone coulomb"),
         ["cone must be lagged (the default), exact or convex", "'coulomb'"]),
    case("cone_no_friction", deck("cone convex"),
         ["cone applies with friction only", "remove cone or add friction"], np4=True),
    # speed
    case("speed_unknown", deck("friction 0.5 speed slip"),
         ["speed must be approach or contact (the default with friction)", "'slip'"]),
    case("speed_contact_no_friction", deck("speed contact"),
         ["speed contact applies with friction only", "remove speed or add friction"]),
    case("subspace_friction", deck("friction 0.5 subspace 10"),
         ["subspace applies without friction only", "remove subspace or friction"], np4=True),
    # rho
    case("rho_zero", deck("rho 0"), ["rho must be positive", "got 0"]),
    case("rho_negative", deck("rho -1"), ["rho must be positive", "got -1"]),
    case("rho_nan", deck("rho nan"), ["rho", "expected a number"]),
    # solver, warmstart
    case("solver_unknown", deck("solver nonsense"),
         ["solver 'nonsense' is unknown", "cg", "apgd", "uzawa"]),
    case("solver_exact_under_mpirun", deck("solver exact"),
         ["solver exact runs on one processor only", "use apgd"], np4=True, min_np=2),
    case("warmstart_maybe", deck("warmstart maybe"), ["warmstart must be yes or no", "'maybe'"]),
    case("warmstart_without_value", deck("warmstart"), ["warmstart needs 1 value"]),
    # walls
    case("wall_qplane", deck("wall qplane 0 1"),
         ["wall 'qplane' is unknown", "use xplane, yplane, zplane, region, stl or mesh"]),
    case("wall_null_null", deck("wall zplane NULL NULL"), ["lo and hi cannot both be NULL"]),
    case("wall_lo_equals_hi", deck("wall zplane 3 3"), ["lo (3) must be below hi (3)"]),
    case("wall_lo_above_hi", deck("wall zplane 4 3"), ["lo (4) must be below hi (3)"]),
    # moving walls
    case("wall_variable_missing", deck("wall zplane v_nowhere NULL"),
         ["variable nowhere does not exist"], np4=True),
    case("wall_variable_atom_style", deck("wall zplane v_za NULL", setup="variable za atom z"),
         ["variable za is not equal-style"]),
    # region walls
    case("wall_region_unknown", deck("wall region nowhere"),
         ["wall region nowhere", "no region with that ID"], np4=True,
         liggghts=["wall region nowhere"] + LIGGGHTS_NO_REGION_WALLS),
    case("wall_region_no_id", deck("wall region"), ["wall needs 2 value", "wall region ID"]),
    # triangle-mesh walls (wall stl): the file named, the problem said, on every rank count
    case("wall_stl_missing", deck("wall stl nowhere.stl"),
         ["wall stl", "STL file nowhere.stl", "cannot be opened"], np4=True),
    case("wall_stl_not_stl", deck("wall stl junk.stl"),
         ["STL file junk.stl", "neither ASCII STL", "nor binary STL"], np4=True,
         files={"junk.stl": "not a mesh at all\n"}),
    case("wall_stl_bad_number", deck("wall stl bad.stl"),
         ["STL file bad.stl", "line 5", "'1,5' is not a number"], np4=True,
         files={"bad.stl": "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                           "vertex 1,5 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid s\n"}),
    case("wall_stl_scale", deck("wall stl part.stl scale -2"),
         ["wall stl scale must be a positive factor", "-2"]),
    case("wall_stl_move_no_variable", deck("wall stl floor.stl move v_nowhere NULL NULL"),
         ["wall stl floor.stl", "variable nowhere does not exist", "variable nowhere equal"],
         np4=True, files={"floor.stl": FLOOR_STL}),
    case("wall_stl_move_nothing", deck("wall stl floor.stl move NULL NULL NULL"),
         ["move NULL NULL NULL moves nothing"], files={"floor.stl": FLOOR_STL}),
    case("wall_mesh_no_fix", deck("wall mesh nowhere"),
         ["wall mesh nowhere", "LAMMPS has no triangle-mesh fix", "wall stl FILE"], np4=True,
         liggghts=["wall mesh nowhere", "no fix with ID nowhere", "mesh/surface"]),
    case("wall_mesh_mover_after", deck("wall mesh cad",
         before_fix="fix cad all mesh/surface file floor.stl type 1",
         after_fix="fix mv all move/mesh mesh cad linear 0.1 0 0"),
         ["wall mesh cad", "fix mv (move/mesh) comes after this fix", "define fix mv before"],
         np4=True, files={"floor.stl": FLOOR_STL}, hosts=("liggghts",)),
    case("wall_stl_rotate_axis", deck("wall stl floor.stl rotate v_a 0 0 0 0 0 0"),
         ["rotate", "axis direction is zero"], files={"floor.stl": FLOOR_STL}),

    case("wall_region_atom_outside", deck("wall region small",
         setup="region small sphere 1.5 1.5 1.5 1.0 side in"),
         ["on the wrong side of wall region small"],
         liggghts=["wall region small"] + LIGGGHTS_NO_REGION_WALLS),
    case("wall_region_moving_union", deck("wall region mover", setup=(
        "variable dx equal 0.01*step\nregion a block 0 6 0 6 0 6 move v_dx NULL NULL\n"
        "region b sphere 3 3 3 1\nregion mover union 2 a b")),
         ["wall region mover", "union of moving regions has no known surface velocity",
          "its own 'wall region' keyword"],
         liggghts=["wall region mover"] + LIGGGHTS_NO_REGION_WALLS),
    # restitution and bounce
    case("restitution_above_one", deck("restitution 1.5"), ["restitution must be in [0, 1]"],
         np4=True),
    case("restitution_negative", deck("restitution -0.1"), ["restitution must be in [0, 1]"]),
    case("restitution_not_a_number", deck("restitution high"),
         ["restitution", "expected a number"]),
    case("restitution_one_type", deck("restitution 0.5 1"), ["restitution takes 1 or 3 value"]),
    case("restitution_type_out_of_range", deck("restitution 0.5 1 3"), ["out of bounds"]),
    case("cohesion_negative", deck("cohesion -1"), ["cohesion must be a force >= 0"]),
    case("cohesion_not_a_number", deck("cohesion strong"), ["cohesion", "expected a number"]),
    case("friction_negative", deck("friction -0.5"),
         ["friction must be a Coulomb coefficient >= 0"]),
    case("friction_not_a_number", deck("friction rough"), ["friction", "expected a number"]),
    case("wall_friction_negative", deck("wall zplane 0 NULL friction -1"),
         ["wall friction must be a Coulomb coefficient >= 0"]),
    case("wall_friction_type_range", deck("wall zplane 0 NULL friction 0.5 1 1"),
         ["wall ... friction takes one value", "'friction mu I J' before the wall keyword"]),
    case("wall_friction_no_value", deck("wall zplane 0 NULL friction"),
         ["wall ... friction needs a value"]),
    case("friction_exact_solver", deck("solver exact friction 0.5"),
         ["solver exact has no friction", "use hybrid (the default with friction), apgd, nsgs, pgs or uzawa"]),
    case("friction_cg_solver", deck("solver cg friction 0.5"),
         ["solver cg has no friction", "use hybrid (the default with friction), apgd, nsgs, pgs or uzawa"], np4=True),
    case("rolling_negative", deck("friction 0.5 rolling -0.1"),
         ["rolling must be a coefficient >= 0"]),
    case("rolling_without_friction", deck("rolling 0.1"),
         ["rolling needs friction", "add 'friction mu'"]),
    case("twisting_negative", deck("friction 0.5 twisting -0.1"),
         ["twisting must be a coefficient >= 0", "twisting torque is at most"]),
    case("twisting_without_friction", deck("rolling 0 twisting 0.1"),
         ["twisting needs friction", "add 'friction mu'"]),
    case("twisting_type_out_of_range", deck("friction 0.5 twisting 0.1 1 7"),
         ["out of bounds"]),
    case("disc_in_3d", deck("friction 0.5 disc"), ["disc requires 'dimension 2'"]),
    case("bounce_negative", deck("restitution 0.5 bounce -1"), ["bounce must be a speed >= 0"]),
    case("wall_lo_not_a_number", deck("wall zplane abc NULL"), ["wall lo", "expected a number"]),
    case("wall_hi_not_a_number", deck("wall zplane 0 nan"), ["wall hi", "expected a number"]),
    case("wall_below_box", deck("wall zplane -1 NULL"),
         ["wall zplane at -1 lies outside the box (0 to 6)", "move it inside"], np4=True),
    case("wall_above_box", deck("wall yplane NULL 7"),
         ["wall yplane at 7 lies outside the box", "move it inside"]),
    case("wall_periodic", deck("wall xplane 0 6", boundary="p f f"),
         ["wall xplane needs a non-periodic boundary", "boundary command"], np4=True),
    case("wall_zplane_2d", TWOD_DECK, ["wall zplane is not allowed in a 2d simulation"]),
    # the atoms
    case("radius_zero", deck(setup="set atom 4 diameter 0"),
         ["atom 4 has radius or mass <= 0", "set diameter"], np4=True),
    case("velocity_inf_from_variable",
         deck(setup="variable bad atom 1e308*10\nset atom 4 vx v_bad"),
         ["atom 4 has a non-finite", "velocity"], np4=True),
    case("velocity_nan_from_variable",
         deck(setup="variable bad atom (1e308*10)-(1e308*10)\nset atom 4 vy v_bad"),
         ["atom 4 has a non-finite", "velocity"]),
    case("velocity_inf_in_data_file", DATA_DECK, ["atom 4 has a non-finite", "data file"],
         files={"bad.data": DATA_BAD_VELOCITY},
         modern=["floating point number 1e999", "out of range"]),    # read_data checks it
    case("force_inf_during_run",
         deck(setup="variable big equal 1e308*10\ngroup g4 id 4",
              after_fix="fix push g4 addforce v_big 0 0"),
         ["atom 4 has a non-finite velocity or force at step 1"],
         # LIGGGHTS's kinetic energy is sum m (v + 0 f)^2 (compute ke): NaN at step 0 already
         liggghts_setup_nan=True),
    case("centre_behind_wall", deck("wall zplane NULL 4.2"),
         ["centre of atom 4 is behind a wall", "move the wall or the atom"], np4=True),
    # LIGGGHTS only: its granular neighbour list holds cross-processor pairs on both
    # processors only with newton off (the LIGGGHTS host's decks get 'newton off' first)
    case("newton_on_liggghts", deck(setup="newton on off"),    # pair on, bond as before
         ["requires 'newton off'", "LIGGGHTS"], np4=True, hosts=("liggghts",)),
    # box and run style
    case("triclinic_box", TRICLINIC_DECK, ["does not support triclinic"]),
    case("run_style_respa", deck(after_fix="run_style respa 2 2"),
         ["does not support run_style respa", "use verlet"]),
    # skin: the message names the skin to use (and that skin works, see check_skin_advice)
    case("skin_too_small", SKIN_DECK,
         ["together more than the skin", "use 'neighbor", "bin'"], np4=True),
]


# Decks where the fix misbehaves today, with what the fix should do: fixed(res) is True once
# it does (res is None when the deck ran without error, else the failed run's RunResult).
# Run with --known-bugs; not registered in ctest.
KnownBug = namedtuple("KnownBug", "name deck fixed bug files")
KnownBug.__new__.__defaults__ = ({},)

FALLING_SPHERE = """units           lj
atom_style      sphere
boundary        f f f
region          box block 0 10 0 10 -500 10
create_box      1 box
create_atoms    1 single 5 5 5 units box
pair_style      none
neighbor        {skin} bin
timestep        0.05
fix             g all gravity 1.0 vector 0 0 -1
fix             1 all hardcontact
run             {steps}
"""


POUR = """units           lj
atom_style      sphere
boundary        f f f
read_data       pour.data
pair_style      none
neighbor        2.0 bin
timestep        0.02
fix             g all gravity 10.0 vector 0 0 -1
fix             1 all hardcontact wall xplane 0 {w} wall yplane 0 {w} wall zplane 0 NULL
thermo          100
run             1000
"""


def pour_data():
    """200 spheres (d 0.8-1) on a jittered lattice from z = 5.6 up, falling into a 6 x 6 box."""
    s = sd.pile(n_side=5, layers=8, seed=1, height=40.0, v_down=0.0, v_random=0.2)
    s = s._replace(pos=s.pos + [0.0, 0.0, 5.0])
    return s


def _data_text(scene):
    fd, path = tempfile.mkstemp(suffix=".data")
    os.close(fd)
    try:
        sd.write_data(path, scene, "known bug: pour")
        with open(path) as f:
            return f.read()
    finally:
        os.unlink(path)


def _runs_clean(res):
    return res is None


def _error_with(*phrases):
    return lambda res: res is not None and any(
        all(p.lower() in e.lower() for p in phrases) for e in res.errors)


KNOWN_BUGS = [
    KnownBug("skin_false_alarm_under_gravity", FALLING_SPHERE.format(skin=1.5, steps=200),
             _runs_clean,
             "one sphere falling under gravity (no contact possible, largest move per step "
             "0.38 < skin/2 = 0.75) stops at step 151 with 'an atom moved 0.7525 since the last "
             "neighbor list build, more than half the skin': the rebuild is forced only when "
             "disp + (this step's move) > skin/2, so an atom whose speed grows (gravity, a "
             "collision) overshoots by the increase of its step"),
    KnownBug("skin_false_alarm_pour", POUR.format(w=repr(pour_data().box[0, 1])), _runs_clean,
             "a realistic pour (200 spheres, g 10, h 0.02, 'neighbor 2.0 bin') stops at step 63: "
             "'an atom moved 1.00159 since the last neighbor list build, more than half the skin "
             "(1) ... The largest move in one step was 0.256398: use 'neighbor 1.03 bin'' - the "
             "largest move per step is a quarter of skin/2, and the advice is half the skin in "
             "use (skin 1.2: step 50, advice 0.818; skins 0.8, 1.0 and 1.5 happen to pass)",
             files={"pour.data": lambda: _data_text(pour_data())}),
    KnownBug("skin_advice_smaller_than_current", FALLING_SPHERE.format(skin=1.51, steps=200),
             _runs_clean,
             "the same deck with the skin the previous ERROR asked for ('neighbor 1.51 bin') "
             "stops at step 53 and now asks for 'neighbor 0.53 bin', smaller than the skin in "
             "use (with skin 6.0: step 242, asks for 2.42)"),
    KnownBug("radius_growth_without_reneighbor",
             deck(style="sphere 1", setup="variable d equal 1.0+step*0.5",
                  after_fix="fix grow all adapt 1 atom diameter v_d\n"
                            "thermo_style custom step f_1[2] f_1[3] f_1[7]\nrun 10"),
             _error_with("radius"),
             "fix adapt grows the spheres at rest from diameter 1 to 8.5 (centres 3 apart): "
             "the run goes on with overlaps of 5.5, no ERROR and f_1[2] = f_1[3] = 0; the check "
             "'an atom of radius ... appeared during the run' is only made at neighbor list "
             "builds, and at rest none happens; the overlap diagnostics only see candidate rows"),
    KnownBug("radius_growth_advice_ineffective",
             deck(style="sphere 1", boundary="p f f",
                  setup="variable d equal 1.0+step*0.01\nvelocity all set 10 0 0 units box",
                  before_fix="comm_modify cutoff 3.0",
                  after_fix="fix grow all adapt 1 atom diameter v_d"),
             lambda res: res is None or not _error_with("comm_modify cutoff")(res),
             "the ERROR for a growing radius says \"use 'comm_modify cutoff 1.31' and restart "
             "the run\", but with comm_modify cutoff 3.0 the same ERROR comes back: the check "
             "compares with the largest radius at the start of the run and ignores the ghost "
             "cutoff, so the advice cannot help"),
    KnownBug("wall_with_shrink_wrapped_boundary",
             deck("wall zplane 0 NULL", boundary="p p s",
                  after_fix="fix g all gravity 1.0 vector 0 0 -1\nrun 500"),
             _runs_clean,
             "boundary p p s with a floor 'wall zplane 0 NULL': the first run is fine, the box "
             "then shrink-wraps to the atoms (z from 0.499 up) and the second run stops with "
             "'wall zplane at 0 lies outside the box (0.499375 to 1.43...): move it inside', "
             "although the floor is where it should be"),
    KnownBug("maxiter_overflow", deck("maxiter 99999999999"), _error_with("maxiter"),
             "maxiter 99999999999 is accepted silently (wraps to 1215752191), and maxiter "
             "3000000000 is refused with 'maxiter must be at least 1, got 3000000000': an int "
             "overflow in utils::inumeric, not caught by the fix"),
]


_QUOTED = re.compile(r"'[^']*'|\"[^\"]*\"")
_NAN = re.compile(r"(?<![A-Za-z_])-?nan(?![A-Za-z_])", re.IGNORECASE)


def nan_lines(res, deck_text, skip_step0=False):
    """Output lines with a NaN, leaving out the echo of the deck and user input quoted back
    (and the thermo row of step 0 with skip_step0)."""
    echoed = {l.strip() for l in deck_text.splitlines() if l.strip()}
    bad = []
    for text in (res.log, res.stdout, res.stderr):
        for line in (text or "").splitlines():
            s = line.strip()
            # the deck's last line echoed back: "Last command:" (old), "Last input line:" (modern)
            if not s or s in echoed or s.startswith(("Last command:", "Last input line:")):
                continue
            if skip_step0 and s.split()[0] == "0":
                continue
            if _NAN.search(_QUOTED.sub("''", s)):
                bad.append(s)
    return bad


def run_case(args, name, deck_text, files, np):
    workdir = "%s/%s" % (args.workdir, name)
    lr.fresh_workdir(workdir)
    for fname, text in files.items():
        with open("%s/%s" % (workdir, fname), "w") as f:
            f.write(text)
    return lr.run_deck(args.lmp, deck_text, np, workdir, expect_error=True,
                       timeout=min(args.timeout, CASE_TIMEOUT))


def check_error_case(args, c):
    """All the checks of one table row; returns the failures (empty: passed)."""
    problems = []
    try:
        res = run_case(args, c.name, c.deck, c.files, args.np)
    except lr.LammpsRunError as e:
        return ["%s" % e]
    head = "%s (np %d, exit %s, %.1f s)" % (c.name, args.np, res.returncode, res.seconds)
    if res.returncode == 0 or res.returncode is None:
        problems.append("exit status %s, expected non-zero" % res.returncode)
    if res.returncode is not None and res.returncode < 0:
        problems.append("killed by signal %d (a crash, not a clean ERROR)" % -res.returncode)
    lammps_own = c.modern is not None and args.lmp.name == "modern"
    liggghts_own = c.liggghts is not None and args.lmp.name == "liggghts"
    if ("MPI_ABORT" in res.stderr or "MPI_Abort" in res.stderr) and not lammps_own:
        problems.append("MPI_Abort instead of a clean error->all")
    clean = [e for e in res.errors if e.startswith("ERROR:") or (lammps_own and e.startswith("ERROR"))]
    if not clean:
        problems.append("no 'ERROR:' line (error->all on every rank); ERROR lines: %s" % res.errors)
    want = [p.lower() for p in (c.modern if lammps_own else c.liggghts if liggghts_own else c.phrases)]
    if clean and not any(all(p in e.lower() for p in want) for e in clean):
        problems.append("no ERROR line holds all of %s: %s" % (want, clean))
    nans = nan_lines(res, c.deck,
                     skip_step0=c.liggghts_setup_nan and args.lmp.name == "liggghts")
    if nans:
        problems.append("'nan' in the output: %s" % nans[:3])
    if not problems:
        print("ok: %s: %s" % (head, clean[0][:160]))
        if c.name == "skin_too_small":
            problems += check_skin_advice(args, clean)
    else:
        problems = ["%s: %s\n%s" % (head, p, res.summary(15)) for p in problems]
    return problems


def check_skin_advice(args, errors):
    m = None
    for e in errors:
        m = m or re.search(r"use 'neighbor ([0-9.eE+-]+) bin'", e)
    if not m:
        return ["skin_too_small: no skin value in the ERROR: %s" % errors]
    skin = float(m.group(1))
    fixed = SKIN_DECK.replace("neighbor 0.001 bin", "neighbor %s bin" % m.group(1))
    workdir = "%s/skin_too_small_advice" % args.workdir
    lr.fresh_workdir(workdir)
    try:
        res = lr.run_deck(args.lmp, fixed, args.np, workdir, timeout=min(args.timeout, CASE_TIMEOUT))
    except lr.LammpsRunError as e:
        return ["skin_too_small: the suggested 'neighbor %g bin' does not run: %s" % (skin, e)]
    lr.check(res.returncode == 0 and not res.errors,
             "skin_too_small: the suggested 'neighbor %g bin' runs the deck without ERROR" % skin)
    return []


def check_known_bug(args, b):
    """None when the deck now behaves, else a description of what it still does."""
    try:
        files = {k: (v() if callable(v) else v) for k, v in b.files.items()}
        res = run_case(args, "known_bug_" + b.name, b.deck, files, args.np)
    except lr.LammpsRunError as e:
        if "expected to fail but exited 0" not in str(e):
            return "%s: %s" % (b.name, e)      # timed out
        res = None
    if b.fixed(res):
        return None
    what = "ran without ERROR" if res is None else "ERROR lines %s" % res.errors
    return "%s: %s\n  bug: %s" % (b.name, what, b.bug)


def test():
    p_args = [a for a in sys.argv[1:] if a != "--known-bugs"]
    known = len(p_args) != len(sys.argv) - 1
    args = lr.test_args(__doc__, p_args)

    if known:
        still = [r for r in (check_known_bug(args, b) for b in KNOWN_BUGS) if r]
        for r in still:
            print("KNOWN BUG:", r)
        lr.check(not still, "%d of %d known fix bugs still present" % (len(still), len(KNOWN_BUGS)))
        return

    cases = [c for c in CASES if (args.np < 4 or c.np4) and args.np >= c.min_np
             and (c.hosts is None or args.lmp.name in c.hosts)]
    failures = []
    for c in cases:
        failures += check_error_case(args, c)
    for f in failures:
        print("FAILED:", f, file=sys.stderr)
    lr.check(not failures, "%d bad decks (np %d) each end with the expected ERROR, cleanly and "
                           "fast (%d failed)" % (len(cases), args.np, len(failures)))


if __name__ == "__main__":
    lr.main(test)
