#!/usr/bin/env python3
"""The case layer's discharge_counts, packing_regions and linear_contact modules (tools/granair_cases): the step
counts and the segment plan; the counts of a two-segment run read from hand-made `fix print` files and logs, the
strays of the second segment added to "removed" from its start on, its accounting
balanced (and its checks failing one particle off); a loose packing inside a cylinder
and a box (packing_regions); the rate of a count growing
linearly (its window means and slope exact, their error zero); Beverloo's k recovered
from rates made with it (circular and slot); and the linear spring-dashpot's damping
against the damped oscillator solved by steps: the restitution and the contact time."""
import math
import os
import sys
import tempfile

import numpy as np

import random

from granair_cases import CaseError, checks, closed_forms, dem, discharge_counts, linear_contact, packing_regions

failures = []


def check(name, got, want, rel=1e-9, abs_tol=0.0):
    if not (abs(got - want) <= max(rel * abs(want), abs_tol)):
        failures.append(f"{name}: got {got!r}, expected {want!r} (rel {rel}, abs {abs_tol})")


COLS = ("step", "atoms", "fed", "removed", "below")
with tempfile.TemporaryDirectory() as case:
    os.makedirs(os.path.join(case, "post"))
    os.makedirs(os.path.join(case, "log"))
    with open(os.path.join(case, "post", "counts_1.txt"), "w") as fh:
        fh.write("# step atoms fed removed below\n0 100 0 0 0\n10 100 5 5 1\n20 100 9 9 2\n")
    with open(os.path.join(case, "post", "counts_2.txt"), "w") as fh:   # from the restart at 20, 2 strays deleted
        fh.write("# step atoms fed removed below\n30 100 14 12 1\n")
    with open(os.path.join(case, "log", "segment_1.liggghts"), "w") as fh:
        fh.write("granair stray 1: 0 particles below the sink plane at the start\n")
    with open(os.path.join(case, "log", "segment_2.liggghts"), "w") as fh:
        fh.write("run 10\ngranair stray 2: 2 particles below the sink plane at the start\n")
    c = discharge_counts.read(case, 2, COLS)
    if list(c["step"]) != [0, 10, 20, 30]:
        failures.append(f"steps: {list(c['step'])}")
    if list(c["stray"]) != [0, 0, 0, 2] or list(c["removed"]) != [0, 5, 9, 14]:
        failures.append(f"strays {list(c['stray'])}, removed {list(c['removed'])}")
    if list(c["atoms"]) != [100, 100, 100, 100] or c["atoms"].dtype.kind != "i":
        failures.append(f"atoms: {c['atoms']}")
    acc = discharge_counts.accounting(c, 100)
    check("balance closes with the strays", int(np.max(np.abs(acc["balance"]))), 0)
    check("inserted", acc["inserted"], 114)
    check("in the silo", acc["in_silo"], 99)
    check("discharged", acc["discharged"], 15)
    ch = checks.Checks("unit")
    discharge_counts.check_accounting(ch, "run", acc)
    if len(ch.lines) != 3 or ch.failed:
        failures.append(f"check_accounting: {ch.lines}")
    ch = checks.Checks("unit")
    discharge_counts.check_accounting(ch, "run", discharge_counts.accounting(c, 101))   # one particle too many
    if [ln[:4] for ln in ch.lines] != ["FAIL", "FAIL", "PASS"]:
        failures.append(f"check_accounting of an unbalanced run: {ch.lines}")
    try:
        discharge_counts.read(case, 3, COLS)
        failures.append("a missing segment: no CaseError")
    except CaseError:
        pass

# step counts: dt = 1e-3 s, the unit 0.1 s: counts every 0.05 units (5 steps), snapshots every 0.5 (10 counts),
# segments of 3 (6 snapshots), the window after 2 for 4
st = discharge_counts.steps(1e-3, 0.1, 0.05, 0.5, 3.0, 2.0, 4.0)
if st != dict(print=5, snap=50, seg=300, avg_from=200, total=600):
    failures.append(f"steps: {st}")

# the segments: 25 steps in pieces of 10, CG from the segments ending after step 12
pl = discharge_counts.plan(25, 10, 5, 12)
if pl != [dict(nsteps=10, cg_every=0), dict(nsteps=10, cg_every=5), dict(nsteps=5, cg_every=5)]:
    failures.append(f"plan: {pl}")
