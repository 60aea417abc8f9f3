"""Unit tests of the toolkit (python/hctools) that tests, examples and bench share: what it
writes reads back exactly, and its readers take LAMMPS's and LIGGGHTS's output as they print
it. (run_deck itself runs in every deck test, against the real hosts.)"""

import gzip
import math
import os
import struct
import sys
import tempfile
import unittest

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import hctools as hc  # noqa: E402
from hctools.run import liggghts_deck  # noqa: E402


def read_data_sections(path):
    """{section: rows of floats} and the header lines of a data file (a reader independent of
    the writer under test)."""
    lines = open(path).read().splitlines()
    out, name = {"header": lines[:10]}, None
    for line in lines[1:]:
        w = line.split()
        if not w:
            continue
        if w[0] in ("Atoms", "Velocities"):
            name = w[0]
            out[name] = []
        elif name:
            out[name].append([float(t) for t in w])
    return out


LOG = """LAMMPS (29 Sep 2021 - Update 2)
thermo_style    custom step time f_hc[7] c_zavg
run 2
Per MPI rank memory allocation (min/avg/max) = 5.1 | 5.1 | 5.1 Mbytes
Step Time f_hc[7] c_zavg
       0            0            0          5.5
WARNING: Fix hardcontact: something (src/lammps/outputs.cpp:80)
       1         0.02   1.5e-05    5.25
       2         0.04   2.5e-05    5.125
Loop time of 1.25 on 2 procs for 2 steps with 1210 atoms

98.5% CPU use with 2 MPI tasks x 1 OpenMP threads

Section |  min time  |  avg time  |  max time  |%varavg| %total
---------------------------------------------------------------
Pair    | 0          | 0          | 0          |   0.0 |  0.00
Modify  | 1.1        | 1.125      | 1.15       |   1.0 | 90.00
Other   |            | 0.125      |            |       | 10.00

Nlocal:        605.000 ave         605 max         605 min
Per MPI rank memory allocation (min/avg/max) = 5.1 | 5.1 | 5.1 Mbytes
Step Time f_hc[7] c_zavg
       2         0.04   2.5e-05    5.125
       3         0.06   3.5e-05    5.0
ERROR: Fix hardcontact: bad thing (src/lammps/keywords.cpp:1)
"""

# LIGGGHTS heads its columns without the f_/c_ prefixes and says "Memory usage per processor"
LOG_LIGGGHTS = """thermo_style    custom step f_hc[7] c_zavg
Memory usage per processor = 4.2 Mbytes
Step hc[7] zavg
       0 0 5.5
       1 1e-05 5.25
Loop time of 0.5 on 1 procs for 1 steps with 10 atoms
"""

DUMP = """ITEM: TIMESTEP
{step}
ITEM: NUMBER OF ATOMS
3
ITEM: BOX BOUNDS ff ff ff
0 10
0 10
0 20
ITEM: ATOMS id type x vx
3 1 3.5 -0.5
1 2 1.5 0.25
2 1 2.5 {v}
"""


class Data(unittest.TestCase):
    def test_exact_round_trip(self):
        rng = np.random.default_rng(3)
        pos, vel = rng.random((5, 3)) * 7.0, rng.normal(size=(5, 3))
        d = rng.uniform(0.8, 1.0, 5)
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "s.data")
            hc.write_data(path, ((0, 7), (0, 7.1), (-1, 9)), d, 2500.0, pos, vel, types=[1, 2, 1, 1, 2])
            s = read_data_sections(path)
        atoms, v = np.array(s["Atoms"]), np.array(s["Velocities"])
        self.assertIn("5 atoms", s["header"])
        self.assertIn("2 atom types", s["header"])
        self.assertTrue(np.array_equal(atoms[:, 0], np.arange(1, 6)))
        self.assertTrue(np.array_equal(atoms[:, 1], [1, 2, 1, 1, 2]))
        self.assertTrue(np.array_equal(atoms[:, 2], d))         # every double exact (repr)
        self.assertTrue(np.array_equal(atoms[:, 4:7], pos))
        self.assertTrue(np.array_equal(v[:, 1:4], vel))
        self.assertTrue(np.array_equal(v[:, 4:7], np.zeros((5, 3))))

    def test_liggghts_2d_masses_and_options(self):
        class Liggghts(str):
            name = "liggghts"
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "d.data")
            hc.write_data(path, ((0, 4), (0, 4), (-0.5, 0.5)), 0.5, 3.0, [[1, 1, 0]], host=Liggghts("x"),
                          dimension=2, velocities=False, number=lambda x: "%.6g" % x)
            s = read_data_sections(path)
        # LIGGGHTS in 2d: pi r^2 rho' must equal LAMMPS's 4/3 pi r^3 rho
        rho = s["Atoms"][0][3]
        self.assertAlmostEqual(math.pi * 0.25 ** 2 * rho, float(hc.sphere_mass(0.5, 3.0)), places=5)
        self.assertNotIn("Velocities", s)

    def test_stl_ascii_exact_and_binary_size(self):
        tri = np.array([[[0, 0, 0], [1, 0, 0], [0, 1, 0.1]], [[1, 0, 0], [1, 1, 1.0 / 3.0], [0, 1, 0.1]]])
        with tempfile.TemporaryDirectory() as tmp:
            a, b = os.path.join(tmp, "a.stl"), os.path.join(tmp, "b.stl")
            hc.write_stl(a, tri)
            hc.write_stl(b, tri, binary=True)
            verts = [[float(t) for t in line.split()[1:]] for line in open(a) if line.split()[:1] == ["vertex"]]
            size = os.path.getsize(b)
            with open(b, "rb") as f:
                f.seek(84 + 50 + 12)
                first = struct.unpack("<3f", f.read(12))
        self.assertTrue(np.array_equal(np.array(verts), tri.reshape(-1, 3)))
        self.assertEqual(size, 84 + 50 * 2)      # the size by which readers tell binary STL
        self.assertTrue(np.allclose(first, tri[1, 0]))


