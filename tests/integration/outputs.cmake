# Outputs and restarts of fix hardcontact.
#   outputs_np*: global vector, per-atom and local arrays against each other and against the
#                mechanics (Newton's third law, wall load = weight, momentum with a starved
#                solver, initial-overlap policy); tests/integration/test_outputs.py
#   restart_np*: run 40 == run 20 + write_restart + (new process) read_restart + run 20,
#                within the solver tolerance; tests/integration/test_restart.py
hardcontact_deck_test(NAME outputs SCRIPT integration/test_outputs.py NP 1 2 4
                      LABELS outputs TIMEOUT 300 HOSTS launcher modern liggghts)
hardcontact_deck_test(NAME restart SCRIPT integration/test_restart.py NP 1 2
                      LABELS restart TIMEOUT 180 HOSTS launcher modern liggghts)

# the fix bugs these scripts once documented are fixed: keep them as regression tests
hardcontact_deck_test(NAME outputs_fixed_bugs_np1 SCRIPT integration/test_outputs.py NP 1
                      LABELS outputs ARGS --known-bugs TIMEOUT 600)

# the developers' problem dump (HARDCONTACT_DUMP_PROBLEMS): the files rebuild the problem the
# solver was given, its solution is LAMMPS's step; an unwritable prefix is an ERROR
hardcontact_deck_test(NAME problem_dump SCRIPT integration/test_problem_dump.py NP 1 2 4
                      LABELS outputs TIMEOUT 180 HOSTS launcher modern)

# the developers' report of the solver's communication (HARDCONTACT_COMM_TIMES): one line per
# run, counts bounded by the iterations, nothing without the variable
hardcontact_deck_test(NAME comm_times SCRIPT integration/test_comm_times.py NP 1 2 4
                      LABELS outputs TIMEOUT 180 HOSTS launcher modern liggghts)
