#!/usr/bin/python3
"""Two-slot silo (Fullard et al. 2019; README.md): DEM discharge through two
14 mm slots separated by L, both friction sets, CG fields over the openings.

    study.py [--size test|demo|study] [--friction low high] [--L 0 1 2 4 8 16 32 single]
             [--jobs 2] [--out DIR] [--check] [--setup-only] [--post-only]

OUT defaults to reference-study/ for the study size (the committed results: a
resumed study adds its runs there) and to run/<size>/ for test and demo.

Per friction set one fill (OUT/runs/<set>/fill: poured into the closed silo
and settled), then per geometry a discharge (OUT/runs/<set>/<geom>) in
restart chunks, the last of them writing the 20 CG snapshots. A stopped
study resumes: a finished fill, chunk or run is skipped. At most --jobs
LIGGGHTS runs at a time (one rank each, nice them: README "Running").
OUT/<set>/<geom>.json (flow rate, accounting, CG averages, cost),
<geom>_flow.csv, <geom>_cg.csv; OUT/flow_rate.csv|png, r2_fields.csv|png,
phi_I.png, maps_<set>.png, summary.txt, level.json per run (compare).
"""
import os
from functools import partial

HERE = os.path.dirname(os.path.abspath(__file__))

import granair_cases as gc        # noqa: E402
import parameters as P            # noqa: E402
import post                       # noqa: E402
import silo                       # noqa: E402


def geometries(names):
    out = []
    for n in names:
        if n == P.SINGLE:
            out.append(P.SINGLE)
        else:
            try:
                out.append(int(n))
            except ValueError:
                raise gc.CaseError(f"--L {n}: expected a separation in whole mm or '{P.SINGLE}'")
    return out


def main():
    ap = gc.cli.parser(__doc__, out_help="outputs (default: reference-study/ beside this script for the study "
                                         "size, the committed results a resumed study continues; run/<size> else)")
    ap.add_argument("--size", choices=sorted(P.SIZES), default="demo")
    ap.add_argument("--friction", nargs="+", choices=sorted(P.FRICTION), default=None,
                    help="friction sets (default: the size's; demo low, study both)")
    ap.add_argument("--L", nargs="+", default=None,
                    help="separations [mm] and/or 'single' (default: the size's; study all eight)")
    gc.study.options(ap)
    a = gc.study.parse(ap, lambda a: os.path.join(HERE, "reference-study" if a.size == "study" else os.path.join("run", a.size)))
    a.friction = a.friction or P.SIZES[a.size]["friction"]
    geoms = geometries(a.L) if a.L else P.SIZES[a.size]["geometries"]
    runs = os.path.join(a.out, "runs")
    print(f"two-slot-silo: size {a.size}, friction {' '.join(a.friction)}, "
          f"geometries {' '.join(silo.geometry_name(L) for L in geoms)}, {a.jobs} job(s)", flush=True)

    def one(f, L, simulate):
        cost = simulate()
        try:
            post.run(silo.numbers(a.size, f), L, os.path.join(runs, f, silo.geometry_name(L)),
                     os.path.join(runs, f, "fill"), os.path.join(a.out, f))
        except gc.CaseError as e:      # the run is kept: --post-only redoes this
            print(f"two-slot-silo {f} {silo.geometry_name(L)}: post-processing failed ({e}); the run is "
                  f"finished, rerun the study with --post-only", flush=True)
        return {"cpu_s": sum(c["cpu_s"] for c in cost.values())}

    fills = [(f"{f} fill", *silo.fill_stage(silo.numbers(a.size, f), os.path.join(runs, f, "fill"))) for f in a.friction]
    # the normalisers first (single, L = 0), the sets interleaved, so a stopped study has the most useful runs
    order = sorted(((f, L) for f in a.friction for L in geoms), key=lambda t: (post.priority(t[1]), a.friction.index(t[0])))
    discharges = []
    for f, L in order:
        setup, simulate = silo.run_stage(silo.numbers(a.size, f), L, os.path.join(runs, f, silo.geometry_name(L)),
                                         os.path.join(runs, f, "fill"), lambda m, f=f: print(f"two-slot-silo {f} {m}", flush=True))
        discharges.append((f"{f} {silo.geometry_name(L)}", setup, partial(one, f, L, simulate)))
    if gc.study.drive(a, "two-slot-silo", fills, discharges) is None:
        return
    c = gc.checks.Checks(f"two-slot-silo {a.size}")
    post.study(a, runs, geoms, c)
    c.report(enforce=a.check)


if __name__ == "__main__":
    gc.cli.main(main)
