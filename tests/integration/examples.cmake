# Example deck tests: each examples/<scene>/ deck run in a shortened form (variables such as
# nsteps) and its numbers checked. Label "examples" (+ "integration"). All together they are
# meant to stay under about 4 minutes on 2 busy cores.

# example_test(<name> [SCRIPT <stem>] <timeout> [HOSTS ...]): test example_<name> runs
# integration/test_example_<stem or name>.py on one rank (hosts: hardcontact_deck_test's default)
function(example_test name)
  cmake_parse_arguments(PARSE_ARGV 1 E "" "SCRIPT" "HOSTS")
  if(NOT E_SCRIPT)
    set(E_SCRIPT ${name})
  endif()
  set(_hosts)
  if(E_HOSTS)
    set(_hosts HOSTS ${E_HOSTS})
  endif()
  hardcontact_deck_test(NAME example_${name} SCRIPT integration/test_example_${E_SCRIPT}.py
                        NP 1 LABELS examples TIMEOUT ${E_UNPARSED_ARGUMENTS} ${_hosts})
endfunction()

# paper 6.2: sticky particles, h = 0.01, 0.5, 1.5, final state against the exact solution
example_test(sticky_particles SCRIPT sticky 120)

# pile: 750 discs settle (0.15 s), hard contacts and the soft-sphere twin, compare.py
example_test(pile 240)

# pour: fix pour drops 150 discs (0.4 s), hard contacts and the soft-sphere twin
example_test(pour 240)

# potentials/glass_beads.params: the restitution asked for is the one gran/hertz/history gives
example_test(glass_params 120)

# disc_packing: 500 bidisperse discs compressed by gravity: random close packing, isostatic
example_test(disc_packing 240)

# hopper: 2d silo on a floor of frozen discs, 480 discs drain through 8 and 12 mm outlets
example_test(hopper 240)

# cluster_impact (the flagship, paper 6.3): 6 steps of the 2000-disc impact at h = 0.1
example_test(cluster_impact 300)

# bouncing_ball: restitution against a still and a vibrated floor, apexes at e^(2k) H, rest
example_test(bouncing_ball 120)

# liggghts_settle (LIGGGHTS decks): 468 beads settle, hard contacts and the Hertz twin, as shipped
example_test(liggghts_settle 240 HOSTS liggghts)

# liggghts_hopper (LIGGGHTS decks): beads settle in and drain from a hopper read from an STL
# file by fix mesh/surface (`wall mesh cad`), and the wall/gran mesh twin; shortened (about 750
# beads, 0.25 s of discharge; 11 s)
example_test(liggghts_hopper 300 HOSTS liggghts)

# mixer: a drum with 6 lifters from an STL file (wall stl ... rotate) mixes two halves of a
# bed, and the bare drum; one revolution each (5 s); the launcher (CI time; the mesh code is
# the same on every host and test_phys_mesh_wall runs it on all three)
example_test(mixer 120 HOSTS launcher)

# heap: 300 spheres poured onto a rough floor with mu 0.1 and with mu 0.5 + rolling 0.1:
# the angle of repose grows with friction (LAMMPS hosts; LIGGGHTS pours with fix insert/pour
# and particle templates, another deck)
example_test(heap 300 HOSTS launcher modern)

# hopper3d: 600 beads (mu 0.5) settle in a conical hopper (region wall) and drain through a
# 10 mm outlet, hard and soft: no bead leaves the cone, overlaps within tol, Beverloo-band rate
example_test(hopper3d 240 HOSTS launcher modern)

# drum: 120 spheres in a drum rotating at Froude number 0.01 (0.11 revolution): the bed stays in
# the drum and is dragged up the rising side, its surface tilts; soft twin; the decks differ only
# in their contact block (LAMMPS hosts: LIGGGHTS has no region walls)
example_test(drum 300 HOSTS launcher modern)

# column_collapse: a quasi-2D column (L0 6, about 300 spheres) released onto a rough floor,
# mu 0.5 and 0.1, and the soft twin: runout ordering, the experiments' band, the twin's runout
example_test(column_collapse 300 HOSTS launcher modern)
