#!/usr/bin/env python3
"""The pieces of the DEM-only silo studies (cases/two-slot-silo, cases/corn-silo) that
live in the case layer: the chunked particle balance (gc.tally), the text tables
(gc.tables), a slab silo's CG fields (gc.cg_slab), the phi(I) fit's picture
(gc.phi_i), the per-chunk inputs (gc.chunk_inputs), the linear spring-dashpot
(gc.linear_contact), a silo's ring wall loads (gc.silo_walls) and its layered fill
(gc.layered_fill), the steady summary of a strain series (gc.strain.steady, check_hull),
against hand-made logs, fields, meshes, stand-in programs, a
numerically integrated contact and Janssen's closed form. Fast (no simulation): label unit."""
import math
import os
import sys
import tempfile
import unittest

import numpy as np

import granair_cases as gc
from granair_cases import CaseError

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from test_case_layer import FakeProgram, read  # noqa: E402


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as fh:
        fh.write(text)
    return path


def chunk_log(k, start, end):
    keys = ("atoms", "in_silo", "outlet", "sink", "feed")
    line = lambda s, t, v: (f"granair chunk {k} {s}: time {t} " + " ".join(f"{a} {b}" for a, b in zip(keys, v)))  # noqa: E731
    return f"LIGGGHTS\n{line('start', *start)}\nrun 100\ngranair chunk {k} pending: 1\n{line('end', *end)}\n"


class Tally(unittest.TestCase):
    def test_log_values_reads_labelled_key_value_lines(self):
        with tempfile.TemporaryDirectory() as d:
            p = write(os.path.join(d, "log"), "granair chunk 1 start: time 0.1 atoms 5 note x\n"
                                              "granair chunk 10 start: time 9 atoms 9\n"
                                              "granair chunk 1 start: time 0.2 atoms 6\n")
            # chunk 10's line is not chunk 1's; the last line of a label wins; words stay strings
            self.assertEqual(gc.tally.log_values(p, "granair chunk 1"), {"start": {"time": 0.2, "atoms": 6.0}})
            self.assertEqual(gc.tally.log_values(p, "granair chunk 10")["start"]["atoms"], 9.0)

    def test_balance_of_two_chunks_closes_and_names_a_gap(self):
        # fill 100; chunk 0: feed 10, 30 cross the outlet, 20 reach the sink; chunk 1: feed 5, 10 cross, 15 removed
        with tempfile.TemporaryDirectory() as d:
            logs = [write(os.path.join(d, f"chunk_{k}.liggghts"), chunk_log(k, s, e)) for k, (s, e) in enumerate([
                ((0.0, (100, 100, 0, 0, 0)), (0.1, (90, 80, 30, 20, 10))),
                ((0.1, (90, 80, 30, 20, 10)), (0.2, (80, 75, 40, 35, 15)))])]
            states = [gc.tally.chunk_states(p, k) for k, p in enumerate(logs)]
            self.assertEqual(states[1][1], dict(t=0.2, atoms=80, in_silo=75, outlet=40, sink=35, feed=15))
            acc = gc.tally.balance(100, 100, states, list(range(40)), list(range(35)), [3, 4], lost=2)
            # inserted 115 = 75 in the silo + 5 below the outlet + 35 removed; 40 crossings = 5 + 35
            self.assertEqual((acc["inserted"], acc["in_silo"], acc["below_outlet"], acc["removed"], acc["discharged"]),
                             (115, 75, 5, 35, 40))
            self.assertTrue(acc["closes"] and acc["chunks_consistent"] and acc["pending_all_removed"])
            self.assertEqual((acc["t_end"], acc["lost_atom_warnings"], acc["pending_deleted"]), (0.2, 2, 2))
            # a particle crossing without its record, a pending id the sink never counted: not closed
            self.assertFalse(gc.tally.balance(100, 100, states, list(range(39)), list(range(35)))["closes"])
            self.assertFalse(gc.tally.balance(100, 100, states, list(range(40)), list(range(35)), [99])["closes"])
            # a chunk that does not start where the one before ended
            bad = [states[0], (dict(states[1][0], atoms=91), states[1][1])]
            self.assertFalse(gc.tally.balance(100, 100, bad, list(range(40)), list(range(35)))["chunks_consistent"])
            c = gc.checks.Checks("t")
            gc.tally.check(c, "run", acc, 2)
            self.assertEqual((len(c.lines), c.failed), (6, []))
            with self.assertRaisesRegex(CaseError, r"no 'granair chunk 2 start/end' lines"):
                gc.tally.chunk_states(logs[0], 2)

    def test_crossing_flow_in_windows_per_opening_and_binned(self):
        # 1 g crossing every 10 ms from t = 0.005 s, alternately left and right, 0.5 s of records
        t = np.arange(0.005, 0.5, 0.01)
        m, x = np.full(t.size, 1e-3), np.where(np.arange(t.size) % 2, 1.0, -1.0)
        q, (tc, series) = gc.tally.crossing_flow(t, m, 0.1, 0.5, 0.2, [x < 0, x >= 0], 0.05)
        self.assertEqual(q["n_windows"], 2)
        np.testing.assert_allclose(q["windows"], [0.1, 0.1])                 # 20 g over 0.2 s
        self.assertEqual(q["sd"], 0.0)
        np.testing.assert_allclose(q["per_opening_mean"], [0.05, 0.05])
        self.assertAlmostEqual(q["discharged_kg"], 0.05)
        np.testing.assert_allclose(series, np.full(10, 0.1))
        self.assertAlmostEqual(tc[0], 0.025)
        self.assertEqual(len(gc.tally.crossing_flow(t, m, 0.1, 0.5, 0.2)[0]["per_opening_mean"]), 1)

    def test_lost_atoms_counts_the_warnings(self):
        with tempfile.TemporaryDirectory() as d:
            p = write(os.path.join(d, "s"), "WARNING: Lost atoms: original 5 current 5\nx\nWARNING: Lost atoms: ...\n")
            self.assertEqual(gc.tally.lost_atoms(p), 2)


