#!/usr/bin/env python3
"""fits.beverloo_size, fits.mean_se (tools/granair_cases/fits.py) and size_study's window
rates and fit over runs on inputs whose answer
is known: Beverloo rates made with a known k at three parcel sizes (k and the rate at the
primary size recovered exactly), two points (the extrapolation's error from the two
Lagrange weights by hand), three points off a line by hand-computed amounts (chi2, the
Birge ratio and the scaled error), the slot form (exponent 1.5: k, the rate and the
two-point error), bad input, and the standard error of a short series
with a hand-computed lag-1 autocorrelation."""
import math
import sys

import numpy as np

from granair_cases import closed_forms, fits, size_study

failures = []


def check(name, got, want, rel=1e-9, abs_=0.0):
    if not (abs(got - want) <= max(rel * abs(want), abs_)):
        failures.append(f"{name}: got {got!r}, expected {want!r} (rel {rel}, abs {abs_})")


# exact Beverloo rates, D = 25 mm, k = 1.5, at the parcel sizes of s = 4, 5, 6 (660 um primaries)
D, k, rho_b = 25e-3, 1.5, 887.0
d = np.array([4, 5, 6]) * 660e-6
w = np.array([closed_forms.beverloo_circular(D, x, rho_b, k) for x in d])
f = fits.beverloo_size(d, w, 0.01 * w, D, 660e-6)
check("k from exact rates", f["k"], k, 1e-9)
check("W at the primary size", f["w_at"], closed_forms.beverloo_circular(D, 660e-6, rho_b, k), 1e-9)
check("chi2 of exact rates", f["chi2"], 0.0, abs_=1e-12)
check("dof", f["dof"], 1)
check("exact rates: scaled error = statistical error", f["w_at_se"], f["w_at_se_stat"], 1e-12)

# the slot form (exponent 1.5, Hagen-Beverloo): exact rates of a 10 mm slot, 60 mm long, k = 1.4,
# at the parcel sizes of s = 5, 7.6, 10 (218 um primaries): k and the rate at 218 um recovered exactly
b_slot, k_slot = 10e-3, 1.4
d_slot = np.array([5, 7.6, 10]) * 218e-6
w_slot = np.array([closed_forms.beverloo_slot(b_slot, x, 619.0, 0.06, k_slot) for x in d_slot])
f = fits.beverloo_size(d_slot, w_slot, 0.01 * w_slot, b_slot, 218e-6, exponent=1.5)
check("slot: k from exact rates", f["k"], k_slot, 1e-9)
check("slot: W at the primary size", f["w_at"], closed_forms.beverloo_slot(b_slot, 218e-6, 619.0, 0.06, k_slot), 1e-9)
check("slot: chi2 of exact rates", f["chi2"], 0.0, abs_=1e-12)
# its error by hand: two points, y = W^(2/3), sigma_y = (2/3) W^(-1/3) sigma_W, the Lagrange weights
f = fits.beverloo_size(d_slot[:2], w_slot[:2], 0.01 * w_slot[:2], b_slot, 218e-6, exponent=1.5)
y, sy = w_slot[:2] ** (2 / 3), (2 / 3) * w_slot[:2] ** (-1 / 3) * 0.01 * w_slot[:2]
l1, l2 = (d_slot[1] - 218e-6) / (d_slot[1] - d_slot[0]), (218e-6 - d_slot[0]) / (d_slot[1] - d_slot[0])
y_at = l1 * y[0] + l2 * y[1]
check("slot, two points: its error", f["w_at_se_stat"], 1.5 * y_at ** 0.5 * math.hypot(l1 * sy[0], l2 * sy[1]), 1e-9)
try:
    fits.beverloo_size(d_slot, w_slot, 0.01 * w_slot, b_slot, 218e-6, exponent=0.0)
    failures.append("beverloo_size exponent 0: expected ValueError")
except ValueError:
    pass

