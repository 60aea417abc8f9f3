# Example deck tests: each examples/<scene>/ deck run in a shortened form (variables such as
# nsteps) and its numbers checked. Label "examples" (+ "integration"). All together they are
# meant to stay under about 4 minutes on 2 busy cores.

# paper 6.2: sticky particles, h = 0.01, 0.5, 1.5, final state against the exact solution
hardcontact_deck_test(NAME example_sticky_particles SCRIPT integration/test_example_sticky.py
                      NP 1 LABELS examples TIMEOUT 120)