class Tables(unittest.TestCase):
    def test_pm_markdown_and_aligned(self):
        self.assertEqual(gc.tables.pm(dict(w=0.123456, w_sd=0.00123), "w"), "0.123 ± 0.0012")
        self.assertEqual(gc.tables.pm(dict(w=0.01234, w_sd=math.nan), "w", 100, 2), "1.2")     # one run: no SD
        self.assertEqual(gc.tables.markdown(["a", "b"], [[1, "x"]]), ["| a | b |", "|---|---|", "| 1 | x |"])
        self.assertEqual(gc.tables.aligned([["n", "value"], [10, 2.5]]), [" n  value", "10    2.5"])


class CgSlab(unittest.TestCase):
    def test_fullard_fields_of_shear_and_extension(self):
        # simple shear vx = G z (gradient components xz + zx = G): gamma_dot = G; pure extension
        # vx = E x, vz = -E z: gamma_dot = 2 E; at rest (or P = 0) no I and no viscosity
        f = dict(velocity_gradient_xz=np.array([0.0, 3.0, 0.0, 0.0]), velocity_gradient_zx=np.array([0.0, 2.0, 0.0, 0.0]),
                 velocity_gradient_xx=np.array([0.0, 0.0, 4.0, 1.0]), velocity_gradient_zz=np.array([0.0, 0.0, -4.0, -1.0]),
                 pressure=np.array([10.0, 50.0, 200.0, 0.0]), shear_stress=np.array([1.0, 10.0, 40.0, 1.0]))
        gd, i_num, eta = gc.cg_slab.fullard(f, 2e-3, 1200.0)
        self.assertEqual(list(gd), [0.0, 5.0, 8.0, 2.0])
        self.assertAlmostEqual(i_num[1], 2e-3 * 5 * math.sqrt(1200 / 50), places=15)
        self.assertAlmostEqual(eta[2], 40 / 8)
        self.assertTrue(math.isnan(eta[0]) and math.isnan(i_num[3]))
        means = gc.cg_slab.box_mean([("eta", eta), ("gd", gd)], np.array([True, True, False, False]))
        self.assertEqual(means, dict(eta=2.0, gd=2.5))           # the NaN of the point at rest left out

    def test_granairCG_command_and_the_mass_check(self):
        # a stand-in granairCG: its arguments to args_<n>.txt, a 2 x 2 XZ grid of density 1000 to <out>.csv
        body = ('n=$(ls args_* 2>/dev/null | wc -l); echo "$@" > args_$n.txt\n'
                'while [ $# -gt 0 ]; do [ "$1" = --out ] && out=$2; shift; done\n'
                'printf "x,z,density\\n0,0,1000\\n0.001,0,1000\\n0,0.001,1000\\n0.001,0.001,1000\\n" > $out.csv\n')
        with tempfile.TemporaryDirectory() as d, FakeProgram(d, "granairCG", body):
            case = os.path.join(d, "run")
            for step in (100, 200):
                write(os.path.join(case, "post", "cg", f"particles_{step}.dump"),
                      "ITEM: TIMESTEP\n0\nITEM: ATOMS id x y z mass\n1 0 0.005 0 0.002\n2 0 0.02 0 0.5\n")
            box = (-0.05, 0.05, 0.015)
            cpu, steps = gc.cg_slab.run(case, "fields", box, (-0.05, 0, -0.01), (0.05, 0.015, 0.06), 1e-5, 2e-3, 3.0,
                                        1e-3, "granairCG")
            self.assertEqual(steps, [100, 200])
            args = read(os.path.join(case, "args_0.txt")).split()
            self.assertIn("--plane-wall wback y 0.015", " ".join(args))
            self.assertNotIn("--from", args)
            cg_kg, dump_kg, _ = gc.cg_slab.mass_check(case, box, (-0.02, 0.08), 1e-5, 2e-3, 3.0, 1e-3, 200)
            args = " ".join(read(os.path.join(case, "args_1.txt")).split())
            # the grid widened by 3 cutoffs x w = 18 mm; the last snapshot alone (t = 200 x 1e-5 s)
            lo_hi = [float(x) for x in args.split("--min ")[1].split(" --threads")[0].replace("--max ", "").split()]
            np.testing.assert_allclose(lo_hi, [-0.068, 0.0, -0.038, 0.068, 0.015, 0.098], rtol=1e-12)
            self.assertIn("--from 0.001999999998", args)
            self.assertAlmostEqual(cg_kg, 4000 * 1e-6 * 0.015)        # rho dx dz x depth
            self.assertEqual(dump_kg, 0.002)                          # the particle behind the back wall left out


