#!/usr/bin/env python3
"""The case layer (tools/granair_cases) against hand-made inputs: templates,
OpenFOAM fields and entries, time series, the DEM blocks, checks, the runner.
Fast (no simulation): label unit."""
import math
import os
import random
import tempfile
import unittest

import numpy as np

import granair_cases as gc
from granair_cases import CaseError


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as fh:
        fh.write(text)


def read(path):
    with open(path) as fh:
        return fh.read()


class Template(unittest.TestCase):
    def test_fill_formats_and_names_the_missing_key(self):
        self.assertEqual(gc.template.fill("endTime @T:.10g@; air @AIR@;", {"T": 0.15, "AIR": "on"}),
                         "endTime 0.15; air on;")
        self.assertEqual(gc.template.fill("(-@W:.12g@ 0)", {"W": 0.0225}), "(-0.0225 0)")
        with self.assertRaisesRegex(CaseError, r"controlDict: placeholder @T_END@ has no value"):
            gc.template.fill("endTime @T_END@;", {"T": 1}, "controlDict")
        # OpenFOAM macros, LIGGGHTS variables and e-mail-like text are not placeholders
        text = "pFinal { $p; } print \"${vrms} $n\" a@b.c"
        self.assertEqual(gc.template.fill(text, {}), text)

    def test_saved_values_must_match_on_resume(self):
        with tempfile.TemporaryDirectory() as d:
            path = gc.template.save_values(os.path.join(d, "run", "case.json"), dict(A=1, B=(1, 2), C="x"))
            gc.template.check_values(path, dict(A=1, B=[1, 2], C="x"))          # a tuple is saved as a list
            with self.assertRaisesRegex(CaseError, r"other numbers \(A: 1 vs 2, D: None vs 0\); start again"):
                gc.template.check_values(path, dict(A=2, B=[1, 2], C="x", D=0), "start again")
            # a key added to the case later: a folder without it had its default (since)
            gc.template.check_values(path, dict(A=1, B=[1, 2], C="x", D=0), since=dict(D=0))
            with self.assertRaisesRegex(CaseError, r"D: 0 vs 1"):
                gc.template.check_values(path, dict(A=1, B=[1, 2], C="x", D=1), since=dict(D=0))

    def test_a_folder_set_up_in_another_checkout_resumes_here(self):
        # A pack from another machine names that machine's checkout: the place is
        # not a number (check_values passes) and relocate re-fills only the files
        # that name it, with this checkout's.
        with tempfile.TemporaryDirectory() as d:
            write(os.path.join(d, "t", "dem", "in.liggghts"), "include @GRANAIR_ROOT@/x\nrun @N@\n")
            write(os.path.join(d, "t", "system", "controlDict"), "endTime @N@;\n")
            gc.template.render(os.path.join(d, "t"), os.path.join(d, "run"), dict(GRANAIR_ROOT="/elsewhere", N=3))
            path = gc.template.save_values(os.path.join(d, "run", "case.json"), dict(GRANAIR_ROOT="/elsewhere", N=3))
            here = dict(GRANAIR_ROOT="/here", N=3)
            gc.template.check_values(path, here)
            out = gc.template.relocate(os.path.join(d, "t"), os.path.join(d, "run"), here)
            self.assertEqual(out, [os.path.join(d, "run", "dem", "in.liggghts")])
            self.assertEqual(read(out[0]), "include /here/x\nrun 3\n")
            with self.assertRaisesRegex(CaseError, r"N: 3 vs 4"):
                gc.template.check_values(path, dict(GRANAIR_ROOT="/here", N=4))

    def test_render_copies_a_folder_or_part_of_it(self):
        with tempfile.TemporaryDirectory() as d:
            write(os.path.join(d, "t", "system", "controlDict"), "deltaT @DT:g@;\n")
            write(os.path.join(d, "t", "dem", "in.fill"), "timestep @DT@\n")
            out = gc.template.render(os.path.join(d, "t"), os.path.join(d, "run"), {"DT": 5e-4})
            self.assertEqual(len(out), 2)
            self.assertEqual(read(os.path.join(d, "run", "system", "controlDict")), "deltaT 0.0005;\n")
            gc.template.render(os.path.join(d, "t"), os.path.join(d, "fill"), {"DT": 1}, only=["dem"])
            self.assertEqual(os.listdir(os.path.join(d, "fill")), ["dem"])
            with self.assertRaisesRegex(CaseError, "no nowhere"):
                gc.template.render(os.path.join(d, "t"), os.path.join(d, "x"), {"DT": 1}, only=["nowhere"])


