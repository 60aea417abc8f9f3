# Physics deck tests: real decks through lmp_hardcontact, asserted against analytic answers of
# scheme (S) (B. Maury 2006). Each script's docstring says what it checks and why.
# Label "physics" (+ "integration" from hardcontact_deck_test), "soak" for the long ones.
# Those with HOSTS ... liggghts run through build/liggghts_hardcontact too (LIGGGHTS 3.8; all
# but region walls, which LIGGGHTS cannot have: lammps_compat.h).

# two spheres head-on in 3D: momentum-weighted normal velocity, tangential unchanged
hardcontact_deck_test(NAME phys_head_on SCRIPT integration/test_phys_head_on.py NP 1 2 4
                      LABELS physics TIMEOUT 180 HOSTS launcher modern liggghts)
# a row of 10 touching spheres struck at one end: all leave with m v / M, exact per step
hardcontact_deck_test(NAME phys_chain SCRIPT integration/test_phys_chain.py NP 1 2 4
                      LABELS physics TIMEOUT 180 HOSTS launcher modern liggghts)
# a sphere falling under gravity onto a wall: rests on it, weight carried by the wall
hardcontact_deck_test(NAME phys_wall_rest SCRIPT integration/test_phys_wall_rest.py NP 1 2 4
                      LABELS physics TIMEOUT 180 HOSTS launcher modern liggghts)
# the paper's 6.3 cluster (2029 discs, h = 0.1): onto a wall, and two halves colliding;
# with 4 ranks on 2 cores these take 50-100 s each: soak (phys_cluster_ranks runs 4 ranks)
foreach(_case wall free)
  hardcontact_deck_test(NAME phys_cluster_${_case} SCRIPT integration/test_phys_cluster.py
                        NP 1 2 4 SOAK_NP 4 LABELS physics ARGS --case ${_case} TIMEOUT 900
                        HOSTS launcher modern liggghts)
endforeach()

# one step of the 6.3 impact from the same states with 1, 2 and 4 ranks: agreement within tol
# (runs all three rank counts itself)
hardcontact_deck_test(NAME phys_cluster_ranks SCRIPT integration/test_phys_cluster_ranks.py
                      NP 4 LABELS physics TIMEOUT 900
                      HOSTS launcher modern liggghts)
# the whole 6.3 impact with 1, 2 and 4 ranks (long under mpirun on 2 cores)
hardcontact_deck_test(NAME phys_cluster_ranks_full SCRIPT integration/test_phys_cluster_ranks.py
                      NP 4 LABELS physics soak ARGS --full TIMEOUT 2400)

# The opt-in effects, each at np 1, 2 and 4 (integration/test_phys_<effect>.py):
#  restitution  head-on pair leaves at e V (per type pair), e = 0 bit-identical to none, a ball
#               bouncing to e^2 of its height until its impact speed falls below `bounce`
#  moving_wall  walls at variable positions: a rising floor carries a sphere, a vibrated floor
#               is followed below g and left above, a piston pushes without overlap
#  region_wall  walls made of regions: cylinder, cone (hopper), bowl (inside), spherical
#               obstacle (outside): no overlap beyond the documented bounds, resting heights
#  moving_region  region walls that move: a plane region sliding under a sphere (friction: it
#               spins up and rolls at 2/7 V from t* = 2 V / (7 mu g)), rising under it (carried),
#               a rotating drum (bed dragged up, nothing leaves), restart
#  cohesion     a sphere hangs under a ceiling iff m g < F; a touching pair pulled apart opens
#               at F; cohesion 0 bit-identical to none
#  friction     a sphere rolls down an incline at 5/7 g sin or slips at g (sin - mu cos), a
#               launched sphere slides then rolls at 5/7 v0, no lift-off while sliding, the
#               dissipation output, oblique pairs stick/slide at 7/2 mu, friction 0
#               bit-identical to none, a spinning gas: energy never grows, linear and angular
#               momentum exact, ranks agree
#  twisting     a sphere spinning about the vertical on a floor stops at t* = 2 w0 r / (5 mut g)
#               and the contact dissipates 1/2 I w0^2; with rolling too, each stops as alone; a
#               head-on pair's twist slides by 5/4 mut v0 / r or sticks, angular momentum exact
foreach(_effect restitution moving_wall region_wall moving_region cohesion friction twisting)
  set(_hosts launcher modern liggghts)
  if(_effect MATCHES "region")
    set(_hosts launcher modern)    # LIGGGHTS 3.8 has no region walls (lammps_compat.h)
  endif()
  hardcontact_deck_test(NAME phys_${_effect} SCRIPT integration/test_phys_${_effect}.py
                        NP 1 2 4 LABELS physics TIMEOUT 300 HOSTS ${_hosts})