class PhiI(unittest.TestCase):
    def test_the_fit_of_exact_points_and_its_file(self):
        i = np.linspace(0.05, 0.6, 40)
        with tempfile.TemporaryDirectory() as d:
            fits = gc.phi_i.plot(os.path.join(d, "phi_I.png"), os.path.join(d, "fit.txt"),
                                 [("low", "tab:blue", np.column_stack([i, 0.58 / (1 + 0.41 * i)]).tolist()),
                                  ("high", "tab:red", [])], 0.05, "t", "phi = a1 / (1 + a2 I)")
            self.assertEqual([f[0] for f in fits], ["low"])             # a set without points is left out
            self.assertAlmostEqual(fits[0][1], 0.58, places=5)
            self.assertAlmostEqual(fits[0][2], 0.41, places=5)
            self.assertEqual(read(os.path.join(d, "fit.txt")),
                             "# phi = a1 / (1 + a2 I)\nlow: a1 = 0.58, a2 = 0.41, points = 40\n")
            self.assertTrue(os.path.getsize(os.path.join(d, "phi_I.png")) > 0)


# a stand-in liggghts: fails while `stop` exists and the input is in.chunk_1; else notes the
# input and writes the restart its `write_restart` line names
FAKE_CHUNK_LIGGGHTS = ('while [ $# -gt 0 ]; do [ "$1" = -in ] && in=$2; shift; done\n'
                       '[ -e ../stop ] && [ "$in" = dem/in.chunk_1 ] && exit 1\n'
                       'echo $in >> ran.txt; touch $(sed -n "s/^write_restart //p" $in)\n')


