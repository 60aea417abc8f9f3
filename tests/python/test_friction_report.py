"""Unit test of bench/friction/report.py's interpolation of the soft twins (issue 36's target 2:
soft / hard at largest overlaps of 1e-2 and 1e-3, the twins' loop time against their largest
overlap, log-log between the two twins that bracket the overlap asked for)."""

import math
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "bench",
                                "friction"))
import report  # noqa: E402


def twin(overlap, loop):
    return (overlap, loop)


class TwinTimeAt(unittest.TestCase):
    def test_power_law_is_exact_inside_and_outside(self):
        # t = 2 overlap^-0.75: any log-log interpolation of two points on it is exact
        law = lambda x: 2.0 * x ** -0.75
        soft = [twin(x, law(x)) for x in (3e-2, 5e-3)]
        for x, outside in ((1e-2, False), (5e-3, False), (1e-3, True), (5e-2, True)):
            t, far = report.twin_time_at(soft, x)
            self.assertAlmostEqual(t / law(x), 1.0, places=12)
            self.assertEqual(far, outside)

    def test_brackets_with_the_pair_around_the_overlap(self):
        # a kinked curve: the value at 2e-3 comes from the twins at 5e-3 and 1e-3, not 3e-2
        soft = [twin(3e-2, 2.0), twin(5e-3, 10.0), twin(1e-3, 40.0)]
        t, far = report.twin_time_at(soft, 2e-3)
        p = math.log(40.0 / 10.0) / math.log(5e-3 / 1e-3)
        self.assertFalse(far)
        self.assertAlmostEqual(t, 10.0 * (5e-3 / 2e-3) ** p, places=10)
        t2, _ = report.twin_time_at(soft, 1e-2)
        p2 = math.log(10.0 / 2.0) / math.log(3e-2 / 5e-3)
        self.assertAlmostEqual(t2, 2.0 * 3.0 ** p2, places=10)
        # the order of the rows does not matter
        self.assertAlmostEqual(report.twin_time_at(soft[::-1], 2e-3)[0], t, places=12)

    def test_fewer_than_two_twins_give_nothing(self):
        self.assertEqual(report.twin_time_at([twin(1e-2, 3.0)], 1e-2), (None, False))
        self.assertEqual(report.twin_time_at([twin(0.0, 3.0), twin(1e-2, 5.0)], 1e-3), (None, False))


class Summary(unittest.TestCase):
    """bench/friction/summary.py on the recorded results: the 1210-sphere settle's row with
    adaptive steps gives soft / hard at 1e-2 and 1e-3 as an independent log-log interpolation
    of the same CSV between the twins that bracket each overlap."""

    def test_recorded_settle_row(self):
        import csv
        import subprocess
        import tempfile
        root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
        res = os.path.join(root, "bench", "results", "friction", "amd-epyc")
        front = os.path.join(res, "friction_front_target2.csv")
        rows = {r["run"]: r for r in csv.DictReader(open(front))}
        hard = float(rows["hybrid_tol0.01_dtreset0.08"]["loop_s"])
        twins = sorted((float(r["overlap_max"]), float(r["loop_s"]))
                       for r in rows.values() if r["kind"] == "soft")    # stiffest first

        def at(x):
            for (o2, t2), (o1, t1) in zip(twins, twins[1:]):    # o2 < o1
                if o2 <= x <= o1:
                    return math.exp(math.log(t1) + (math.log(x) - math.log(o1)) *
                                    (math.log(t2) - math.log(t1)) / (math.log(o2) - math.log(o1)))
            self.fail("no pair of twins brackets %g" % x)

        with tempfile.TemporaryDirectory() as out:
            subprocess.run([sys.executable, os.path.join(root, "bench", "friction", "summary.py"),
                            "--settle10", front, "--settle20", "none", "--cones", "none",
                            "--collapse", "none", "--out", out],
                           check=True, capture_output=True, env=dict(os.environ, MPLBACKEND="Agg"))
            table = open(os.path.join(out, "friction_summary.md")).read()
        row = [l for l in table.splitlines() if "fix dt/reset to 0.08" in l]
        self.assertEqual(len(row), 1, table)
        cells = [c.strip() for c in row[0].split("|")]
        self.assertEqual(cells[-2], "%.2f; %.2f" % (at(1e-2) / hard, at(1e-3) / hard))


if __name__ == "__main__":
    unittest.main()
