# "Hard cases stay numerically stable": the paper's guarantees (feasibility Prop. 2, energy
# Prop. 3, momentum Prop. 4 / Remark 10, bounded multipliers Prop. 5 / Lemma 1) on scenes built
# to break them. What each test does, its tolerances and measured results: doc/stability.md.
# Scripts: tests/integration/test_stab_*.py (+ stability_common.py). Label "stability" on all;
# long variants carry "soak" (skipped by tests/run_all.sh and CI). --timeout bounds each LAMMPS
# run inside a test (the harness kills a hung run itself; keep it below the ctest TIMEOUT
# divided by the number of runs of the test).

# step-size sweep, h from 0.002 to 5 diameters per step: no wall / a floor; default tol, a tight
# one (1e-10) and the exact solver (the exact-projection properties at round-off)
hardcontact_deck_test(NAME stab_step_sweep_free_np1 HOSTS launcher SCRIPT integration/test_stab_step_sweep.py NP 1
  LABELS stability ARGS --case free --timeout 60 TIMEOUT 300)
hardcontact_deck_test(NAME stab_step_sweep_free_np2 HOSTS launcher SCRIPT integration/test_stab_step_sweep.py NP 2
  LABELS stability ARGS --case free --steps small,huge --timeout 60 TIMEOUT 300)
hardcontact_deck_test(NAME stab_step_sweep_free_tight_np1 HOSTS launcher SCRIPT integration/test_stab_step_sweep.py NP 1
  LABELS stability ARGS --case free --tol 1e-10 --timeout 60 TIMEOUT 300)
hardcontact_deck_test(NAME stab_step_sweep_free_exact_np1 HOSTS launcher SCRIPT integration/test_stab_step_sweep.py NP 1
  LABELS stability ARGS --case free --solver exact --steps tiny,small,medium --timeout 60 TIMEOUT 300)
hardcontact_deck_test(NAME stab_step_sweep_wall_np1 HOSTS launcher SCRIPT integration/test_stab_step_sweep.py NP 1
  LABELS stability ARGS --case wall --timeout 60 TIMEOUT 300)
hardcontact_deck_test(NAME stab_step_sweep_wall_np2 HOSTS launcher SCRIPT integration/test_stab_step_sweep.py NP 2
  LABELS stability ARGS --case wall --steps small,huge --timeout 60 TIMEOUT 300)
# the same with the projected CG solver (the default without friction)
foreach(_case free wall)
  hardcontact_deck_test(NAME stab_step_sweep_${_case}_cg_np1 HOSTS launcher SCRIPT integration/test_stab_step_sweep.py NP 1
    LABELS stability ARGS --case ${_case} --solver cg --timeout 60 TIMEOUT 300)
  hardcontact_deck_test(NAME stab_step_sweep_${_case}_cg_np2 HOSTS launcher SCRIPT integration/test_stab_step_sweep.py NP 2
    LABELS stability ARGS --case ${_case} --solver cg --steps small,huge --timeout 60 TIMEOUT 300)
endforeach()
hardcontact_deck_test(NAME stab_step_sweep_free_tight_cg_np1 HOSTS launcher SCRIPT integration/test_stab_step_sweep.py NP 1
  LABELS stability ARGS --case free --solver cg --tol 1e-10 --timeout 60 TIMEOUT 300)

# dense crystals (hexagonal 2d, FCC 3d) squeezed by gravity between walls: 10^3 steps at rest
# in CI, 10^4 in the soak variants; apgd warm/cold, uzawa and exact must agree
foreach(_dim 2 3)
  # the exact-solver run alone takes 25 s (2d) / 40 s (3d) on an idle core: room for a loaded one
  hardcontact_deck_test(NAME stab_crystal_${_dim}d_np1 HOSTS launcher SCRIPT integration/test_stab_crystal.py NP 1
    LABELS stability ARGS --dim ${_dim} --timeout 240 TIMEOUT 600)
  hardcontact_deck_test(NAME stab_crystal_${_dim}d_soak_np1 HOSTS launcher SCRIPT integration/test_stab_crystal.py NP 1
    LABELS "stability;soak" ARGS --dim ${_dim} --steps 10000 --timeout 600 TIMEOUT 2400)
endforeach()
hardcontact_deck_test(NAME stab_crystal_2d_np2 HOSTS launcher SCRIPT integration/test_stab_crystal.py NP 2
  LABELS stability ARGS --dim 2 --variants apgd_warm,apgd_cold,cg_warm --timeout 60 TIMEOUT 150)

# radius ratio 10, mass ratio 1000: heavy spheres through a bed of light ones
hardcontact_deck_test(NAME stab_polydisperse HOSTS launcher SCRIPT integration/test_stab_polydisperse.py NP 1 2
  LABELS stability ARGS --timeout 120 TIMEOUT 300)