# two points: the line through them; var(y_at) = (L1 s1)^2 + (L2 s2)^2 with the Lagrange weights
d2, w2, se2 = np.array([3.3e-3, 3.96e-3]), np.array([0.0915, 0.0823]), np.array([0.001, 0.0014])
f = fits.beverloo_size(d2, w2, se2, D, 660e-6)
y, sy = w2 ** 0.4, 0.4 * w2 ** -0.6 * se2
l1, l2 = (d2[1] - 660e-6) / (d2[1] - d2[0]), (660e-6 - d2[0]) / (d2[1] - d2[0])
y_at = l1 * y[0] + l2 * y[1]
check("two points: W at the primary size", f["w_at"], y_at ** 2.5, 1e-12)
check("two points: its error", f["w_at_se_stat"], 2.5 * y_at ** 1.5 * math.hypot(l1 * sy[0], l2 * sy[1]), 1e-9)
check("two points: k", f["k"], -(y[1] - y[0]) / (d2[1] - d2[0]) * D / (y[0] - d2[0] * (y[1] - y[0]) / (d2[1] - d2[0])), 1e-9)
if not (math.isnan(f["birge"]) and f["w_at_se"] == f["w_at_se_stat"]):
    failures.append("two points: expected no Birge ratio and the statistical error")

# three points off the line y = 1 + x by hand: d = 1, 2, 3, y = 1, 2.2, 3, sigma_y 0.1: the
# fit is y = 0.0667 + 1.0 d, residuals -2/3, 4/3, -2/3 sigma, chi2 8/3, Birge sqrt(8/3)
y3, s3 = np.array([1.0, 2.2, 3.0]), 0.1
w3 = y3 ** 2.5
f = fits.beverloo_size([1.0, 2.0, 3.0], w3, s3 / (0.4 * w3 ** -0.6), 10.0, 0.0)
check("off-line slope", f["b1"], 1.0, 1e-9)
check("off-line intercept", f["b0"], 0.2 / 3, 1e-9)
for i, want in enumerate((-2 / 3, 4 / 3, -2 / 3)):
    check(f"off-line residual {i}", f["residuals"][i], want, 1e-9)
check("off-line chi2", f["chi2"], 8 / 3, 1e-9)
check("off-line Birge ratio", f["birge"], math.sqrt(8 / 3), 1e-9)
check("off-line scaled error", f["w_at_se"], math.sqrt(8 / 3) * f["w_at_se_stat"], 1e-9)
# var(b0) of three equally weighted points at d = 1, 2, 3: s^2 sum d^2 / (n sum d^2 - (sum d)^2) = s^2 14/6
check("off-line intercept error", f["w_at_se_stat"], 2.5 * (0.2 / 3) ** 1.5 * s3 * math.sqrt(14 / 6), 1e-9)

for bad in (([3e-3], [0.09], [0.001]), ([3e-3, 4e-3], [0.09, 0.08], [0.001, 0.0])):
    try:
        fits.beverloo_size(*bad, D, 660e-6)
        failures.append(f"beverloo_size{bad}: expected ValueError")
    except ValueError:
        pass

# mean_se: x = 1, 2, 3, 4: residuals -1.5 -0.5 0.5 1.5, r1 = 1.25 / 5 = 0.25, sd^2 = 5/3:
# se = sqrt(5/3) / 2 * sqrt(1.25 / 0.75) = 5/6
m, se = fits.mean_se([1.0, 2.0, 3.0, 4.0])
check("mean", m, 2.5)
check("se with r1 = 0.25", se, 5 / 6, 1e-12)
m, se = fits.mean_se([1.0, 3.0, 1.0, 3.0, 1.0, 3.0])        # r1 < 0: plain sd / sqrt(n)
check("se with r1 < 0", se, np.std([1, 3, 1, 3, 1, 3], ddof=1) / math.sqrt(6), 1e-12)
if not math.isnan(fits.mean_se([1.0, 2.0])[1]):
    failures.append("mean_se of two values: expected NaN")

# size_study.window_rates: m(t) = 2 t up to 0.3 s, then 5 t - 0.9 (rate 2, then 5): the 0.1 s
# windows from 0.1 to 0.45 s are [0.1, 0.2], [0.2, 0.3], [0.3, 0.4] (the partial last one dropped)
tt = np.linspace(0.0, 0.5, 1001)
mm = np.where(tt <= 0.3, 2 * tt, 5 * tt - 0.9)
rates = size_study.window_rates(tt, mm, 0.1, 0.45, 0.1)
if rates.size != 3:
    failures.append(f"window_rates: {rates.size} windows, expected 3")