class Foam(unittest.TestCase):
    def test_fields_and_entries(self):
        with tempfile.TemporaryDirectory() as d:
            write(os.path.join(d, "s"), "internalField nonuniform List<scalar>\n3\n(\n0.5\n1\n-2e-3\n)\n;\n")
            write(os.path.join(d, "v"), "internalField nonuniform List<vector> 2\n(\n(1 2 3)\n(4 5 -6)\n)\n;\n")
            write(os.path.join(d, "u"), "internalField   uniform (0 0 1);\n")
            write(os.path.join(d, "short"), "internalField   nonuniform List<vector> 2((0 0 1) (0 0 2));\n")
            np.testing.assert_array_equal(gc.foam.read_field(os.path.join(d, "short"))[:, 2], [1, 2])
            np.testing.assert_array_equal(gc.foam.read_field(os.path.join(d, "s")), [0.5, 1, -2e-3])
            np.testing.assert_array_equal(gc.foam.read_field(os.path.join(d, "v"))[1], [4, 5, -6])
            self.assertEqual(gc.foam.read_field(os.path.join(d, "u"), 4).shape, (4, 3))
            with self.assertRaisesRegex(CaseError, "expected 5"):
                gc.foam.read_field(os.path.join(d, "s"), 5)
            write(os.path.join(d, "controlDict"), "stopAt          endTime;\nendTime 2;\n")
            gc.foam.set_entry(os.path.join(d, "controlDict"), "stopAt", "writeNow")
            self.assertIn("stopAt          writeNow;", read(os.path.join(d, "controlDict")))
            self.assertEqual(gc.foam.read_entry(os.path.join(d, "controlDict"), "endTime"), "2")
            with self.assertRaisesRegex(CaseError, "no entry 'deltaT'"):
                gc.foam.read_entry(os.path.join(d, "controlDict"), "deltaT")
            with self.assertRaisesRegex(CaseError, "no entry 'deltaT'"):
                gc.foam.set_entry(os.path.join(d, "controlDict"), "deltaT", 1)
            for t in ("0", "0.25", "0.5"):
                os.makedirs(os.path.join(d, "case", t))
            os.makedirs(os.path.join(d, "case", "system"))
            self.assertEqual([t for t, _ in gc.foam.time_dirs(os.path.join(d, "case"))], [0, 0.25, 0.5])


    def test_plane_cells_and_their_picture(self):
        # two cells side by side, x in [0, 2], z in [0, 1], y in [0, 0.1]; front y = 0, back y = 0.1
        head = "FoamFile { version 2.0; format ascii; class %s; object %s; }\n"
        pts = [(x, y, z) for y in (0, 0.1) for z in (0, 1) for x in (0, 1, 2)]   # 0-5 front, 6-11 back
        faces = ["4(1 7 10 4)", "4(0 3 4 1)", "4(1 4 5 2)", "4(6 7 10 9)", "4(7 8 11 10)"]
        owner = [0, 0, 1, 0, 1]                  # one internal face, then frontAndBack (4 faces)
        with tempfile.TemporaryDirectory() as d:
            m = os.path.join(d, "constant", "polyMesh")
            write(os.path.join(m, "points"), head % ("vectorField", "points") + f"{len(pts)}\n(\n"
                  + "\n".join("(%g %g %g)" % p for p in pts) + "\n)\n")
            write(os.path.join(m, "faces"), head % ("faceList", "faces") + "5\n(\n" + "\n".join(faces) + "\n)\n")
            write(os.path.join(m, "owner"), head % ("labelList", "owner") + "5\n(\n" + "\n".join(map(str, owner)) + "\n)\n")
            write(os.path.join(m, "boundary"), head % ("polyBoundaryMesh", "boundary")
                  + "1\n(\n    frontAndBack\n    {\n        type empty;\n        nFaces 4;\n        startFace 1;\n    }\n)\n")
            cells = gc.foam.plane_cells(d)
            self.assertEqual(len(cells), 2)
            np.testing.assert_array_equal(sorted(map(tuple, cells[1])), [(1, 0), (1, 1), (2, 0), (2, 1)])
            write(os.path.join(d, "0", "eps"), "internalField nonuniform List<scalar> 2(0.4 1);\n")
            png = gc.plots.case_fields(os.path.join(d, "f.png"), "t", d, [0], [("eps", "eps", "viridis", (0, 1))],
                                       (0, 2000), (0, 1000))
            self.assertTrue(os.path.getsize(png) > 1000)
            self.assertIsNone(gc.plots.case_fields(os.path.join(d, "g.png"), "t", d, [0],
                                                   [("p", "p", "RdBu_r", None)], (0, 2000), (0, 1000)))