class ChunkInputs(unittest.TestCase):
    def test_layout_in_whole_intervals_and_the_snapshot_chunk(self):
        # 0.42 s in 0.21 s chunks of 5 ms intervals (955 steps each), then 20 snapshots
        self.assertEqual(gc.chunk_inputs.layout(0.42, 0.21, 0.005, 955, 20),
                         [(0, 42 * 955, False), (1, 42 * 955, False), (2, 19 * 955 + 1, True)])
        self.assertEqual(gc.chunk_inputs.layout(0.25, 0.3, 0.005, 10), [(0, 500, False)])

    def test_inputs_run_in_turn_and_resume_after_a_failure(self):
        text = "read_restart @RESTART_IN@\nrun @N_STEPS@ # @T_CHUNK:.3g@ s, cg @CG_EVERY@, seed @SEED@\nwrite_restart @RESTART_OUT@\n"
        chunks = gc.chunk_inputs.layout(0.02, 0.01, 0.005, 10, 3)
        with tempfile.TemporaryDirectory() as d, FakeProgram(d, "liggghts", FAKE_CHUNK_LIGGGHTS):
            run, fill = os.path.join(d, "run"), os.path.join(d, "fill")
            write(os.path.join(fill, "dem", "fill.restart"), "x")

            def setup(folder):
                gc.chunk_inputs.write(folder, text, chunks, dict(DEM_DT=1e-3, SNAP_STEPS=10),
                                      os.path.join(fill, "dem", "fill.restart"), "in.chunk", lambda k: dict(SEED=k + 7))
            setup_only, simulate = gc.chunk_inputs.stage(run, chunks, setup, progress=lambda s: None)
            setup_only()
            self.assertEqual(read(os.path.join(run, "dem", "in.chunk_2")),
                             "read_restart dem/chunk_1.restart\nrun 21 # 0.021 s, cg 10, seed 9\n"
                             "write_restart dem/chunk_2.restart\n")
            self.assertTrue(read(os.path.join(run, "dem", "in.chunk_0")).startswith("read_restart ../fill/dem/fill.restart"))
            write(os.path.join(d, "stop"), "")
            with self.assertRaises(CaseError):
                simulate()                                        # chunk 1 fails: chunk 0 is kept
            self.assertEqual(list(gc.chunk_inputs.cost(run)), ["chunk_0"])
            os.remove(os.path.join(d, "stop"))
            cost = simulate()                                     # goes on at chunk 1
            self.assertEqual(list(cost), ["chunk_0", "chunk_1", "chunk_2"])
            self.assertEqual((cost["chunk_2"]["steps"], cost["chunk_2"]["cg"]), (21, True))
            self.assertEqual(read(os.path.join(run, "ran.txt")).split(),
                             ["dem/in.chunk_0", "dem/in.chunk_1", "dem/in.chunk_2"])
            self.assertFalse(os.path.exists(os.path.join(run, "dem", "chunk_0.restart")))   # two back: removed
            self.assertTrue(gc.chunk_inputs.finished(run, chunks))
            simulate()                                            # finished: nothing runs again
            self.assertEqual(len(read(os.path.join(run, "ran.txt")).split()), 3)
            # the post-processing is kept while it is newer than the record, made again after it
            calls, js = [], os.path.join(d, "post.json")
            post = lambda: calls.append(1) or dict(n=len(calls))          # noqa: E731
            self.assertEqual(gc.chunk_inputs.post_once(js, run, post), dict(n=1))
            self.assertEqual(gc.chunk_inputs.post_once(js, run, post), dict(n=1))
            os.utime(gc.chunk_inputs.record_file(run), (os.path.getmtime(js) + 10,) * 2)
            self.assertEqual(gc.chunk_inputs.post_once(js, run, post), dict(n=2))
            # a run file's measure kept beside the results, read back once the run folder is gone
            saved, src = os.path.join(d, "res", "fill.json"), os.path.join(run, "dem", "in.chunk_0")
            self.assertIsNone(gc.chunk_inputs.kept(saved, os.path.join(d, "none"), dict, "x"))
            self.assertEqual(gc.chunk_inputs.kept(saved, src, lambda: dict(rho=700.5), "in.chunk_0"),
                             dict(rho=700.5, source="in.chunk_0"))
            os.remove(src)
            self.assertEqual(gc.chunk_inputs.kept(saved, src, None, "x"), dict(rho=700.5, source="in.chunk_0"))


