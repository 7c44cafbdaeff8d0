#!/usr/bin/env python3
"""Closed-form discharge estimates (tools/granair_cases/closed_forms.py) against hand values.

Hand values (computed on paper, 4 significant figures):
- MCC hopper (reference case B): D = 25 mm, d = 660 um, rho_b = 900, C = 0.58:
  k = 3: 0.58 * 900 * sqrt(9.81) * (0.02302)^2.5 = 0.1315 kg/s;
  k = 1: (0.02434)^2.5 -> 0.1511 kg/s (the band in cases/mcc-hopper/README.md).
- Slot b = 10 mm, L = 60 mm, d = 0.2 mm, rho_b = 600, k = 2:
  0.58 * 600 * sqrt(9.81) * 0.06 * (0.0096)^1.5 = 65.40 * 9.406e-4 = 0.06151 kg/s.
- Carleton (1972) without air: 4 V0^2 sin(theta)/B = g, V0 = sqrt(g B / (4 sin theta)):
  B = 10 mm, theta = 15 deg: sqrt(0.0981 / 1.0353) = 0.3078 m/s.
- Crewdson: dp/dz = -rho_b g / 2 halves the weight: W = W0 / sqrt(2);
  dp/dz = -rho_b g stops the flow.
- Janssen, D = 0.15 m, rho_b = 760, mu_w = 0.52, K = 0.5: z0 = D / (4 mu_w K) = 0.14423 m;
  at 0.2 m depth p_v = 760 x 9.81 x 0.14423 x (1 - exp(-1.3867)) = 806.6 Pa, p_w = 403.3 Pa;
  far below the surface p_w -> rho_b g D / (4 mu_w) = 537.7 Pa; near it p_w = K rho_b g h.
"""
import math
import unittest

from granair_cases import closed_forms as cf


class ClosedForms(unittest.TestCase):
    def test_beverloo_circular_mcc_band(self):
        lo, hi = cf.beverloo_band("circular", 0.025, 660e-6, 900.0)
        self.assertAlmostEqual(lo, 0.1315, delta=5e-5)
        self.assertAlmostEqual(hi, 0.1511, delta=5e-5)

    def test_hagen_beverloo_slot(self):
        w = cf.beverloo_slot(0.010, 0.2e-3, 600.0, 0.060, 2.0)
        self.assertAlmostEqual(w, 0.06151, delta=5e-5)

    def test_beverloo_closed_orifice_is_zero(self):
        self.assertEqual(cf.beverloo_circular(1e-3, 1e-3, 900.0, 3.0), 0.0)

    def test_slot_needs_length(self):
        with self.assertRaises(ValueError):
            cf.beverloo_band("slot", 0.01, 2e-4, 600.0)

    def test_carleton_dry_root(self):
        v = cf.carleton_velocity(0.010, 15.0, 2e-4, 1060.0)
        self.assertAlmostEqual(v, 0.3078, delta=5e-5)

    def test_carleton_air_solves_its_balance_and_slows(self):
        B, th, d, rp, rf, mu = 0.010, 15.0, 218e-6, 1060.0, 1.2, 1.8e-5
        v = cf.carleton_velocity(B, th, d, rp, rf, mu)
        lhs = 4 * v * v * math.sin(math.radians(th)) / B + \
            15 * rf ** (1 / 3) * mu ** (2 / 3) * v ** (4 / 3) / (rp * d ** (5 / 3))
        self.assertAlmostEqual(lhs, 9.81, delta=1e-9)
        r = cf.carleton_ratio(B, th, d, rp, rf, mu)
        self.assertTrue(0 < r < 1)
        # coarser particles feel less drag: the ratio tends to 1
        self.assertGreater(cf.carleton_ratio(B, th, 10 * d, rp, rf, mu), r)

    def test_ergun_and_wen_yu(self):
        # the first-step packed column (tests/case/first_step_force.py): eps = 1 - pi/6,
        # d = 1 mm, U_s = 0.2 eps = 0.0953 m/s: 150 mu U (1-e)^2/(e^3 d^2) = 652.3,
        # 1.75 rho U^2 (1-e)/(e^3 d) = 92.3 Pa/m
        eps = 1 - math.pi / 6
        self.assertAlmostEqual(cf.ergun_gradient(0.2 * eps, eps, 1e-3, 1.2, 1.8e-5), 744.6, delta=0.5)
        # 0.5 mm glass beads in air (cases/fluidised-bed/README.md): Ar = 1.2 x 2498.8 x 9.81 x
        # 1.25e-10 / 3.24e-10 = 11349, U_mf = 0.1885 m/s
        self.assertAlmostEqual(cf.archimedes(0.5e-3, 2500, 1.2, 1.8e-5), 11349, delta=1)
        self.assertAlmostEqual(cf.wen_yu_umf(0.5e-3, 2500, 1.2, 1.8e-5), 0.1885, delta=5e-5)

    def test_crewdson(self):
        self.assertAlmostEqual(cf.crewdson(1.0, -600.0 * 9.81 / 2, 600.0), 1 / math.sqrt(2), delta=1e-12)
        self.assertEqual(cf.crewdson(1.0, -600.0 * 9.81 * 1.5, 600.0), 0.0)
        self.assertEqual(cf.crewdson(0.3, 0.0, 600.0), 0.3)

    def test_janssen(self):
        p_v, p_w = cf.janssen(0.2, 0.15, 760.0, 0.52, 0.5)
        self.assertAlmostEqual(p_v, 806.6, delta=0.05)
        self.assertAlmostEqual(p_w, 403.3, delta=0.05)
        self.assertAlmostEqual(float(cf.janssen(50.0, 0.15, 760.0, 0.52, 0.5)[1]), 537.7, delta=0.05)
        _, near = cf.janssen(1e-4, 0.15, 760.0, 0.52, 0.5)
        self.assertAlmostEqual(float(near) / (0.5 * 760 * 9.81 * 1e-4), 1.0, delta=1e-3)
        self.assertEqual(cf.janssen([0.1, 0.2], 0.15, 760.0, 0.52, 0.5)[1].shape, (2,))

    def test_latz_yield(self):
        # the lactose closure (cases/wedge-silo/continuum/latzSchmidt/rheology): c0 0.5579,
        # cMax 0.5771, T0 0.41; at c = 0.5675, 1 - c/cMax = 0.016635, p_y = 0.41 x 0.0096 / 0.016635
        c0, cm, t0 = 0.5579, 0.5771, 0.41
        self.assertAlmostEqual(cf.latz_yield_pressure(0.5675, c0, cm, t0), 0.23661, delta=1e-5)
        self.assertEqual(cf.latz_yield_pressure(0.55, c0, cm, t0), 0.0)
        for q in (1e-3, 0.28, 2.1, 50.0):     # the inverse, over the silo's range and beyond
            c = cf.latz_yield_packing(q, c0, cm, t0)
            self.assertTrue(c0 < c < cm)
            self.assertAlmostEqual(cf.latz_yield_pressure(c, c0, cm, t0) / q, 1.0, delta=1e-12)
        self.assertEqual(cf.latz_yield_packing(0.0, c0, cm, t0), c0)
        with self.assertRaises(ValueError):
            cf.latz_yield_pressure(cm, c0, cm, t0)


if __name__ == "__main__":
    unittest.main(verbosity=2)