class Series(unittest.TestCase):
    def test_rates_and_windows(self):
        t = np.arange(1, 101) * 0.01            # 1 s in 0.01 s steps
        m = 0.2 * t                              # a steady 0.2 kg/s
        self.assertAlmostEqual(gc.series.slope(t, m, 0.3), 0.2, places=12)
        dt = gc.series.step_lengths(t)
        centres, (flow,) = gc.series.window_means(t, dt, [np.full(100, 0.2)], 0.1)
        self.assertEqual(len(centres), 10)
        np.testing.assert_allclose(flow, 0.2, rtol=1e-12)
        self.assertAlmostEqual(centres[0], 0.05, places=12)
        # a last window of 0.05 s: kept when longer than keep_last x width
        c2, _ = gc.series.window_means(t[:95], dt[:95], [m[:95]], 0.1, keep_last=0.4)
        c3, _ = gc.series.window_means(t[:95], dt[:95], [m[:95]], 0.1, keep_last=0.6)
        c4, _ = gc.series.window_means(t[:95], dt[:95], [m[:95]], 0.1, keep_last=None)
        self.assertEqual((len(c2), len(c3), len(c4)), (10, 9, 9))
        left = 100 - 50 * t                      # half of it gone at t = 1 s
        self.assertEqual(gc.series.steady_window(t, left, 0.3), (0.3, 1.0))
        self.assertAlmostEqual(gc.series.time_mean(t, t, 0.5, dt=dt), 0.75, places=12)

    def test_csv_round_trip(self):
        with tempfile.TemporaryDirectory() as d:
            p = os.path.join(d, "s.csv")
            gc.series.write_csv(p, [("t", [0.1, 0.2]), ("mass_flow_kg_s", [1 / 3, 2.0])])
            s = gc.series.read_csv(p)
            self.assertEqual(list(s), ["t", "mass_flow_kg_s"])
            self.assertEqual(s["mass_flow_kg_s"][0], 0.33333333)
            with self.assertRaisesRegex(CaseError, "has 2 rows, expected at least 3"):
                gc.series.read_csv(p, min_rows=3)