class LinearContact(unittest.TestCase):
    def test_against_the_integrated_damped_oscillator(self):
        # m x'' = -k x - gamman m x' from x = 0, x' = 1 until the overlap x is 0 again (RK4)
        m, k, e = 2e-6, 1e4, 0.6
        t_c, gamman = gc.linear_contact.contact_time(m, k, e), gc.linear_contact.gamma_per_mass(m, k, e)

        def acc(x, v):
            return -k / m * x - gamman * v
        x, v, t, h = 0.0, 1.0, 0.0, t_c / 20000
        while True:
            k1 = (v, acc(x, v))
            k2 = (v + h / 2 * k1[1], acc(x + h / 2 * k1[0], v + h / 2 * k1[1]))
            k3 = (v + h / 2 * k2[1], acc(x + h / 2 * k2[0], v + h / 2 * k2[1]))
            k4 = (v + h * k3[1], acc(x + h * k3[0], v + h * k3[1]))
            xn = x + h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
            vn = v + h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
            if xn < 0:                        # the contact ends inside this step: interpolate
                frac = x / (x - xn)
                t, v = t + frac * h, v + frac * (vn - v)
                break
            x, v, t = xn, vn, t + h
        self.assertAlmostEqual(t / t_c, 1.0, places=6)
        self.assertAlmostEqual(-v, e, places=6)
        self.assertAlmostEqual(gc.linear_contact.damping_ratio(e), gamman / (2 * math.sqrt(k / m)), places=15)


def png_size(path):
    """(width, height) of a PNG from its IHDR chunk."""
    with open(path, "rb") as fh:
        head = fh.read(24)
    return int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")


def cylinder_rings(R=0.1, rows=5, height=0.01, sectors=24):
    """A cylinder wall of `rows` rings `height` tall as a dump mesh/vtk mesh, and its gc.wall_rings.Rings."""
    quads = [q for k in range(rows) for q in gc.stl_walls.revolution(R, R, k * height, (k + 1) * height, 1, sectors)]
    pts, cells = [], []
    for q in quads:
        pts += q
        cells += [np.array([len(pts) - 4, len(pts) - 3, len(pts) - 2]), np.array([len(pts) - 4, len(pts) - 2, len(pts) - 1])]
    mesh = {"points": np.array(pts), "cells": cells}
    z = np.array(pts)[np.array(cells)].mean(axis=1)[:, 2]
    return mesh, gc.wall_rings.Rings(mesh, np.minimum((z / height).astype(int), rows - 1), rows), z


