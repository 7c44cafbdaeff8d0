#!/usr/bin/python3
"""Corn silo, hopper-angle sweep (Rivera, Avila & Avila 2023, reference case D;
README.md): DEM only (LIGGGHTS, no air).

    study.py [--size study|demo|test] [--angles A ...] [--seeds N] [--jobs J]
             [--youngs E] [--out DIR] [--check] [--post-only] [--fresh] [--setup-only]

For every hopper angle (from the horizontal) and every run (its own random
insertion), in OUT/runs/a<angle>-s<k>/: the fill (template/dem/in.fill: the
grains inserted at random above the shut outlet and settled), then the
discharge (template/dem/in.liggghts) in chunks of CHUNK s, each one LIGGGHTS
process from the previous one's restart. A stopped study resumes: finished
runs are skipped, an unfinished one goes on from its last restart (a fill
that did not finish starts again). Jobs run --jobs at a time (one rank each).

Each finished run is post-processed into OUT/a<angle>/ (post.py): mass flow,
particle accounting, wall loads (static fill and discharge, per ring of wall
elements, maxima and where), the strain invariants over the outlet
(gc.strain), the flow pattern and, for the first run, the coloured layers.
Then every angle with all its runs: mean +- SD (OUT/a<angle>/mean.json,
level.json, the mean wall loads as VTK), and the study's tables and figures
(OUT/summary.csv, summary.md, *.png). --post-only does only that, from the
runs that exist.

Checked (--check exits 1 on a failure): per run, the exact accounting
(inserted = in the silo + below the outlet + removed at the sink; grains
requested = inserted); the shaft's static wall pressure against Janssen's
(the band of K); the strain of a homogeneous deformation by the hull method.
"""
import json
import math
import os
import shutil
from functools import partial

import granair_cases as gc
import geometry
import parameters as P
import post

HERE = os.path.dirname(os.path.abspath(__file__))
OUTS = {"study": "results", "full": "results-full", "demo": "results-demo", "test": "results-test"}


def numbers(grains, discharge, angle, k, youngs):
    """Every number of one run (the template's placeholders, the post-processing's)."""
    radii = [d / 2 for d in P.DIAMETERS]
    t_r = gc.dem.rayleigh_time(min(radii), youngs, P.NU, P.RHO_P)
    dt = P.RAYLEIGH_FRACTION * t_r
    cv = max(1, round(P.CV_EVERY / dt))               # every output interval is a multiple of this
    per = lambda t: max(1, round(t / P.CV_EVERY)) * cv          # noqa: E731
    h = P.hopper_height(angle)
    half = P.D_SILO / 2 + 0.005
    fill_chunk = per(0.05)
    insertion, z_ins_hi = layers(grains, h, radii, P.SEEDS[k][0], per(P.LAYER_TIME))
    z_hi = max(z_ins_hi, P.STRESS_TOP) + 0.02
    youngs_wall = P.YOUNGS_WALL_REF * youngs / P.YOUNGS_REF
    v = dict(GRAINS=grains, ANGLE=angle, SEED=P.SEEDS[k][0], DIST_SEED=P.SEEDS[k][1], DT=dt, RAYLEIGH_S=t_r,
             YOUNGS=youngs, YOUNGS_WALL=youngs_wall, SOFTENING=youngs / P.YOUNGS_REF, NU=P.NU, NU_WALL=P.NU_WALL,
             E_PP=P.E_PP, E_PW=P.E_PW, MU_PP=P.MU_PP, MU_PW=P.MU_PW, RHO_P=P.RHO_P, G=P.G,
             CHARACTERISTIC_VELOCITY=P.CHARACTERISTIC_VELOCITY, SKIN=0.3 * P.DIAMETERS[2],
             MODULUS_RANGE="\n".join(["soft_particles  yes             # LIGGGHTS asks for this below E = 5e6 Pa"]
                                      * (youngs < 5e6) + ["hard_particles  yes             # ... and this above 1e9 Pa"]
                                      * (youngs_wall > 1e9)) or "# (5e6 <= E <= 1e9 Pa: LIGGGHTS' default range)",
             HALF=half, Z_LO=P.SINK_Z - 0.02, Z_HI=z_hi, INSERTION=insertion, LAYER_HEIGHT=P.LAYER_HEIGHT,
             INSERT_FRACTION=P.INSERT_FRACTION, HOPPER_HEIGHT=h, SINK_Z=P.SINK_Z,
             SETTLE_RMS=P.SETTLE_RMS, SETTLE_MIN=P.SETTLE_MIN, SETTLE_MAX=P.SETTLE_MAX, CHUNK_STEPS=fill_chunk,
             N_MIN=math.ceil(P.SETTLE_MIN / (fill_chunk * dt)), N_MAX=math.ceil(P.SETTLE_MAX / (fill_chunk * dt)),
             CV_RADIUS=P.CV_RADIUS, CV_HEIGHT=P.CV_HEIGHT, CV_DUMP_RADIUS=P.CV_RADIUS + P.CV_MARGIN, CV_DUMP_LO=-P.CV_MARGIN,
             CV_DUMP_HI=P.CV_HEIGHT + P.CV_MARGIN, CV_STEPS=cv, FLOW_STEPS=per(P.FLOW_EVERY), WALL_STEPS=per(P.WALL_EVERY),
             FULL_STEPS=per(P.FULL_EVERY), THERMO_STEPS=per(0.05), CHUNK=P.CHUNK, DISCHARGE_CHUNK_STEPS=per(P.CHUNK),
             DISCHARGE_STEPS=per(discharge), DISCHARGE_S=per(discharge) * dt)
    for i, (r, w) in enumerate(zip(radii, P.MASS_FRACTIONS), 1):
        v[f"R{i}"], v[f"W{i}"] = r, w
    return v