endforeach()

# Triangle-mesh walls (test_phys_mesh_wall.py): a sphere rolls down a slope of triangles at
# 5/7 g sin as on a region plane (no bump at the edges), spheres slide across a floor of
# triangles (through their shared vertices) unchanged, spheres in a closed cube (binary STL)
# move as between plane walls and never leave it, sliding / rising / rotating meshes (conveyor,
# lift, drum), restart; on LIGGGHTS also `wall mesh` on fix mesh/surface and fix move/mesh.
# Every host serially, the launcher with 2 ranks; with 4 ranks as soak on every host (CI time: 24-29 s
# on both cores; the meshes are searched by each sphere's owner, the same code on every host,
# and np 4 passes on all three hosts).
hardcontact_deck_test(NAME phys_mesh_wall SCRIPT integration/test_phys_mesh_wall.py NP 1 4 SOAK_NP 4
                      LABELS physics TIMEOUT 300 HOSTS launcher modern liggghts)
hardcontact_deck_test(NAME phys_mesh_wall_np2 SCRIPT integration/test_phys_mesh_wall.py
                      NP 2 LABELS physics TIMEOUT 300 HOSTS launcher)

# the same friction decks solved by nsgs (block Gauss-Seidel on the true Coulomb law, no De
# Saxce fixed point): the analytic rolling, slipping and stopping outcomes, the oblique pair,
# and the spinning gas's energy, momenta and rank agreement; serially on every host, under
# mpirun (np 4, the block-Jacobi split across processors) on the launcher (CI time: each np 4
# run takes 40-47 s and both cores)
hardcontact_deck_test(NAME phys_friction_nsgs_np1 SCRIPT integration/test_phys_friction.py
                      NP 1 LABELS physics TIMEOUT 300 ARGS --solver nsgs
                      HOSTS launcher modern liggghts)
# (np 4 is soak since 2026-12-06, CI time: 44 s on both cores; the default solver, hybrid, runs
# nsgs sweeps under mpirun in phys_friction_np4 on every host)
hardcontact_deck_test(NAME phys_friction_nsgs_np4 SCRIPT integration/test_phys_friction.py
                      NP 4 LABELS physics soak TIMEOUT 300 ARGS --solver nsgs HOSTS launcher)

# the contact virial: a column at rest gives the hydrostatic stress/atom profile and pressure
# exactly (frictionless and with friction; `fix_modify virial no` takes it out); a box
# compressed by a moving wall gives the virial identity of each step and the wall's force over
# its area as the mean pressure. Every rank count on the launcher; LIGGGHTS (newton off, its
# own compute syntax) serially and at np 2; the plugin serially
hardcontact_deck_test(NAME phys_stress SCRIPT integration/test_phys_stress.py NP 1 2
                      LABELS physics TIMEOUT 300 HOSTS launcher modern liggghts
                      MPI_HOSTS launcher liggghts)
hardcontact_deck_test(NAME phys_stress_np4 SCRIPT integration/test_phys_stress.py NP 4
                      LABELS physics TIMEOUT 300 HOSTS launcher)

# the neighbor rebuild look-ahead under acceleration: a falling sphere with a skin 9 x its step
hardcontact_deck_test(NAME phys_skin_lookahead SCRIPT integration/test_phys_skin_lookahead.py
                      NP 1 LABELS physics TIMEOUT 300 HOSTS launcher modern liggghts)

# the subspace start (subspace N) of cg and apgd: a heavy sphere at rest on a tray, with and without: same
# height, no overlap beyond tol, at most half the iterations; ranks take the same coefficients
hardcontact_deck_test(NAME phys_subspace SCRIPT integration/test_phys_subspace.py NP 1 2 4
                      LABELS physics TIMEOUT 300 HOSTS launcher modern liggghts)

# adaptive steps (issue 36): fix dt/reset with the fix - a sphere's free fall is the scheme's
# with the steps dt/reset chose, then it rests on the wall (drop); a frictional pile settles at
# rest with 0.6 x the steps or fewer and the fixed step's height within 5 % (pile)
foreach(_case drop pile)
  hardcontact_deck_test(NAME phys_dt_reset_${_case} SCRIPT integration/test_phys_dt_reset.py
    NP 1 2 4 LABELS physics HOSTS launcher modern ARGS --case ${_case} TIMEOUT 300)
endforeach()