class SiloWalls(unittest.TestCase):
    def test_profiles_and_maxima_of_dumps(self):
        mesh, rings, z = cylinder_rings()
        pts, tri = gc.dem.merge_points(mesh)
        with tempfile.TemporaryDirectory() as d:
            def dump(name, scale):           # normal load 1e4 z x scale (largest at the top ring), shear 10 x scale
                return gc.dem.write_mesh_vtk(os.path.join(d, name), pts, tri, dict(
                    normal_stress_average=1e4 * z * scale, shear_stress_average=np.full(len(z), 10.0 * scale)))
            files = [(s, dump(f"walls_{s}.vtk", s / 100)) for s in (100, 200, 300)]
            prof, (sn, _, el_n, _) = gc.silo_walls.profiles(rings, dump("walls_fill.vtk", 0.5), files, files[1:])
            np.testing.assert_allclose(prof["static_normal_Pa"], [25, 75, 125, 175, 225], rtol=1e-9)
            np.testing.assert_allclose(prof["discharge_normal_Pa"], 2.5 * np.array([50, 150, 250, 350, 450]), rtol=1e-9)
            np.testing.assert_allclose(prof["peak_shear_Pa"], np.full(5, 30.0), rtol=1e-9)
            np.testing.assert_allclose(el_n, 2.5e4 * z, rtol=1e-9)              # the steady dumps' element mean
            lower = rings.z < 0.03
            res = gc.silo_walls.maxima(rings, prof, [("hopper", lower), ("shaft", ~lower)])
            self.assertAlmostEqual(res["hopper_discharge_normal_max_Pa"], 625.0)
            self.assertAlmostEqual(res["hopper_static_normal_max_z_m"], 0.025)
            self.assertAlmostEqual(res["shaft_peak_normal_Pa"], 1350.0)
            self.assertEqual(len(res), 2 * (2 * 2 * 3 + 2))
            gc.silo_walls.mean_vtk(os.path.join(d, "walls_fill.vtk"), [dict(static_normal_Pa=sn, static_shear_Pa=sn),
                                   dict(static_normal_Pa=3 * sn, static_shear_Pa=sn)], os.path.join(d, "mean.vtk"),
                                   "static", "t")
            np.testing.assert_allclose(gc.dem.read_mesh_vtk(os.path.join(d, "mean.vtk"))["fields"]["normal_Pa"], 2 * sn,
                                       rtol=1e-8)

    def test_profiles_written_and_their_mean_over_runs(self):
        mesh, rings, _ = cylinder_rings(rows=3)
        depth = 0.05 - rings.z
        with tempfile.TemporaryDirectory() as d:
            paths = []
            for k, scale in enumerate((1.0, 3.0)):
                prof = dict(static_normal_Pa=scale * np.array([10.0, 20.0, 30.0]), peak_shear_Pa=np.full(3, scale))
                els = tuple(np.full(len(rings.ring), scale * j) for j in range(4))
                paths.append(os.path.join(d, f"s{k}_walls.csv"))
                gc.silo_walls.write(paths[-1], os.path.join(d, f"s{k}_elements.csv"), rings, prof, depth, els,
                                    lambda i: "hopper" if i == 0 else "shaft")
            self.assertEqual(list(gc.series.read_csv(os.path.join(d, "s1_elements.csv"))),
                             ["static_normal_Pa", "static_shear_Pa", "discharge_normal_Pa", "discharge_shear_Pa"])
            rows = gc.silo_walls.mean_profiles(paths)
        self.assertEqual([r["wall"] for r in rows], ["hopper", "shaft", "shaft"])
        self.assertEqual((rows[1]["static_normal_Pa"], rows[1]["static_normal_sd_Pa"]), (40.0, math.sqrt(800.0)))
        self.assertEqual(list(rows[2])[-2:], ["peak_shear_Pa", "peak_shear_sd_Pa"])
        self.assertAlmostEqual(rows[2]["depth_m"], 0.025)

    def test_janssen_shaft_of_a_janssen_wall(self):
        # the measured pressure is Janssen's with the mean K: the ratio is 1; no wall shear: K_eff is
        # p_w over the weight above each ring per area
        mesh, rings, _ = cylinder_rings(R=0.075, rows=10)
        D, rho_b, mu_w, ks, surface = 0.15, 700.0, 0.5, (0.4, 0.6), 0.1
        depth = surface - rings.z
        prof = dict(static_normal_Pa=gc.closed_forms.janssen(depth, D, rho_b, mu_w, 0.5, 9.81)[1],
                    static_shear_Pa=np.zeros(rings.n))
        wall, band = np.ones(rings.n, bool), depth > 0.02
        zs = np.linspace(0.0005, 0.0995, 200)
        res, dep = gc.silo_walls.janssen_shaft(rings, prof, wall, band, surface, D, rho_b, mu_w, ks, zs, np.full(200, 1e-3),
                                               0.05)
        np.testing.assert_allclose(dep, depth)
        self.assertAlmostEqual(res["shaft_static_over_janssen_mid"], 1.0, places=12)
        self.assertEqual(res["janssen_rings"], int(band.sum()))
        self.assertTrue(res["janssen_lo_mean_Pa"] < res["shaft_static_mean_Pa"] < res["janssen_hi_mean_Pa"]
                        < res["hydrostatic_mean_Pa"])
        self.assertEqual(res["mu_mobilised"], 0.0)
        self.assertAlmostEqual(res["shaft_pressure_at_janssen_depth_Pa"],
                               float(gc.closed_forms.janssen(np.array([0.05]), D, rho_b, mu_w, 0.5, 9.81)[1][0]), delta=0.5)

    def test_layer_slice_colours_by_the_layer_at_rest(self):
        fill = dict(id=np.array([1, 2, 3]), z=np.array([0.005, 0.015, 0.025]))
        final = dict(id=np.array([1, 2, 3]), x=np.zeros(3), y=np.array([0.0, 0.0, 0.5]), z=np.zeros(3),
                     radius=np.full(3, 0.001))
        fig, ax = gc.plots.pyplot().subplots()
        ax.set(xlim=(-0.1, 0.1), ylim=(-0.1, 0.1), aspect="equal")
        gc.silo_walls.layer_slice(fig, ax, fill, final, 0.0, 0.01, 0.1)
        col = ax.collections[0].get_facecolors()
        self.assertEqual(len(col), 2)                           # the third is outside the slice
        np.testing.assert_allclose(col[0][:3], gc.plots.pyplot().matplotlib.colors.to_rgb("tab:blue"))
        np.testing.assert_allclose(col[1][:3], gc.plots.pyplot().matplotlib.colors.to_rgb("tab:orange"))

    def test_panels_of_layers_and_force_chains(self):
        fill = dict(id=np.array([1, 2]), z=np.array([0.005, 0.015]))
        final = dict(id=np.array([1, 2]), x=np.array([0.0, 0.01]), y=np.zeros(2), z=np.zeros(2), radius=np.full(2, 0.003))
        cols = " ".join(f"c_pairs[{k}]" for k in range(1, 13))
        with tempfile.TemporaryDirectory() as d:
            dumps = []
            for step, f in ((0, 1.0), (500, 3.0)):      # two contacts, the second three times the first's force
                rows = [[0.0] * 12, [0.0] * 12]
                rows[0][2], rows[0][5], rows[0][9] = 0.01, 0.02, f
                rows[1][2], rows[1][5], rows[1][9] = 0.02, 0.03, 3 * f
                dumps.append(write(os.path.join(d, f"pairs_{step}.dump"), f"ITEM: TIMESTEP\n{step}\nITEM: NUMBER OF ENTRIES\n2\n"
                                   f"ITEM: BOX BOUNDS\n0 1\n0 1\n0 1\nITEM: ENTRIES {cols}\n" +
                                   "".join(" ".join(map(str, r)) + "\n" for r in rows)))
            png = gc.silo_walls.layer_panels(os.path.join(d, "layers.png"), [("a", fill, final, 0.01)] * 2,
                                             0.025, 0.075, 0.01, 0.007, "t", dpi=40)
            self.assertEqual(png_size(png)[1], round(5.6 * 40))
            png = gc.silo_walls.force_chain_panels(os.path.join(d, "fc.png"), [("a", dumps, 1e-4, 0.01, 0.1),
                                                   ("b", dumps[:1], 1e-4, 0.01, 0.1)], 0.025, 0.075, 0.01, "t", dpi=40)
            self.assertEqual(png_size(png)[1], round(2 * 5.2 * 40))       # two rows: at rest and the last dump

    def test_outline(self):
        fig, ax = gc.plots.pyplot().subplots()
        gc.silo_walls.outline(ax, 0.025, 0.075, 0.03, 0.2)
        self.assertEqual([list(l.get_xdata()) for l in ax.lines], [[-0.025, -0.075, -0.075], [0.025, 0.075, 0.075]])