def layers(grains, h, radii, seed, steps):
    """The fill's insertion block (gc.layered_fill): layers of LAYER_HEIGHT at INSERT_FRACTION,
    each just above the estimated rest level of the grains below it (BULK_FRACTION),
    inserted LAYER_TIME apart. Returns (LIGGGHTS lines, top of the last layer)."""
    return gc.layered_fill.cylinder(grains, P.mean_grain_volume(), P.D_SILO, P.D_OUTLET, h,
                                    P.D_SILO / 2 - max(radii) - 0.001, P.INSERT_FRACTION, P.LAYER_HEIGHT,
                                    P.BULK_FRACTION, P.LAYER_GAP, seed, steps)


def read_state(run):
    """The run's progress: the fill (post/fill.json) and the discharge chunks (log/discharge.json,
    gc.chunks); None before the fill is done."""
    path, old = os.path.join(run, "post", "fill.json"), os.path.join(run, "post", "state.json")
    if not os.path.exists(path):        # a run of the study before gc.chunks kept its state whole
        return json.load(open(old)) if os.path.exists(old) else None
    with open(path) as fh:
        fill = json.load(fh)
    chunks = gc.chunks.record(run, "discharge")["chunks"]
    last = chunks[-1] if chunks else dict(step=0, ndis=0)
    return dict(fill, step=last["step"], ndis=last["ndis"], chunk=len(chunks),
                cpu_discharge_s=sum(c["cpu_s"] for c in chunks), wall_s=fill["wall_s"] + sum(c["wall_s"] for c in chunks),
                orphans=sum(c["orphans"] for c in chunks), orphans_kg=sum(c["orphans_kg"] for c in chunks))


def setup(run, v, fresh):
    """The run folder from the template. A run that has started (its fill is done)
    is kept, and must have been set up with the same numbers."""
    saved = os.path.join(run, "numbers.json")
    if os.path.exists(saved) and read_state(run) is not None and not fresh:
        return gc.template.check_values(saved, v, "run with --fresh to start it again, or give another --out")
    gc.runner.clean(run)
    gc.template.render(os.path.join(HERE, "template"), run, v)
    geometry.write(os.path.join(run, "dem"), v["ANGLE"], v["HALF"], v["Z_HI"] - 0.001)
    os.makedirs(os.path.join(run, "post"))
    gc.template.save_values(saved, v)


