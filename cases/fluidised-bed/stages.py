#!/usr/bin/env python3
"""Velocity stages of the fluidised-bed run, and the case files they set.

    stages.py CASE_DIR [--quick]

Writes the inlet table of CASE_DIR/0/U (steady stages joined by short linear
ramps), endTime in CASE_DIR/system/controlDict, and CASE_DIR/stages.csv
(stage, role, U_s, start, end, and avg_start: a stage is averaged from
SETTLE after its start, or over its last half if shorter). Velocities are
multiples of Wen & Yu's U_mf.

Full sweep: a gentle ramp up to fluidise the poured bed, then steps DOWN
from fluidised to packed, the classical way of measuring U_mf (a bed
defluidised slowly settles into a reproducible packing; a bed fluidised from
a poured packing shows an overshoot). Roles: 'fluidised' stages
(U >= 1.7 U_mf,WY) give the plateau, 'packed' stages (U <= 0.7 U_mf,WY) the
packed-bed line; stages in between show the transition and are plotted but
not asserted (which side of U_mf they fall on is what the run measures).
Whenever the measured U_mf passes its check (within 15 % of Wen & Yu), the
'fluidised' stages are above it and the 'packed' ones below it.
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bedphysics as bp  # noqa: E402

# (U / U_mf,WY, duration [s], role). A 'ramp-up' stage ramps linearly from
# the previous velocity (0 at the start); the others hold their velocity
# after a 2 ms ramp.
FULL = [
    (2.0, 0.06, "ramp-up"),     # fluidise the poured bed gently (a jump to
                                # 2 U_mf lifts it as a plug)
    (2.0, 0.12, "fluidised"),
    (1.7, 0.12, "fluidised"),
    (1.3, 0.04, "transition"),
    (0.9, 0.04, "transition"),
    (0.7, 0.03, "packed"),
    (0.55, 0.02, "packed"),
    (0.4, 0.02, "packed"),
    (0.25, 0.02, "packed"),
]
# Rank-independence run: the settled bed below U_mf (deterministic), then
# fluidised (chaotic: compared statistically).
QUICK = [
    (0.5, 0.02, "packed"),
    (1.5, 0.02, "ramp-up"),
    (1.5, 0.06, "fluidised"),
]
RAMP = 0.002   # [s] linear ramp between steady stages
SETTLE = 0.04  # [s] a stage is averaged after this (or its first half if shorter)
DT = 0.0005    # CFD time step [s] (system/controlDict deltaT)


def schedule(stages):
    """Rows (stage, role, u, start, end, avg_start) and table points (t, u)."""
    u_wy = bp.wen_yu_umf()
    rows, points, t = [], [(0.0, 0.0)], 0.0
    for k, (f, dur, role) in enumerate(stages):
        u = f * u_wy
        start, end = t, t + dur
        if role == "ramp-up":
            points.append((end, u))
        else:
            if k > 0 or start > 0:
                points.append((start + RAMP, u))
            else:
                points[0] = (0.0, u)
            points.append((end, u))
        rows.append((k, role, u, start, end, start + min(SETTLE, 0.5 * dur)))
        t = end
    return rows, points


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("case")
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    rows, points = schedule(QUICK if args.quick else FULL)
    end = rows[-1][4]
    if abs(round(end / DT) * DT - end) > 1e-9:
        sys.exit(f"stages.py: end time {end} s is not a whole number of CFD steps ({DT} s)")

    table = "\n".join(f"            ({t:.6f} (0 0 {u:.8f}))" for t, u in points)
    u_path = os.path.join(args.case, "0", "U")
    with open(u_path) as fh:
        text = fh.read()
    with open(u_path, "w") as fh:
        fh.write(text.replace("INLET_TABLE", table))
    cd_path = os.path.join(args.case, "system", "controlDict")
    with open(cd_path) as fh:
        text = fh.read()
    with open(cd_path, "w") as fh:
        fh.write(text.replace("END_TIME", f"{end:.6f}"))
    with open(os.path.join(args.case, "stages.csv"), "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["stage", "role", "U_s_m_s", "start_s", "end_s", "avg_start_s"])
        for r in rows:
            w.writerow([r[0], r[1], f"{r[2]:.8f}", f"{r[3]:.6f}", f"{r[4]:.6f}", f"{r[5]:.6f}"])


if __name__ == "__main__":
    main()