for i, want in enumerate((2.0, 2.0, 5.0)):
    check(f"window rate {i}", rates[i], want, 1e-9)
# size_study.analyse: the exact slot rates above, sorted by d, every pair on the same line
runs = [dict(s=s_, d=x, W=w_, se=0.01 * w_) for s_, x, w_ in zip((10, 5, 7.6), d_slot[[2, 0, 1]], w_slot[[2, 0, 1]])]
res = size_study.analyse(runs, b_slot, 218e-6, exponent=1.5)
check("analyse: k", res["fit"]["k"], k_slot, 1e-9)
if [r["s"] for r in runs] != [5, 7.6, 10] or len(res["pairs"]) != 3 or "residuals" in res["fit"]:
    failures.append(f"analyse: runs {[r['s'] for r in runs]}, {len(res['pairs'])} pairs, keys {sorted(res['fit'])}")
for p in res["pairs"]:
    check(f"analyse: pair {p['s']} k", p["k"], k_slot, 1e-9)
for r in runs:
    check(f"analyse: line W at s = {r['s']}", r["line_W"], r["W"], 1e-9)
if [x["without_s"] for x in res["leave_one_out"]] != [5, 7.6, 10]:
    failures.append(f"analyse: leave_one_out {res['leave_one_out']}")
for x in res["leave_one_out"]:
    check(f"analyse: without s = {x['without_s']} k", x["k"], k_slot, 1e-9)

# size_study.against: W 0.12 over a converged 0.10 +- 0.01 is 1.2 (band 1.2/1.1 .. 1.2/0.9),
# over the DEM run of the same d (the s = 5 run above) W / that run's W, and outside 15 %
lv = size_study.against([dict(d=runs[0]["d"], W=0.12), dict(d=1e-3, W=0.105)], runs, 0.10, 0.01, 0.15)
check("against: ratio", lv[0]["over_dem_converged"], 1.2)
check("against: band low", lv[0]["over_dem_converged_band"][0], 0.12 / 0.11)
check("against: band high", lv[0]["over_dem_converged_band"][1], 0.12 / 0.09)
check("against: same d", lv[0]["over_dem_same_d"], 0.12 / runs[0]["W"])
if lv[0]["within_target"] or not lv[1]["within_target"] or lv[1]["over_dem_same_d"] is not None:
    failures.append(f"against: within_target {lv[0]['within_target']}, {lv[1]['within_target']}, "
                    f"same d {lv[1]['over_dem_same_d']}")
# size_study.against_line: the printed line of the second level (no DEM run at its d; 1.05, within 15 %)
lv[1]["folder"] = "x"
line = size_study.against_line(lv[1], "calibrated mu(I)", 0.15)
want = ("continuum, calibrated mu(I), d in I = 1000 um (x): W 0.1050 kg/s = 1.050 x the size-converged DEM "
        "(0.955-1.167); within 15 %: yes")
if line != want:
    failures.append(f"against_line: {line!r}, expected {want!r}")

# size_study.seed_repeats: a repeat of the s = 5 run 0.003 kg/s higher, the two s.e. 0.00225 and 0.0015,
# is z = 0.003 / sqrt(0.00225^2 + 0.0015^2) = 1.1094; a repeat of an s with no seed-1 run is left out
reps = [dict(s=5, d=runs[0]["d"], W=runs[0]["W"] + 0.003, se=0.0015), dict(s=99, d=0.01, W=0.1, se=0.001)]
old_se = runs[0]["se"]
runs[0]["se"] = 0.00225
sd, fa = size_study.seed_repeats(runs, reps, b_slot, 218e-6, 1.5)
check("seed_repeats: z", sd[0]["z"], 0.003 / (0.00225 ** 2 + 0.0015 ** 2) ** 0.5, 1e-9)
if len(sd) != 1 or sd[0]["W_seed1"] != runs[0]["W"] or fa is None or size_study.seed_repeats(runs, [], b_slot, 218e-6, 1.5) != ([], None):
    failures.append(f"seed_repeats: {len(sd)} repeats, fit over all {fa is not None}")
runs[0]["se"] = old_se

if failures:
    print("\n".join(failures))
    sys.exit(1)
print("beverloo_size, mean_se, size_study: all checks passed")