def simulate(name, run, v, out, fresh):
    """The folder (setup), the fill (if not done) and the discharge chunks still to run;
    post-processes the run."""
    setup(run, v, fresh)

    def fill():
        for f in os.listdir(os.path.join(run, "post")):
            os.remove(os.path.join(run, "post", f))
        shutil.rmtree(os.path.join(run, "restart"), ignore_errors=True)     # and the chunks of an earlier fill
        gc.runner.clean(os.path.join(run, "log"))
        cpu = gc.runner.liggghts(run, "dem/in.fill", "fill", "log/log.fill", screen=False)   # the screen in log/fill.log
        settled = gc.dem.fill_report(os.path.join(run, "log", "log.fill"), "granair fill: settled")
        print(f"corn-silo {name}: {settled} ({cpu:.0f} s CPU)", flush=True)
        return dict(cpu_fill_s=cpu)
    if read_state(run) is None:
        gc.study.once(os.path.join(run, "post", "fill.json"), fill)
    total, chunk, upto = v["DISCHARGE_STEPS"], v["DISCHARGE_CHUNK_STEPS"], {}

    def segment(k, rec):
        """Chunk k's variables: to the next multiple of the chunk, the counts of the chunks before."""
        s = read_state(run)
        if s["step"] >= total:
            return None
        if not os.path.exists(os.path.join(run, "post", "fill.json")):
            raise gc.CaseError(f"{run}: an unfinished run of an older study.py (post/state.json); run with --fresh")
        for f in ("walls_*.vtk", "full_*.dump", "pairs_*.dump"):     # what a stopped chunk left beyond the restart
            for step, path in gc.dem.numbered(os.path.join(run, "post", f)):
                if step > s["step"]:
                    os.remove(path)
        upto[k] = min(total, (s["step"] // chunk + 1) * chunk)
        return dict(upto=upto[k], chunk=f"{k:03d}", ndis0=s["ndis"],
                    nrem0=s["orphans"], mrem0=repr(s["orphans_kg"]))

    def collect(case, k):
        flow = post.read_flow([os.path.join(case, "post", f"flow_{k:03d}.txt")])
        if not len(flow["step"]):
            raise gc.CaseError(f"{case}/post/flow_{k:03d}.txt: no rows (did the chunk run?)")
        flow = {c: x[-1] for c, x in flow.items()}
        with open(os.path.join(case, "post", f"orphans_{k:03d}.txt")) as fh:
            n, m = fh.read().split()[:2]
        print(f"corn-silo {name}: t = {upto[k] * v['DT']:.2f} of {v['DISCHARGE_S']:.2f} s, "
              f"{int(flow['discharged'])} grains discharged", flush=True)
        return dict(step=upto[k], ndis=int(flow["discharged"]), orphans=int(float(n)), orphans_kg=float(m))
    gc.chunks.liggghts(run, "dem/in.liggghts", segment, "post/fill.restart", "discharge", f"corn-silo {name}", collect)
    return post.run(name, run, v, read_state(run), out)


def finished(name, run, v, out):
    """--post-only: post-process the run if it is finished (else None)."""
    state = read_state(run)
    return post.run(name, run, v, state, out) if state and state["step"] >= v["DISCHARGE_STEPS"] else None


def main():
    ap = gc.cli.parser(__doc__, out_help="results (default: results/, results-demo/ or results-test/ by --size)")
    ap.add_argument("--size", choices=sorted(P.SIZES), default="study",
                    help="study: 8000 grains, 0.75 s, 6 angles x 3 runs; full: 25 000 grains, 3 s, 6 angles x 3 runs; "
                         "demo: 8000 grains, 1 s, 10 and 35 deg; test: 8000 grains, 0.2 s, 27 deg")
    ap.add_argument("--angles", type=float, nargs="+", help="hopper angles [deg from the horizontal] (default: the size's)")
    ap.add_argument("--seeds", type=int, help=f"runs per angle, 1-{len(P.SEEDS)} (default: the size's)")
    ap.add_argument("--youngs", type=float, default=P.YOUNGS, help=f"corn Young's modulus [Pa] (default {P.YOUNGS:g})")
    ap.add_argument("--discharge", type=float, help="discharge time [s] (default: the size's)")
    gc.study.options(ap, fresh=True)
    size = P.SIZES[ap.parse_known_args()[0].size]
    a = gc.study.parse(ap, os.path.join(HERE, OUTS[ap.parse_known_args()[0].size]))
    angles = [int(x) if float(x).is_integer() else x for x in (a.angles or size["angles"])]
    seeds = a.seeds or size["seeds"]
    discharge = a.discharge or size["discharge"]
    bad = [x for x in angles if not 0 < x < 90]
    if bad or not 1 <= seeds <= len(P.SEEDS) or not a.youngs > 0 or not discharge > 0:
        ap.error(f"--angles {bad or angles} (0-90 deg), --seeds {seeds} (1-{len(P.SEEDS)}), "
                 f"--youngs {a.youngs} (> 0), --discharge {discharge} (> 0)")
    print(f"corn-silo: {size['grains']} grains, {discharge:g} s of discharge, angles {', '.join(map(str, angles))} deg, "
          f"{seeds} run(s) each, E = {a.youngs:.3g} Pa, {a.jobs} at a time, results in {a.out}", flush=True)
    runs = []
    for k in range(seeds):          # seed-major: a study stopped early still has every angle
        for angle in angles:
            name = f"a{angle}-s{k + 1}"
            v = numbers(size["grains"], discharge, angle, k, a.youngs)
            run = os.path.join(a.out, "runs", name)
            runs.append((name, partial(setup, run, v, a.fresh), partial(simulate, name, run, v, a.out, a.fresh),
                         partial(finished, name, run, v, a.out)))
    done = gc.study.drive(a, "corn-silo", [], runs)
    if done is None:
        return
    c = gc.checks.Checks(f"corn-silo {os.path.basename(a.out)}")
    post.study(a.out, {n: r for n, r in done.items() if r}, angles, seeds, size, c)
    c.report(enforce=a.check)


if __name__ == "__main__":
    shutil.which("liggghts") or print("corn-silo: liggghts not on PATH (install-deps.sh installs it)")
    gc.cli.main(main)