class Logs(unittest.TestCase):
    def test_blocks_warnings_and_error(self):
        blocks = hc.parse_thermo(LOG)
        self.assertEqual(len(blocks), 2)
        self.assertEqual(list(blocks[0]["Step"]), [0, 1, 2])
        self.assertEqual(blocks[0]["Step"].dtype, np.int64)
        self.assertTrue(np.array_equal(blocks[0]["f_hc[7]"], [0.0, 1.5e-5, 2.5e-5]))
        self.assertEqual(list(blocks[1]["Step"]), [2, 3])     # a run that died keeps its rows

    def test_window_summary_and_rows(self):
        from hctools.summary import window_values
        got = window_values(LOG, ["rows", "mean:f_hc[7]", "max:c_zavg", "delta:Step", "loop",
                                  "steps"], block=0)
        self.assertEqual(got[0], 2)
        self.assertAlmostEqual(got[1], 2e-5, places=15)
        self.assertEqual(got[2:], [5.25, 2, 1.25, 2])
        self.assertEqual(window_values(LOG, ["Step", "c_zavg"], 0, each=True), [[1, 5.25], [2, 5.125]])
        self.assertEqual(window_values(LOG, ["rows"], 0, keep_first=True), [3])
        self.assertEqual(window_values(LOG, ["half:c_zavg"], 0, keep_first=True), [(5.25 + 5.125) / 2])
        self.assertEqual(window_values(LOG, ["time:Modify"], 0), [1.125])
        self.assertEqual(window_values(LOG, ["sum:Step"], 0), [3])
        # the last block is a run that died (no Loop time line): its loop time is unknown
        self.assertEqual(window_values(LOG, ["rows", "last:Step"])[:2], [1, 3])
        self.assertTrue(math.isnan(window_values(LOG, ["loop"])[0]))
        with self.assertRaises(KeyError):
            window_values(LOG, ["mean:f_hc[1]"])

    def test_liggghts_columns_named_as_lammps(self):
        b = hc.parse_thermo(LOG_LIGGGHTS)[0]
        self.assertIn("f_hc[7]", b)
        self.assertIn("c_zavg", b)

    def test_loop_times(self):
        t = hc.loop_times(LOG)
        self.assertEqual(len(t), 1)
        self.assertEqual((t[0]["loop"], t[0]["procs"], t[0]["steps"], t[0]["atoms"]), (1.25, 2, 2, 1210))
        self.assertAlmostEqual(t[0]["cpu_frac"], 0.985)
        self.assertEqual(t[0]["Modify"], 1.125)


class Dumps(unittest.TestCase):
    def test_sorted_by_id_gzip_and_glob(self):
        with tempfile.TemporaryDirectory() as tmp:
            with gzip.open(os.path.join(tmp, "d.gz"), "wt") as f:
                f.write(DUMP.format(step=0, v="1e-3") + DUMP.format(step=5, v="2"))
            for k in (0, 5):
                with open(os.path.join(tmp, "d.%d.txt" % k), "w") as f:
                    f.write(DUMP.format(step=k, v="1e-3" if k == 0 else "2"))
            fr = hc.read_dump(os.path.join(tmp, "d.gz"))
            per_step = hc.read_dump(os.path.join(tmp, "d.*.txt"))
        self.assertEqual([f.timestep for f in fr], [0, 5])
        c = fr[1].columns
        self.assertEqual(list(c["id"]), [1, 2, 3])
        self.assertEqual(list(c["type"]), [2, 1, 1])
        self.assertEqual(list(c["vx"]), [0.25, 2.0, -0.5])
        self.assertEqual(fr[0].box.shape, (3, 2))
        for a, b in zip(fr, per_step):
            self.assertEqual(a.timestep, b.timestep)
            self.assertTrue(all(np.array_equal(a.columns[k], b.columns[k]) for k in a.columns))


class Hosts(unittest.TestCase):
    def test_modern_host_loads_the_plugin_first(self):
        h = hc.Host("/usr/bin/lmp", "modern", "/tmp/x.so")
        self.assertTrue(h.deck_text("units lj\n").startswith("plugin load /tmp/x.so\n"))
        self.assertTrue(h.rewrites)
        self.assertFalse(hc.Host("/usr/bin/lmp").rewrites)

    def test_liggghts_rewrites(self):
        out = liggghts_deck("comm_modify vel yes\ndump d all custom 1 f id x vx\n"
                            "dump_modify d format float %.17g\nset group all omega 0 0 0\n")
        self.assertIn("newton          off", out)
        self.assertIn("communicate single vel yes", out)
        self.assertIn('format "%d %.17g %.17g"', out)
        self.assertNotIn("omega", out)
        with self.assertRaises(hc.LammpsRunError):
            liggghts_deck("set group all omega 0 0 1\n")


class Soft(unittest.TestCase):
    def test_hertz_stiffness_gives_the_overlap(self):
        p = hc.hertz_params(1.0, 1.0, 1e-3, 10.0, 0.5, 20)
        r_eff = 0.25
        self.assertAlmostEqual(p["kn"] * math.sqrt(r_eff) * (1e-3) ** 1.5 / 10.0, 1.0, places=12)
        self.assertAlmostEqual(p["dt"] * 20, p["t_c"], places=15)
        self.assertGreater(p["gamma_n"], 0.0)


if __name__ == "__main__":
    unittest.main()
