#!/usr/bin/env python3
"""gc.calibration (tools/granair_cases/calibration.py): the material entries of a
hand-made muI block are replaced by the committed calibration
(cases/rheology-calibration/results/calibration.json), the numerics kept (the
viscosity floor the literature block's, written explicitly), d overridden on
request; a block without an entry, a non-muI block and an
unknown material stop with the file and the key named."""
import json
import math
import sys

import granair_cases as gc
from granair_cases import calibration

failures = []
LITERATURE = """// literature header
rheology
{
    type        muI;
    muS         0.401;
    mu2         0.908;
    I0          0.0465;
    d           660e-6;
    rhoP        1500;
    phiMax      0.632;
    phiMin      0.443;
    etaMax      1e5;
    regularisation barkerGray2017;
}
"""


def entry(text, key):
    line = next(l for l in text.splitlines() if l.strip().startswith(key + " "))
    return float(line.split()[1].rstrip(";"))


with open(calibration.RESULTS) as fh:
    fit = json.load(fh)["mcc-hopper"]
out = calibration.block(LITERATURE, "mcc-hopper")
for key, name in calibration.KEYS.items():
    if abs(entry(out, key) - fit["fit"][name]) > 1e-5 * abs(fit["fit"][name]):
        failures.append(f"{key}: {entry(out, key)} vs calibration {fit['fit'][name]}")
for key, want in (("d", fit["d_parcel_m"]), ("rhoP", fit["rho_p"]), ("etaMax", 1e5)):
    if abs(entry(out, key) - want) > 1e-5 * want:
        failures.append(f"{key}: {entry(out, key)} vs {want}")
# the floor stays the literature block's (rho_p d sqrt(g d) of its d), not the parcel's
if abs(entry(out, "etaMin") - 1500 * 660e-6 * (9.81 * 660e-6) ** 0.5) > 1e-5 * 0.080:
    failures.append(f"etaMin: {entry(out, 'etaMin')} vs the literature floor 0.0802")
if entry(calibration.block(LITERATURE.replace("    etaMax", "    etaMin      0.5;\n    etaMax"), "mcc-hopper"),
         "etaMin") != 0.5:
    failures.append("an explicit etaMin of the block should stay")
if entry(calibration.set_entry(out, "etaMin", 0.01, "test"), "etaMin") != 0.01:
    failures.append("set_entry did not replace etaMin")
if "literature header" in out or "barkerGray2017" not in out:
    failures.append("the literature header comment should go, the numerics stay")
if abs(entry(calibration.block(LITERATURE, "mcc-hopper", d=2e-3), "d") - 2e-3) > 1e-12:
    failures.append("d override not applied")
for text, material, want in ((LITERATURE.replace("    phiMin      0.443;\n", ""), "mcc-hopper", "phiMin"),
                             (LITERATURE.replace("muI", "latzSchmidt"), "mcc-hopper", "type muI"),
                             (LITERATURE, "no-such-material", "no-such-material")):
    try:
        calibration.block(text, material, where="test block")
        failures.append(f"no error for a block without {want}")
    except gc.CaseError as e:
        if want not in str(e):
            failures.append(f"error does not name {want}: {e}")

# The fits: points of a known mu(I) and phi(I) with a small deterministic scatter
# come back within a few of their standard errors (and the errors are small).
import numpy as np  # noqa: E402
truth = dict(mu_s=0.36, mu_2=0.75, I0=0.12)
i = np.logspace(-3, -0.5, 9)
wiggle = 0.004 * np.sin(7.0 * np.arange(len(i)))
fm = calibration.fit_mu(i, calibration.mu_jop(i, truth) + wiggle, np.full(len(i), 0.004))
for k in truth:
    if abs(fm[k] - truth[k]) > 3 * fm[k + "_se"] or fm[k + "_se"] > 0.2 * truth[k]:
        failures.append(f"fit_mu {k}: {fm[k]:.4g} +- {fm[k + '_se']:.2g} vs {truth[k]}")
exact = calibration.fit_mu(i, calibration.mu_jop(i, truth), np.full(len(i), 0.004))
if any(abs(exact[k] - truth[k]) > 1e-6 * truth[k] for k in truth):
    failures.append(f"fit_mu of exact points: {exact} vs {truth}")
fp = calibration.fit_phi(i, 0.62 - 0.2 * i + 0.1 * wiggle, np.full(len(i), 0.001))
if abs(fp["phi_max"] - 0.62) > 3 * fp["phi_max_se"] or abs(fp["phi_min"] - 0.42) > 3 * fp["phi_min_se"]:
    failures.append(f"fit_phi: {fp} vs phi_max 0.62, phi_min 0.42")

# The shear cell's bulk: a linear velocity profile V_x = gdot z with uniform stresses; only the
# band lo <= z <= hi counts (outside it the profile is spoiled on purpose)
z = np.linspace(0.0, 0.02, 41)
gdot, d, rho_p, p, sxz, szz, phi_b = 30.0, 1e-3, 1500.0, 400.0, -150.0, 420.0, 0.58
prof = dict(z=z, velocity_x=gdot * z, pressure=np.full(41, p), shear_stress=np.full(41, 160.0),
            stress_xz=np.full(41, sxz), stress_zz=np.full(41, szz), volume_fraction=np.full(41, phi_b),
            mean_diameter=np.full(41, d))
prof["velocity_x"][:5] = 0.0
prof["stress_xz"][-3:] = 0.0
b = calibration.shear_bulk(prof, 0.003, 0.018, rho_p)
want = dict(I=gdot * d / math.sqrt(p / rho_p), mu=150.0 / p, mu_J2=160.0 / p, mu_xz=150.0 / szz, phi=phi_b,
            gamma_dot=gdot, uniformity=0.0)
for k, v in want.items():
    if abs(b[k] - v) > 1e-9 * max(1.0, abs(v)):
        failures.append(f"shear_bulk {k}: {b[k]!r}, expected {v!r}")
wall = np.array([[-150.0 * 2e-4, 0.0, 420.0 * 2e-4], [-150.0 * 2e-4, 0.0, 420.0 * 2e-4]])
pt = calibration.shear_point(prof, [prof] * 10, 0.003, 0.018, rho_p, wall, 2e-4)
if abs(pt["wall_tau"] - 150.0) > 1e-9 or abs(pt["wall_sigma"] - 420.0) > 1e-9 or pt["mu_se"] > 1e-12:
    failures.append(f"shear_point: wall {pt['wall_tau']}, {pt['wall_sigma']} Pa, mu_se {pt['mu_se']} "
                    "(expected 150, 420, 0 for identical snapshots)")
dev = calibration.vs_fit([dict(I=0.12, mu=0.6, mu_se=0.01)], truth)
if abs(dev[0]["mu_reference_fit"] - 0.555) > 1e-12 or abs(dev[0]["difference"] - 0.045) > 1e-12:
    failures.append(f"vs_fit: {dev} (mu_jop(I0) = (mu_s + mu_2) / 2 = 0.555)")

print("\n".join(failures) or "calibration: all checks passed")
sys.exit(1 if failures else 0)
