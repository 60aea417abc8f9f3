# Example deck tests: each examples/<scene>/ deck run in a shortened form (variables such as
# nsteps) and its numbers checked. Label "examples" (+ "integration"). All together they are
# meant to stay under about 4 minutes on 2 busy cores.

# paper 6.2: sticky particles, h = 0.01, 0.5, 1.5, final state against the exact solution
hardcontact_deck_test(NAME example_sticky_particles SCRIPT integration/test_example_sticky.py
                      NP 1 LABELS examples TIMEOUT 120)

# pile: 750 discs settle (0.15 s), hard contacts and the soft-sphere twin, compare.py
hardcontact_deck_test(NAME example_pile SCRIPT integration/test_example_pile.py
                      NP 1 LABELS examples TIMEOUT 240)

# pour: fix pour drops 150 discs (0.4 s), hard contacts and the soft-sphere twin
hardcontact_deck_test(NAME example_pour SCRIPT integration/test_example_pour.py
                      NP 1 LABELS examples TIMEOUT 240)

# potentials/glass_beads.params: the restitution asked for is the one gran/hertz/history gives
hardcontact_deck_test(NAME example_glass_params SCRIPT integration/test_example_glass_params.py
                      NP 1 LABELS examples TIMEOUT 120)

# disc_packing: 500 bidisperse discs compressed by gravity: random close packing, isostatic
hardcontact_deck_test(NAME example_disc_packing SCRIPT integration/test_example_disc_packing.py
                      NP 1 LABELS examples TIMEOUT 240)

# hopper: 2d silo on a floor of frozen discs, 480 discs drain through 8 and 12 mm outlets
hardcontact_deck_test(NAME example_hopper SCRIPT integration/test_example_hopper.py
                      NP 1 LABELS examples TIMEOUT 240)

# cluster_impact (the flagship, paper 6.3): 6 steps of the 2000-disc impact at h = 0.1
hardcontact_deck_test(NAME example_cluster_impact SCRIPT integration/test_example_cluster_impact.py
                      NP 1 LABELS examples TIMEOUT 300)

hardcontact_deck_test(NAME example_bouncing_ball SCRIPT integration/test_example_bouncing_ball.py
                      NP 1 LABELS examples TIMEOUT 120)

# liggghts_settle (LIGGGHTS decks): 468 beads settle, hard contacts and the Hertz twin, as shipped
hardcontact_deck_test(NAME example_liggghts_settle SCRIPT integration/test_example_liggghts_settle.py
                      NP 1 LABELS examples TIMEOUT 240 HOSTS liggghts)

# liggghts_hopper (LIGGGHTS decks): beads settle in and drain from a hopper read from an STL
# file by fix mesh/surface (`wall mesh cad`), and the wall/gran mesh twin; shortened (about 750
# beads, 0.25 s of discharge; 11 s)
hardcontact_deck_test(NAME example_liggghts_hopper SCRIPT integration/test_example_liggghts_hopper.py
                      NP 1 LABELS examples TIMEOUT 300 HOSTS liggghts)

# mixer: a drum with 6 lifters from an STL file (wall stl ... rotate) mixes two halves of a
# bed, and the bare drum; one revolution each (5 s); the launcher (CI time; the mesh code is
# the same on every host and test_phys_mesh_wall runs it on all three)
hardcontact_deck_test(NAME example_mixer SCRIPT integration/test_example_mixer.py
                      NP 1 LABELS examples TIMEOUT 120 HOSTS launcher)

# heap: 300 spheres poured onto a rough floor with mu 0.1 and with mu 0.5 + rolling 0.1:
# the angle of repose grows with friction (LAMMPS hosts; LIGGGHTS pours with fix insert/pour
# and particle templates, another deck)
hardcontact_deck_test(NAME example_heap SCRIPT integration/test_example_heap.py
                      NP 1 LABELS examples TIMEOUT 300 HOSTS launcher modern)

# hopper3d: 600 beads (mu 0.5) settle in a conical hopper (region wall) and drain through a
# 10 mm outlet, hard and soft: no bead leaves the cone, overlaps within tol, Beverloo-band rate
hardcontact_deck_test(NAME example_hopper3d SCRIPT integration/test_example_hopper3d.py
                      NP 1 LABELS examples TIMEOUT 240 HOSTS launcher modern)

# drum: 120 spheres in a drum rotating at Froude number 0.01 (0.11 revolution): the bed stays in
# the drum and is dragged up the rising side, its surface tilts; soft twin; the decks differ only
# in their contact block (LAMMPS hosts: LIGGGHTS has no region walls)
hardcontact_deck_test(NAME example_drum SCRIPT integration/test_example_drum.py
                      NP 1 LABELS examples TIMEOUT 300 HOSTS launcher modern)
