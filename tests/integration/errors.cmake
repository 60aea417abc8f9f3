# Error handling of fix hardcontact: a table of bad decks (tests/integration/test_errors.py),
# each must end with a clean 'ERROR: ...' naming what to change, no NaN, no hang.
# np 4 runs the subset of cases marked np4. Cases where the fix still misbehaves run only with
# `test_errors.py --known-bugs` and are not registered here.
# On LIGGGHTS np 1 and np 4 (the cases marked for MPI: errors found on one rank): np 2 runs all
# ~60 decks under mpirun again, about 2 minutes there, most of the LIGGGHTS tests' time budget.
# The modern host's np 2 (the same adapter code as the launcher's np 2, 49 s) is soak since
# 2026-12-06 (CI time).
hardcontact_deck_test(NAME errors SCRIPT integration/test_errors.py NP 1 4
                      LABELS errors TIMEOUT 600 HOSTS launcher modern liggghts)
hardcontact_deck_test(NAME errors_np2 SCRIPT integration/test_errors.py NP 2
                      LABELS errors TIMEOUT 600 HOSTS launcher)
hardcontact_deck_test(NAME errors_soak_np2 SCRIPT integration/test_errors.py NP 2
                      LABELS errors soak TIMEOUT 600 HOSTS modern)

# the fix bugs these scripts once documented are fixed: keep them as regression tests (not on
# LIGGGHTS: their decks need LAMMPS commands it lacks, atom_style sphere 1 and comm_modify)
hardcontact_deck_test(NAME errors_fixed_bugs_np1 SCRIPT integration/test_errors.py NP 1
                      LABELS errors ARGS --known-bugs TIMEOUT 600)

# guard rails for a half-converted soft deck (deck_checks.h): a granular pair style, fix
# wall/gran on the fix's atoms, an open region wall each give one WARNING naming the line; an
# integrator on a disjoint group and the converted deck none. Serially on every host, under
# mpirun (shared atoms counted over ranks) on the launcher
hardcontact_deck_test(NAME deck_checks SCRIPT integration/test_deck_checks.py NP 1 2 4
                      LABELS errors TIMEOUT 300 HOSTS launcher modern liggghts MPI_HOSTS launcher)