class LayeredFill(unittest.TestCase):
    def test_layers_above_the_rest_level(self):
        # 1001 grains of 1 cm3 into D = 0.2 m on a flat floor (h = 0), regions of radius 0.09 m at 0.25:
        # 1.001e-3 m3 / (0.25 pi 0.09^2) = 0.157 m of region, so two layers of at most 10 cm (501 + 500)
        lines, top = gc.layered_fill.cylinder(1001, 1e-6, 0.2, 0.05, 0.0, 0.09, 0.25, 0.1, 0.6, 0.02, 100, 500)
        regions = [ln.split() for ln in lines.splitlines() if ln.startswith("region")]
        counts = [int(ln.split("particles_in_region ")[1].split()[0]) for ln in lines.splitlines() if "insert/pack" in ln]
        self.assertEqual(counts, [501, 500])
        # the first 0.02 m above the floor; the second 0.02 m above the first's 501 grains at rest at 0.6
        self.assertAlmostEqual(float(regions[0][7]), 0.02, places=12)
        self.assertAlmostEqual(float(regions[1][7]), 501e-6 / 0.6 / (math.pi * 0.01) + 0.02, places=5)
        self.assertAlmostEqual(top, float(regions[1][7]) + 500e-6 / (0.25 * math.pi * 0.09 ** 2), places=5)
        self.assertEqual([ln.split()[1] for ln in lines.splitlines() if ln.startswith("run")], ["500", "1"])
        seeds = [int(ln.split("seed ")[1].split()[0]) for ln in lines.splitlines() if "insert/pack" in ln]
        self.assertEqual(seeds[:2], [101, 103])                 # primes after the seed, each after the last