class Dem(unittest.TestCase):
    def test_packing_keeps_its_gap_and_its_box(self):
        L, gap = 0.01, 1e-5
        d = [random.Random(2).uniform(1e-3, 2e-3) for _ in range(150)]

        def sample(rng, r, top):
            return rng.uniform(r, L - r), rng.uniform(0, L), rng.uniform(r, top)

        atoms = gc.dem.loose_packing(sorted(d, reverse=True), random.Random(1), sample,
                                     lambda x, y, z, r: True, lambda top: top * 1.05, 0.01,
                                     2e-3 * 1.0001, gap, periodic_y=L)
        self.assertEqual(len(atoms), 150)
        a = np.array(atoms)
        for i in range(len(a)):
            dy = a[i, 1] - a[:, 1]
            dy -= L * np.round(dy / L)
            dist = np.sqrt((a[i, 0] - a[:, 0]) ** 2 + dy ** 2 + (a[i, 2] - a[:, 2]) ** 2)
            need = (a[i, 3] + a[:, 3]) / 2 + gap
            self.assertTrue(np.all((dist >= need * (1 - 1e-12)) | (np.arange(len(a)) == i)))

    def test_packing_periodic_in_x_and_y_and_typed_data(self):
        # the shear cell of cases/rheology-calibration: minimum images in x and y
        L, gap = 0.008, 1e-5
        d = [1.5e-3] * 60

        def sample(rng, r, top):
            return rng.uniform(0, L), rng.uniform(0, L), rng.uniform(r, top)

        atoms = gc.dem.loose_packing(d, random.Random(3), sample, lambda x, y, z, r: True, lambda top: top * 1.05,
                                     0.01, 1.5e-3 * 1.0001, gap, periodic_y=L, periodic_x=L)
        a = np.array(atoms)
        for i in range(len(a)):
            dx, dy = a[i, 0] - a[:, 0], a[i, 1] - a[:, 1]
            dx -= L * np.round(dx / L)
            dy -= L * np.round(dy / L)
            dist = np.sqrt(dx ** 2 + dy ** 2 + (a[i, 2] - a[:, 2]) ** 2)
            self.assertTrue(np.all((dist >= (1.5e-3 + gap) * (1 - 1e-12)) | (np.arange(len(a)) == i)))
        with tempfile.TemporaryDirectory() as tmp:
            p = os.path.join(tmp, "p.data")
            gc.dem.write_data(p, atoms[:3], (0, L, 0, L, 0, 0.02), 1500, "t", types=[2, 1, 2])
            with open(p) as fh:
                rows = [ln.split() for ln in fh.read().split("Atoms")[1].splitlines() if ln.strip()]
            self.assertEqual([r[1] for r in rows], ["2", "1", "2"])
            with self.assertRaisesRegex(CaseError, "2 atom types for 3 atoms"):
                gc.dem.write_data(p, atoms[:3], (0, L, 0, L, 0, 0.02), 1500, "t", types=[1, 1])

    def test_rayleigh_time_steps_stl(self):
        # glass bead of the fluidised bed, README: 3.1e-5 s
        self.assertAlmostEqual(gc.dem.rayleigh_time(0.25e-3, 5e6, 0.3, 2500) * 1e5, 3.06, places=2)
        self.assertEqual(gc.dem.time_steps(5e-4, 1e-4, 0.2), (25, 2e-5))
        text = gc.dem.stl("w", [[(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]])
        self.assertEqual(text.count("facet normal"), 2)
        self.assertTrue(text.startswith("solid w\n") and text.endswith("endsolid w\n"))
        # a triangle stays one facet (the fan of a disk: no degenerate second half)
        self.assertEqual(gc.dem.stl("t", [[(0, 0, 0), (1, 0, 0), (0, 1, 0)]]).count("facet normal"), 1)

    def test_dump_series_and_mesh_vtk(self):
        with tempfile.TemporaryDirectory() as d:
            snap = "ITEM: TIMESTEP\n{}\nITEM: NUMBER OF ATOMS\n{}\nITEM: BOX BOUNDS ff ff ff\n0 1\n0 1\n0 1\n" \
                   "ITEM: ATOMS id z\n"
            write(os.path.join(d, "cv.dump"), snap.format(0, 2) + "1 0.5\n2 0.25\n" + snap.format(10, 0)
                  + snap.format(20, 1) + "7 0.1\n" + snap.format(30, 2) + "3 0.2\n")   # the last cut short
            steps = gc.dem.read_dumps(os.path.join(d, "cv.dump"))
            self.assertEqual([s for s, _ in steps], [0, 10, 20])
            np.testing.assert_array_equal(steps[0][1]["z"], [0.5, 0.25])
            self.assertEqual(len(steps[1][1]["id"]), 0)
            # two chunks' dumps (the second starts where the first ended) merged, each step once
            write(os.path.join(d, "cv2.dump"), snap.format(20, 1) + "8 0.9\n" + snap.format(40, 1) + "9 0.3\n")
            out, n = gc.dem.merge_dumps([os.path.join(d, "cv.dump"), os.path.join(d, "cv2.dump")], os.path.join(d, "all"))
            merged = gc.dem.read_dumps(out)
            self.assertEqual((n, [s for s, _ in merged]), (4, [0, 10, 20, 40]))
            self.assertEqual(float(merged[2][1]["z"][0]), 0.1)         # the first chunk's copy of step 20
            # a dump local (the force chains: compute pair/gran/local)
            write(os.path.join(d, "pairs.dump"), "ITEM: TIMESTEP\n5\nITEM: NUMBER OF ENTRIES\n1\nITEM: BOX BOUNDS ff ff ff\n"
                  "0 1\n0 1\n0 1\nITEM: ENTRIES c_p[1] c_p[2] \n0.5 -2.5\n")
            (step, cols), = gc.dem.read_dumps(os.path.join(d, "pairs.dump"))
            self.assertEqual((step, list(cols), float(cols["c_p[2]"][0])), (5, ["c_p[1]", "c_p[2]"], -2.5))
            # LIGGGHTS 3.8's dump mesh/vtk form (OFFSETS/CONNECTIVITY, FIELD data), two triangles
            write(os.path.join(d, "m.vtk"), "# vtk DataFile Version 5.1\nGenerated by LIGGGHTS\nASCII\n"
                  "DATASET POLYDATA\nPOINTS 6 float\n0 0 0 1 0 0 0 1 0\n0 0 1 1 0 1 0 1 1\n\n"
                  "POLYGONS 3 6\nOFFSETS vtktypeint64\n0 3 6\nCONNECTIVITY vtktypeint64\n0 1 2 3 4 5\n\n"
                  "CELL_DATA 2\nFIELD FieldData 2\nnormal_stress_average 1 2 double\n10.5 -0\n"
                  "meshid 1 2 int\n0 1\n")
            m = gc.dem.read_mesh_vtk(os.path.join(d, "m.vtk"))
            self.assertEqual(m["points"].shape, (6, 3))
            np.testing.assert_array_equal(m["cells"][1], [3, 4, 5])
            np.testing.assert_array_equal(m["fields"]["normal_stress_average"], [10.5, 0])
            # what write_mesh_vtk writes reads back (legacy per-cell lists, SCALARS)
            out = gc.dem.write_mesh_vtk(os.path.join(d, "w.vtk"), m["points"], np.array(m["cells"]),
                                        {"p_Pa": [1.5, 2.5]})
            back = gc.dem.read_mesh_vtk(out)
            np.testing.assert_array_equal(back["cells"][0], [0, 1, 2])
            np.testing.assert_array_equal(back["fields"]["p_Pa"], [1.5, 2.5])
            with self.assertRaisesRegex(CaseError, "field q has 1 values for 2 triangles"):
                gc.dem.write_mesh_vtk(os.path.join(d, "x.vtk"), m["points"], np.array(m["cells"]), {"q": [1]})
            # the wall loads of a stress dump (normal, shear, area); without the shear field: named
            write(os.path.join(d, "walls_20.vtk"), read(os.path.join(d, "m.vtk")).replace(
                "FIELD FieldData 2", "FIELD FieldData 3").replace("meshid", "shear_stress_average 1 2 double\n-1 2\nmeshid"))
            normal, shear, area = gc.dem.wall_loads(os.path.join(d, "walls_20.vtk"))
            np.testing.assert_array_equal(np.c_[normal, shear, area], [[10.5, 1, 0.5], [0, 2, 0.5]])
            with self.assertRaisesRegex(CaseError, "shear_stress_average"):
                gc.dem.wall_loads(os.path.join(d, "m.vtk"))
            write(os.path.join(d, "walls_3.vtk"), "")
            write(os.path.join(d, "walls_fill.vtk"), "")
            self.assertEqual(gc.dem.numbered(os.path.join(d, "walls_*.vtk")),
                             [(3, os.path.join(d, "walls_3.vtk")), (20, os.path.join(d, "walls_20.vtk"))])

    def test_dump_and_balance(self):
        with tempfile.TemporaryDirectory() as d:
            write(os.path.join(d, "dump"), "ITEM: TIMESTEP\n0\nITEM: ATOMS id x z radius\n1 0.5 1 0.1\n2 -0.5 2 0.2\n")
            dump = gc.dem.read_dump(os.path.join(d, "dump"))
            np.testing.assert_array_equal(dump["z"], [1, 2])
            write(os.path.join(d, "log"), "\nDEM discharge balance (whole run)\n"
                  "    inserted                               5842   0.0111 kg\n"
                  "    present                                4353   0.0083 kg\n"
                  "    removed at the sink                    1489   0.0028 kg\n"
                  "    lost (inserted - present - removed)       0   0 kg\n"
                  "    discharged (crossed the outlet)        1500   0.0029 kg\n"
                  "total wall time 114.2 s\n")
            bal = gc.dem.discharge_balance(os.path.join(d, "log"))
            self.assertEqual((bal["inserted"], bal["removed"], bal["closes"]), (5842, 1489, True))
            self.assertEqual(bal["wall_time_s"], 114.2)
            write(os.path.join(d, "bad"), "nothing\n")
            with self.assertRaisesRegex(CaseError, "no DEM discharge balance"):
                gc.dem.discharge_balance(os.path.join(d, "bad"))
            # the fill's report: the last matching line, not the script's echoed print command
            write(os.path.join(d, "log.fill"), 'print "granair fill: settled after $n steps"\n'
                  "granair fill: settled after 3 x 100 steps, rms 0.01 m/s\n"
                  "granair fill: settled after 4 x 100 steps, rms 0.004 m/s\n")
            self.assertEqual(gc.dem.fill_report(os.path.join(d, "log.fill")),
                             "granair fill: settled after 4 x 100 steps, rms 0.004 m/s")
            with self.assertRaisesRegex(CaseError, r"bad: no line beginning 'granair fill: settled'"):
                gc.dem.fill_report(os.path.join(d, "bad"), "granair fill: settled")
            with self.assertRaisesRegex(CaseError, "missing: cannot read the fill's log"):
                gc.dem.fill_report(os.path.join(d, "missing"))


class ChecksAndRunner(unittest.TestCase):
    def test_checks_state_tolerance_and_fail(self):
        c = gc.checks.Checks("t")
        self.assertTrue(c.close("w", 1.01, 1.0, 0.02, "why"))
        self.assertFalse(c.close("w", 1.03, 1.0, 0.02))
        self.assertFalse(c.near("nan", math.nan, 0, 1))
        self.assertTrue(c.exact("n", 3, 3))
        self.assertIn("tolerance 2 %", c.lines[0])
        with self.assertRaises(SystemExit):
            c.report(enforce=True)

    def test_run_logs_and_reports_the_tail(self):
        with tempfile.TemporaryDirectory() as d:
            cpu = gc.runner.run(["sh", "-c", "echo hello"], d, "greet")
            self.assertGreaterEqual(cpu, 0)
            self.assertEqual(read(os.path.join(d, "log", "greet.log")), "hello\n")
            with self.assertRaisesRegex(CaseError, r"(?s)exit 3.*last words"):
                gc.runner.run(["sh", "-c", "echo last words; exit 3"], d, "bad")
            with self.assertRaisesRegex(CaseError, "cannot start"):
                gc.runner.run(["no-such-program-here"], d)
            r = gc.runner.pool([("a", lambda x: {"cpu_s": x}, (1,)), ("b", lambda x: x, (2,))], 2, "test")
            self.assertEqual(r, {"a": {"cpu_s": 1}, "b": 2})


class CG(unittest.TestCase):
    def test_read_grids_and_invariants(self):
        with tempfile.TemporaryDirectory() as d:
            rows = ["r,z,density,contact_stress_rr,contact_stress_rt,contact_stress_rz,contact_stress_tr,"
                    "contact_stress_tt,contact_stress_tz,contact_stress_zr,contact_stress_zt,contact_stress_zz"]
            for r in (0.5, 1.5):
                for z in (0.0, 1.0, 2.0):       # sigma = diag(1, 2, 6) + shear 3 in rz
                    rows.append(f"{r},{z},{10 * r + z},1,0,3,0,2,0,3,0,6")
            write(os.path.join(d, "f.csv"), "\n".join(rows) + "\n")
            f = gc.cg.read(os.path.join(d, "f.csv"))
            self.assertEqual(f["axes"], ("r", "z"))
            self.assertEqual(f["density"].shape, (2, 3))
            self.assertAlmostEqual(f["density"][1, 2], 17.0)
            p, tau = gc.cg.invariants(f, "contact_stress")
            # P = 3; deviator diag(-2, -1, 3), shear 3: J2 = (4 + 1 + 9) / 2 + 9 = 16
            np.testing.assert_allclose(p, 3.0)
            np.testing.assert_allclose(tau, 4.0)
            with self.assertRaisesRegex(CaseError, "kinetic_stress"):
                gc.cg.invariants(f, "kinetic_stress")
            write(os.path.join(d, "bad.csv"), "r,z,density\n0.5,0,1\n1.5,1,2\n")
            with self.assertRaisesRegex(CaseError, "not a grid"):
                gc.cg.read(os.path.join(d, "bad.csv"))


class Numerics(unittest.TestCase):
    def test_roots_minima_block_errors_field_lists(self):
        self.assertAlmostEqual(gc.numerics.bisect(lambda x: x * x - 2, 0, 2), math.sqrt(2), places=14)
        self.assertAlmostEqual(gc.numerics.bisect(lambda x: 1 / x - 1e3, 1e-9, 1, increasing=False, geometric=True),
                               1e-3, places=14)
        self.assertAlmostEqual(gc.numerics.golden(lambda x: (x - 0.3) ** 2, 0, 1), 0.3, places=7)
        self.assertAlmostEqual(gc.numerics.golden(lambda x: math.log(x / 0.02) ** 2, 1e-4, 10, log=True), 0.02, places=7)
        # block errors: 4 blocks of two snapshots; block means 1, 2, 3, 4 -> se = std / 2
        tables = [dict(v=np.array([x]), axes=("z",)) for x in (1, 1, 2, 2, 3, 3, 4, 4)]
        se = gc.series.block_errors(tables, lambda t: dict(m=float(t["v"][0])), ["m"], 4)
        self.assertAlmostEqual(se["m"], np.std([1, 2, 3, 4], ddof=1) / 2)
        self.assertTrue(math.isnan(gc.series.block_errors(tables[:1], lambda t: dict(m=1.0), ["m"])["m"]))
        m, sd = gc.series.mean_sd([1.0, None, 3.0, float("nan")])
        self.assertEqual((m, sd), (2.0, math.sqrt(2)))
        self.assertTrue(math.isnan(gc.series.mean_sd([5.0])[1]))
        # row by row over runs, cut to the shortest run, strings (read_table) read as numbers
        cols = gc.series.mean_sd_columns([dict(w=np.array([1.0, 2.0, 9.0])), dict(w=["3", "nan"])], ["w"])
        self.assertEqual(list(cols["w"]), [2.0, 2.0])
        self.assertEqual(cols["w_sd"][0], math.sqrt(2))
        self.assertTrue(math.isnan(cols["w_sd"][1]))
        self.assertEqual(gc.foam.nonuniform([1.0, 0.0]), "nonuniform List<scalar> 2 (1 0)")
        self.assertEqual(gc.foam.nonuniform([(0.5, 0, 0)]), "nonuniform List<vector> 1 ((0.5 0 0))")


class FakeProgram:
    """A shell script on PATH in place of a program (liggghts, granairFoam)."""
    def __init__(self, d, name, body):
        self.path = os.path.join(d, "bin", name)
        write(self.path, "#!/bin/sh\n" + body)
        os.chmod(self.path, 0o755)

    def __enter__(self):
        self.old = os.environ["PATH"]
        os.environ["PATH"] = os.path.dirname(self.path) + os.pathsep + self.old

    def __exit__(self, *exc):
        os.environ["PATH"] = self.old


# writes the file after `-var restart_out`, and the value of `-var n` to out_<seg>.txt
FAKE_LIGGGHTS = ('while [ $# -gt 0 ]; do [ "$1" = -var ] && [ "$2" = restart_out ] && echo "$@" > "$3"; '
                 '[ "$1" = -var ] && [ "$2" = n ] && n=$3; [ "$1" = -var ] && [ "$2" = seg ] && s=$3; shift; done\n'
                 'echo $n > out_$s.txt\n')
# a restart point at the controlDict's endTime, as granairFoam writes one
FAKE_FOAM = ('t=$(sed -n "s/^endTime *\\(.*\\);/\\1/p" system/controlDict)\n'
             'mkdir -p restart/$t && touch restart/$t/coupling && echo "to $t"\n')


class Chunks(unittest.TestCase):
    def test_liggghts_segments_resume_and_need_their_restart(self):
        """The second call skips the finished segments; a removed restart stops it with a message."""
        with tempfile.TemporaryDirectory() as d, FakeProgram(d, "liggghts", FAKE_LIGGGHTS):
            case = os.path.join(d, "case")
            write(os.path.join(case, "fill.restart"), "x")
            segs = [dict(n=10), dict(n=20)]
            rec = gc.chunks.liggghts(case, "in.seg", segs, "fill.restart", label="test", progress=lambda s: None)
            self.assertEqual((rec["ran"], rec["reason"]), (2, "2 segments"))
            self.assertTrue(os.path.exists(os.path.join(case, "restart", "segment_2.restart")))
            self.assertFalse(os.path.exists(os.path.join(case, "restart", "segment_1.restart")))
            self.assertEqual(gc.chunks.cost(case, "segment")[2], 2)
            # a longer list goes on after the finished segments
            rec = gc.chunks.liggghts(case, "in.seg", segs + [dict(n=30)], "fill.restart", label="test",
                                     progress=lambda s: None)
            self.assertEqual((rec["ran"], len(rec["chunks"])), (1, 3))
            self.assertEqual(gc.chunks.cost(case, "segment")[2], 3)
            os.remove(os.path.join(case, "restart", "segment_3.restart"))
            with self.assertRaisesRegex(CaseError, "needs the restart"):
                gc.chunks.liggghts(case, "in.seg", segs + [dict(n=30)] * 2, "fill.restart", progress=lambda s: None)

    def test_liggghts_segments_from_a_function_with_what_they_collect(self):
        """segments(k, rec) sees the finished entries; collect() adds to each; old markers are read."""
        with tempfile.TemporaryDirectory() as d, FakeProgram(d, "liggghts", FAKE_LIGGGHTS):
            case = os.path.join(d, "case")
            write(os.path.join(case, "fill.restart"), "x")
            write(os.path.join(case, "restart", "seg_1.done"), "cpu_s = 1.5\nwall_s = 2.0\n")
            write(os.path.join(case, "restart", "seg_1.restart"), "x")
            # a finished run of the old layout: its cost is the markers' (nothing saved by reading it)
            self.assertEqual(gc.chunks.cost(case, "seg"), (1.5, 2.0, 1))
            self.assertFalse(os.path.exists(os.path.join(case, "log", "seg.json")))

            def plan(k, rec):
                return None if k > 3 else dict(n=sum(c["n"] for c in rec["chunks"][1:]) + k)

            def collect(c, k):
                return dict(n=int(read(os.path.join(c, f"out_{k}.txt"))))
            rec = gc.chunks.liggghts(case, "in.seg", plan, "fill.restart", "seg", collect=collect,
                                     progress=lambda s: None)
            self.assertEqual([c["k"] for c in rec["chunks"]], [1, 2, 3])
            self.assertEqual(rec["chunks"][0]["cpu_s"], 1.5)          # from the marker
            self.assertEqual([c.get("n") for c in rec["chunks"]], [None, 2, 5])
            self.assertEqual(rec["ran"], 2)

    def test_foam_chunks_to_finished_and_to_a_later_t_max(self):
        with tempfile.TemporaryDirectory() as d, FakeProgram(d, "granairFoam", FAKE_FOAM):
            case = os.path.join(d, "case")
            write(os.path.join(case, "system", "controlDict"),
                  "startFrom latestTime;\nstartTime 0;\nendTime 1;\n")
            rec = gc.chunks.foam(case, 0.25, lambda c: None, 0.5, progress=lambda s: None)
            self.assertEqual([(c["from"], c["to"]) for c in rec["chunks"]], [(0.0, 0.25), (0.25, 0.5)])
            self.assertEqual((rec["reason"], rec["t_end"]), ("t_max = 0.5 s", 0.5))
            self.assertIn("startTime 0.25;\nendTime 0.5;", read(os.path.join(case, "system", "controlDict")))
            self.assertTrue(os.path.exists(os.path.join(case, "log", "granairFoam_0.25-0.5.log")))
            # a later t_max goes on; finished() ends it; the newest two restart points are kept
            empty = lambda c: "empty" if gc.chunks.latest_restart(c)[0] >= 1 else None   # noqa: E731
            rec = gc.chunks.foam(case, 0.25, empty, 2.0, progress=lambda s: None)
            self.assertEqual((rec["ran"], rec["reason"], rec["t_end"]), (2, "empty", 1.0))
            self.assertEqual(sorted(os.listdir(os.path.join(case, "restart"))), ["0.75", "1"])
            self.assertEqual(gc.chunks.foam(case, 0.25, empty, 2.0)["ran"], 0)


if __name__ == "__main__":
    unittest.main(verbosity=2)
