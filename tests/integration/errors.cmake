# Error handling of fix hardcontact: a table of bad decks (tests/integration/test_errors.py),
# each must end with a clean 'ERROR: ...' naming what to change, no NaN, no hang.
# np 4 runs the subset of cases marked np4. Cases where the fix still misbehaves run only with
# `test_errors.py --known-bugs` and are not registered here.
foreach(_np 1 2 4)
  hardcontact_deck_test(NAME errors_np${_np} SCRIPT integration/test_errors.py NP ${_np}
                        LABELS errors TIMEOUT 600)
endforeach()

# the fix bugs these scripts once documented are fixed: keep them as regression tests
hardcontact_deck_test(NAME errors_fixed_bugs_np1 SCRIPT integration/test_errors.py NP 1
                      LABELS errors ARGS --known-bugs TIMEOUT 600)