class StrainSummary(unittest.TestCase):
    def test_steady_window_of_a_series(self):
        cols = len(gc.strain.COLUMNS)
        # intervals from steps 0, 100, 200, 300 (dt 1e-3 s): I1 1, 2, 3, 4; 50 grains, one lost in each
        rows = [[s, s + 100, 50, 1, 1e-6, float(i + 1), -0.5] + [0.1 * (i + 1)] * 3 + [0.0] * 3 for i, s in
                enumerate((0, 100, 200, 300))]
        self.assertEqual(len(rows[0]), cols)
        with tempfile.TemporaryDirectory() as d:
            res = gc.strain.steady(rows, 1e-3, 0.2, os.path.join(d, "s.csv"))
            self.assertEqual(gc.series.read_csv(os.path.join(d, "s.csv"))["t1"][-1], 0.4)
        self.assertEqual((res["strain_intervals"], res["I1_mean"], res["I1_sd_time"], res["cv_grains_lost"]), (2, 3.5, 0.5, 4))
        self.assertAlmostEqual(res["I1_of_mean"], 3 * 0.35)            # tr of the mean strain diag(0.35)
        self.assertTrue(math.isnan(gc.strain.steady(rows, 1e-3, 1.0)["J2_mean"]))

    def test_check_hull_passes(self):
        c = gc.checks.Checks("t")
        gc.strain.check_hull(c, 0.025)
        self.assertEqual((len(c.lines), c.failed), (1, []))


if __name__ == "__main__":
    unittest.main()