# the same on a frictional bed (mu 0.5) at the fix's default tolerance with friction (1e-2)
hardcontact_deck_test(NAME stab_polydisperse_friction HOSTS launcher SCRIPT integration/test_stab_polydisperse.py
  NP 1 2 LABELS stability ARGS --friction 0.5 --timeout 120 TIMEOUT 300)

# deep piles: a 40-row disordered 2d pile and a 60-sphere column; in CI the default solvers
# (cg without friction, apgd) on both, and on the column the paper's uzawa and the exact
# reference; soak: 2 x 10^4 steps each
foreach(_solver apgd cg)
  hardcontact_deck_test(NAME stab_deep_pile_pile2d_${_solver}_np1 HOSTS launcher SCRIPT integration/test_stab_deep_pile.py
    NP 1 LABELS stability ARGS --case pile2d --solver ${_solver} --timeout 90 TIMEOUT 240)
endforeach()
foreach(_solver apgd cg uzawa exact)
  hardcontact_deck_test(NAME stab_deep_pile_column_${_solver}_np1 HOSTS launcher SCRIPT integration/test_stab_deep_pile.py
    NP 1 LABELS stability ARGS --case column --solver ${_solver} --timeout 40 TIMEOUT 120)
endforeach()
foreach(_case pile2d column)
  foreach(_solver apgd cg uzawa)
    hardcontact_deck_test(NAME stab_deep_pile_${_case}_${_solver}_soak_np1 HOSTS launcher SCRIPT integration/test_stab_deep_pile.py
      NP 1 LABELS "stability;soak" ARGS --case ${_case} --solver ${_solver} --steps 20000 --timeout 1700
      TIMEOUT 3600)
  endforeach()
endforeach()

# degenerate geometry: gap 0, coincident centres, spheres touching walls, all at rest, chains
hardcontact_deck_test(NAME stab_degenerate_np1 HOSTS launcher SCRIPT integration/test_stab_degenerate.py NP 1
  LABELS stability ARGS --timeout 30 TIMEOUT 240)
hardcontact_deck_test(NAME stab_degenerate_np2 HOSTS launcher SCRIPT integration/test_stab_degenerate.py NP 2
  LABELS stability ARGS --cases touching,coincident,chain --timeout 30 TIMEOUT 120)

# a closed box of walls with no force: 10^4 steps in CI, 10^5 soak
hardcontact_deck_test(NAME stab_long_run_np1 HOSTS launcher SCRIPT integration/test_stab_long_run.py NP 1
  LABELS stability ARGS --steps 10000 --timeout 100 TIMEOUT 120)
hardcontact_deck_test(NAME stab_long_run_soak_np1 HOSTS launcher SCRIPT integration/test_stab_long_run.py NP 1
  LABELS "stability;soak" ARGS --steps 100000 --timeout 1700 TIMEOUT 1800)

# the sanitizer build (tests/sanitize.sh): a second build tree under this one, ~20-40 min
if(TARGET lmp_hardcontact)
  add_test(NAME stab_sanitize
    COMMAND bash "${PROJECT_SOURCE_DIR}/tests/sanitize.sh" "${CMAKE_BINARY_DIR}/sanitize"
    WORKING_DIRECTORY "${PROJECT_SOURCE_DIR}")
  set_tests_properties(stab_sanitize PROPERTIES LABELS "sanitize;soak" TIMEOUT 5400 PROCESSORS 2
    ENVIRONMENT "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1")
endif()

# frictional hard cases (issue 36): a crystal bed on a floor with friction, dragged to speed by
# the floor sliding in its own plane (conveyor, a wall-driven rigid bed) or sliding to rest
# (slide); Coulomb's deceleration, the exact momentum balance with the floor's forces, then at
# rest in the floor's frame with a handful of iterations per step; a sphere of 1000 x the mass
# resting on such a bed (heavy); the slide under `speed approach` (the default with friction
# is `speed contact`), held to the slide's checks (slide_speed_approach); 1 and 2 ranks
foreach(_case conveyor slide heavy slide_speed_approach)
  hardcontact_deck_test(NAME stab_friction_${_case} HOSTS launcher
    SCRIPT integration/test_stab_friction.py NP 1 2 LABELS stability
    ARGS --case ${_case} --timeout 200 TIMEOUT 300)
endforeach()
# a frictional heap at rest (issue 36): examples/heap/in.heap pours 400 spheres (mu 0.5, the
# fix's defaults with friction) onto its rough floor; at rest from t = 80 to 100: no maxiter,
# overlaps within tol, kinetic energy, speeds, creep, height and cone angle within what tol
# allows; about 7 s (np 1) and 10 s (np 2)
hardcontact_deck_test(NAME stab_friction_heap HOSTS launcher
  SCRIPT integration/test_stab_friction_heap.py NP 1 2 LABELS stability
  ARGS --timeout 150 TIMEOUT 240)