if any(x["cg_every"] for x in discharge_counts.plan(25, 10, 5, 12, cg_on=False)):
    failures.append("plan: CG snapshots with cg_on false")

# packing regions: every sphere of a loose packing inside and gap clear of the walls
for name, (sample, inside), ok in (
        ("cylinder", packing_regions.cylinder(0.05, 0.0002), lambda x, y, z, r: math.hypot(x, y) + r + 0.0002 <= 0.05 + 1e-12),
        ("box", packing_regions.box(0.05, 0.0055, 0.0002), lambda x, y, z, r: abs(x) + r + 0.0002 <= 0.05 + 1e-12
         and abs(y) + r + 0.0002 <= 0.0055 + 1e-12)):
    atoms = dem.loose_packing([0.01] * 60, random.Random(3), sample, inside, lambda t: t + 0.01, 0.05, 0.010001, 0.0002,
                              origin=(-0.06, -0.06, 0.0))
    if len(atoms) != 60 or not all(ok(x, y, z, d / 2) and z >= d / 2 + 0.0002 for x, y, z, d in atoms):
        failures.append(f"packing_regions.{name}: a sphere outside or {len(atoms)} placed")

# a count growing at 7 per unit time, counted every 0.1: windows of 5 counts
t = np.arange(0, 41) * 0.1
n = np.rint(7.0 * t * 10).astype(int)        # 70 per unit time, integers
tw, rate = discharge_counts.window_rates(t, n, 5)
check("window count", len(rate), 8)
check("window midpoint", tw[0], 0.25, 1e-12)
check("window rate", float(np.max(abs(rate - 70.0))), 0.0, 0.0, 1e-9)
steady, se = discharge_counts.steady_rate(t, n, tw, rate, 1.0)
check("steady slope", steady, 70.0, 1e-9)
check("steady se (exact data)", se, 0.0, 0.0, 1e-9)
if not math.isnan(discharge_counts.steady_rate(t, n, tw, rate, 3.8)[1]):
    failures.append("steady_rate: NaN expected with one window")

# Beverloo's k at fixed C: the rate made with k = 1.4 gives 1.4 back
d, rho_b = 2e-3, 1500.0
W = closed_forms.beverloo_circular(0.02, d, rho_b, 1.4, 0.58)
check("beverloo_k circular", discharge_counts.beverloo_k(W, 0.02, d, rho_b, 0.58), 1.4, 1e-9)
W = closed_forms.beverloo_slot(0.01, d, rho_b, 0.005, 2.1, 0.58)
check("beverloo_k slot", discharge_counts.beverloo_k(W, 0.01, d, rho_b, 0.58, 1.5, 0.005), 2.1, 1e-9)

# the dashpot: integrate m_eff x'' = -k x - gamman m_eff x' through one contact
k_n, e, m = 1.0e6, 0.5, 0.12
law = linear_contact.linear_dashpot(k_n, e, m)
for kind, m_eff in (("pp", m / 2), ("pw", m)):
    gam, dt = law["gamman_" + kind], law["t_contact_" + kind] / 200000
    x, v, steps = 0.0, 1.0, 0
    while True:              # velocity Verlet with the damping taken at the half step
        a = -k_n / m_eff * x - gam * v
        vh = v + 0.5 * dt * a
        x += dt * vh
        v = (vh + 0.5 * dt * (-k_n / m_eff * x)) / (1 + 0.5 * dt * gam)
        steps += 1
        if x <= 0.0 and steps > 1:
            break
    check(f"{kind}: restitution", -v, e, 1e-4)
    check(f"{kind}: contact time", steps * dt, law["t_contact_" + kind], 1e-4)
    zeta = -math.log(e) / math.sqrt(math.pi ** 2 + math.log(e) ** 2)
    check(f"{kind}: gamman = 2 zeta omega_0", gam, 2 * zeta * math.sqrt(k_n / m_eff), 1e-12)

if failures:
    print("\n".join(failures))
    sys.exit(1)
print("discharge_counts, packing_regions, linear_contact: all checks passed")
