#!/usr/bin/env python3
"""The cost model (tools/granair_cases/costs.py) and `./granair estimate`
(tools/estimate.py) against hand values, no simulation (docs/scaling.md).

Hand values, with costs dem = 200 ns, cfd0 = 1 ms, cfd = 2 us/cell,
couple = 100 ns, fixed = 0.5 ms, eff2 = 0.8, memory 100 MiB + 1000 B/particle
+ 4096 B/cell, for P = 1e5, C = 5000, S = 10 coupling steps of K = 50:
  dem    2e-7 * 1e5 * 500    = 10 s
  cfd    (1e-3 + 2e-6 * 5000) * 10 = 0.11 s
  couple 1e-7 * 1e5 * 10     = 0.1 s
  fixed  5e-4 * 10           = 0.005 s      -> 1 rank 10.215 s
  4 ranks: 10.215 / 4 / 0.8 = 3.1922 s, 4 * 3.1922 / 3600 = 3.547e-3 core-h
  memory on 4 ranks: 100 + (1e8 + 2.048e7) / 4 / 2^20 = 128.72 MiB
"""
import io
import json
import os
import tempfile
import unittest
from contextlib import redirect_stdout

from granair_cases import costs as cm  # noqa: E402
import estimate  # noqa: E402

COSTS = {"time": {"dem_s_per_particle_step": 2e-7, "dem_off_s_per_particle_step": 1e-7,
                  "cfd_s_per_step": 1e-3, "cfd_s_per_cell_step": 2e-6,
                  "couple_s_per_particle_step": 1e-7, "fixed_s_per_step": 5e-4},
         "parallel_efficiency_2": 0.8,
         "memory": {"rank_mib": 100.0, "particle_b": 1000.0, "cell_b": 4096.0},
         "cases": {"silo": {"dem_s_per_particle_step": 4e-7, "couple_s_per_particle_step": 1e-7}}}
RUN = {"particles": 1e5, "cells": 5000, "cfd_steps": 10, "interval": 50, "air": True}


class CostModel(unittest.TestCase):
    def test_one_rank_hand_value(self):
        p = cm.predict(COSTS, RUN, 1)
        self.assertAlmostEqual(p["wall_s"], 10.215, places=9)
        self.assertAlmostEqual(p["dem_s"], 10.0, places=9)

    def test_ranks_efficiency_memory(self):
        p = cm.predict(COSTS, RUN, 4)
        self.assertAlmostEqual(p["wall_s"], 10.215 / 4 / 0.8, places=9)
        self.assertAlmostEqual(p["cpu_h"], 10.215 / 0.8 / 3600, places=12)
        self.assertAlmostEqual(p["mem_rank_mib"], 100 + (1e8 + 5000 * 4096) / 4 / 2 ** 20, places=9)

    def test_latency_per_coupling_step(self):
        # with the air on and more than one rank: latency x coupling steps, not divided by the ranks
        lat = {**COSTS, "time": {**COSTS["time"], "latency_s_per_step": 3e-3}}
        self.assertAlmostEqual(cm.predict(lat, RUN, 4)["wall_s"], 10.215 / 4 / 0.8 + 3e-3 * 10, places=9)
        self.assertAlmostEqual(cm.predict(lat, RUN, 1)["wall_s"], 10.215, places=9)
        off = dict(RUN, air=False)
        self.assertAlmostEqual(cm.predict(lat, off, 2)["wall_s"], cm.predict(COSTS, off, 2)["wall_s"], places=12)

    def test_air_off_and_calibration(self):
        off = cm.predict(COSTS, dict(RUN, air=False), 1)
        self.assertAlmostEqual(off["wall_s"], 1e-7 * 1e5 * 500 + 5e-4 * 10, places=9)
        cal = cm.predict(COSTS, RUN, 1, "silo")
        self.assertAlmostEqual(cal["dem_s"], 20.0, places=9)
        with self.assertRaises(KeyError):
            cm.predict(COSTS, RUN, 1, "nosuchcase")

    def test_estimate_reads_a_case_folder(self):
        with tempfile.TemporaryDirectory() as d:
            for sub in ("system", "constant"):
                os.makedirs(os.path.join(d, sub))
            open(os.path.join(d, "system", "controlDict"), "w").write(
                "startTime 0;\nendTime 0.005; // 10 steps\ndeltaT 0.0005;\n")
            open(os.path.join(d, "system", "blockMeshDict"), "w").write(
                "blocks ( hex (0 1 2 3 4 5 6 7) (10 10 20) simpleGrading (1 1 1)\n"
                "         hex (0 1 2 3 4 5 6 7) (5 2 1) simpleGrading (1 1 1) );\n")
            open(os.path.join(d, "constant", "couplingProperties"), "w").write(
                "couplingInterval 50;   // DEM steps per CFD step\nair on;\n")
            costs = os.path.join(d, "costs.json")
            json.dump(COSTS, open(costs, "w"))
            case = estimate.from_case(d)
            self.assertEqual(case["cells"], 2010)
            self.assertEqual(case["interval"], 50)
            self.assertAlmostEqual(case["time"], 0.005)
            out = io.StringIO()
            with redirect_stdout(out):
                estimate.main([d, "--ranks", "1", "--particles", "1e5", "--cells", "5000", "--costs", costs])
            self.assertIn("10 s", out.getvalue())   # 10.215 s printed as "10 s"
            with self.assertRaises(SystemExit) as e:
                estimate.main([d, "--ranks", "1", "--costs", costs])   # no log, no --particles
            self.assertIn("--particles", str(e.exception))


if __name__ == "__main__":
    unittest.main()
