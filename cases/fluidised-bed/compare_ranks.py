#!/usr/bin/env python3
"""Compare the short fluidised-bed run on 1 and on 2 ranks (rank_independence.sh).

    compare_ranks.py RUN_NP1 RUN_NP2

Exits 1 unless
  1. the bead count is the same at every coupling step (no bead lost or
     duplicated by the decomposition);
  2. packed stage (the settled bed at 0.5 U_mf, deterministic): the bed
     pressure drop agrees at every coupling step to TOL_PACKED relative;
  3. fluidised stage (1.5 U_mf, chaotic: trajectories diverge from round-off),
     time average of the bed pressure drop over the stage's averaging window
     (stages.csv): the two runs agree to TOL_FLUIDISED of the buoyant weight
     per area.
Tolerances are argued in README.md.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import analyse  # noqa: E402
import bedphysics as bp  # noqa: E402

TOL_PACKED = 1e-6
TOL_FLUIDISED = 0.05


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    runs = [analyse.read_series(r) for r in sys.argv[1:]]
    stages = analyse.read_stages(sys.argv[1])
    a, b = runs
    failures = []
    if a["t"] != b["t"]:
        sys.exit("compare_ranks.py: the runs have different coupling steps")
    if a["particles"] != b["particles"]:
        k = next(i for i, (p, q) in enumerate(zip(a["particles"], b["particles"])) if p != q)
        failures.append(f"bead count differs at t = {a['t'][k]}: {a['particles'][k]:.0f} vs {b['particles'][k]:.0f}")
    n = int(a["particles"][-1])
    w = bp.buoyant_weight_per_area(n)

    packed, fluid = stages[0], stages[-1]
    worst, t_worst = 0.0, 0.0
    for t, p, q in zip(a["t"], a["dp_bed"], b["dp_bed"]):
        if t <= packed["end_s"] + 1e-12:
            rel = abs(p - q) / abs(p)
            if rel > worst:
                worst, t_worst = rel, t
    print(f"packed stage ({packed['U_s_m_s']:.4f} m/s): largest relative difference of the bed pressure drop "
          f"{worst:.2e} at t = {t_worst:.4f} s (tolerance {TOL_PACKED:.0e})")
    if worst > TOL_PACKED:
        failures.append(f"packed stage: 1 vs 2 ranks differ by {worst:.2e} (relative) at t = {t_worst} s")

    means = []
    for s in runs:
        v = [p for t, p in zip(s["t"], s["dp_bed"]) if fluid["avg_start_s"] < t <= fluid["end_s"] + 1e-12]
        means.append(sum(v) / len(v))
    diff = abs(means[0] - means[1]) / w
    print(f"fluidised stage ({fluid['U_s_m_s']:.4f} m/s): mean bed pressure drop {means[0]:.2f} Pa (1 rank), "
          f"{means[1]:.2f} Pa (2 ranks), W = {w:.2f} Pa: difference {100 * diff:.2f} % of W "
          f"(tolerance {100 * TOL_FLUIDISED:.0f} %)")
    if diff > TOL_FLUIDISED:
        failures.append(f"fluidised stage: mean pressure drops differ by {100 * diff:.2f} % of W")
    if a["particles"] == b["particles"]:
        print(f"beads: the same count at every step on both runs ({n} at the end)")
    if failures:
        print("FAILED:\n  " + "\n  ".join(failures))
        sys.exit(1)
    print("rank independence: all checks passed")


if __name__ == "__main__":
    main()
