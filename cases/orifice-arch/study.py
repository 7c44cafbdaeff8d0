#!/usr/bin/python3
"""Flow through an orifice and the free-fall arch (reference case E, README.md).

    study.py [--size test|demo|study] [--variant silo slab] [--R R ...] [--out DIR] [--jobs 2]
             [--stage all|dem|post] [--keep-dumps] [--setup-only] [--check]

Two geometries (--variant): `silo`, the 3-D flat-bottomed cylindrical silo with
a circular outlet of radius R, and `slab`, the quasi-2-D monolayer between two
plates with a slit |x| < R. For each: one fill, a loose random packing settled
on the closed floor (LIGGGHTS, template/dem/in.fill), then one discharge run
per outlet radius R of the size (--R: some of them) from that restart, with
the particles that leave through the sink re-inserted at the top
(template/dem/in.liggghts). A run goes in segments of the size's `segment` t_d, each ending
with a restart: a stopped study resumes where it stopped (finished fills, segments,
CG fields and runs are skipped). Fills and runs are serial LIGGGHTS jobs,
--jobs of them at a time (default 2).

Per run: counts every PRINT_EVERY t_d (present, re-inserted, removed, below
the floor), the flow rate dN/dt against t / t_d and its steady value over the
averaging window, Beverloo; for the outlets of the size's `cg` list, CG fields
over the averaging window (fields.py: granairCG, profiles, maps, the free-fall
arch z_c(r) and its paraboloid fit).

Outputs in OUT (default: results/ for the study size, run/ for demo):
flow_rate.png, flow_rate_slab.png, beverloo.csv, <variant>_R<R>.csv (counts) and
.flow.csv (1 t_d means), <silo run>.level.json (./granair compare), fields/
(fields.py), summary.txt; the run folders in OUT/runs.

Checked (--check exits 1 on a failure): at every count the accounting closes
exactly (packed + re-inserted = present + removed; present = in the silo +
below the floor), and at the end inserted = in silo + below the floor +
removed; CG: every stress finite, the density integrated over a window
enclosing every particle equals their mass within MASS_INTEGRAL_TOL.
"""
import math
import os
import random
import time
from functools import partial

import numpy as np

import granair_cases as gc
import parameters as P
import fields

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
VARIANTS = ("silo", "slab")


# ------------------------------------------------------------------ numbers
def law():
    """The contact law's template values and the DEM step (parameters.contact_law)."""
    cl = P.contact_law()
    return dict(KN=P.K_N, KT=P.KT_OVER_KN * P.K_N, GAMMAN_PP=cl["gamman_pp"], GAMMAN_PW=cl["gamman_pw"],
                GAMMAT_PP=P.KT_OVER_KN * cl["gamman_pp"], GAMMAT_PW=P.KT_OVER_KN * cl["gamman_pw"],
                DT=cl["dt"], T_CONTACT=cl["t_contact_pp"])


def steps(size):
    """Step counts of a size (gc.discharge_counts.steps): between counts, CG snapshots, segments;
    the start of the averaging window and the run's end."""
    c = P.SIZES[size]
    return gc.discharge_counts.steps(law()["DT"], P.T_D, P.PRINT_EVERY, c["snapshot"], c["segment"], c["transient"],
                                     c["average"])


def geometry(size, variant):
    """The geometry of a size's silo or monolayer [m], its fill and its box."""
    c, d = P.SIZES[size][variant], P.D
    v_p = math.pi / 6 * d ** 3
    g = dict(variant=variant, d=d, h=c["h"] * d, z_sink=-P.SINK_DEPTH * d)
    if variant == "silo":
        r_s = c["R_s"] * d
        g.update(R_s=r_s, n=round(P.PACKING_SETTLED * math.pi * r_s ** 2 * g["h"] / v_p), half_x=r_s + 2 * d,
                 half_y=r_s + 2 * d)
        g["loose_top"] = g["n"] * v_p / (P.PACKING_INSERT * math.pi * r_s ** 2)
    else:
        w = c["width"] * d
        g.update(width=w, half_gap=P.GAP_2D * d / 2, n=round(P.PACKING_SETTLED_2D * w * g["h"] / (math.pi * d * d / 4)),
                 half_x=w / 2 + d, half_y=P.GAP_2D * d / 2 + d / 2)
        g["loose_top"] = g["n"] * math.pi * d * d / 4 / (P.PACKING_INSERT_2D * w)
    g["z_lo"] = g["z_sink"] - 2 * d
    g["z_hi"] = max(g["loose_top"] + 2 * d, g["h"] + (P.FEED_HEIGHT + 3) * d)
    return g


def values(size, variant, R_d=None):
    """Every template value of a fill (R_d None) or of the run with outlet radius R_d [d]."""
    g, st, d = geometry(size, variant), steps(size), P.D
    v = dict(gc.template.constants(P), **law())
    chunk = max(1, round(P.T_D / v["DT"]))
    settle = P.SIZES[size]["settle"]
    v.update(SKIN=P.SKIN * d, CHUNK=chunk, SETTLE_MIN=settle[0], SETTLE_MAX=settle[1],
             N_MIN=math.ceil(settle[0] * P.T_D / (chunk * v["DT"])), N_MAX=math.ceil(settle[1] * P.T_D / (chunk * v["DT"])),
             VRMS_SETTLED=P.SETTLE_VRMS * math.sqrt(P.G * d), Z_FEED_LO=g["h"], Z_FEED_HI=g["h"] + P.FEED_HEIGHT * d,
             Z_SINK=g["z_sink"], FEED_EVERY_STEPS=max(1, round(P.FEED_EVERY * P.T_D / v["DT"])),
             PRINT_EVERY_STEPS=st["print"], THERMO_EVERY=chunk, GRANAIR_ROOT=os.environ.get("GRANAIR_ROOT", ROOT))
    if variant == "silo":
        v.update(R_S=g["R_s"], R_S_D=g["R_s"] / d, R_FEED=g["R_s"] - 1e-3 * d, N_PHI=96, FEED_VZ="0.0")
    else:
        v.update(HALF_GAP=g["half_gap"], HALF_WIDTH=g["width"] / 2, WIDTH_D=g["width"] / d,
                 FEED_VZ=f"{-P.FEED_SPEED_2D * math.sqrt(P.G * d):.6g}")
    if R_d is not None:
        v.update(R_D=R_d, R=R_d * d)
    return v, g


# ---------------------------------------------------------------- geometry files
def packing(g, seed):
    """Random sequential addition of the fill at PACKING_INSERT: [(x, y, z, d)]."""
    d, gap = g["d"], 0.02 * g["d"]
    if g["variant"] == "silo":
        sample, inside = gc.packing_regions.cylinder(g["R_s"], gap)
    else:
        sample, inside = gc.packing_regions.box(g["width"] / 2, g["half_gap"], gap)
    return gc.dem.loose_packing([d] * g["n"], random.Random(seed), sample, inside, lambda t: t + d, g["loose_top"],
                                d * 1.0001, gap, origin=(-g["half_x"], -g["half_y"], 0.0))


def floor_stl(g, R):
    """The floor with the outlet: an annulus from R (an n-gon with the circle's area)
    to beyond the silo wall, or two strips beside the slit |x| < R across the gap."""
    d, quads = g["d"], []
    if g["variant"] == "silo":
        quads = gc.stl_walls.annulus(0.0, R, g["R_s"] + 1.5 * d, 96)
    else:
        y, x1 = g["half_gap"] + 0.25 * d, g["width"] / 2 + 0.5 * d
        pieces = max(1, math.ceil((x1 - R) / d))
        xs = [R + (x1 - R) * k / pieces for k in range(pieces + 1)]
        for a, b in zip(xs, xs[1:]):
            for s in (1, -1):
                quads.append([(s * a, -y, 0.0), (s * b, -y, 0.0), (s * b, y, 0.0), (s * a, y, 0.0)])
    return gc.dem.stl("bottom", quads)


def sink_stl(g):
    """The sink plane z = z_sink across the whole box, in tiles about 4 d wide."""
    hx, hy = g["half_x"] - 0.1 * g["d"], g["half_y"] - 0.1 * g["d"]
    nx, ny = max(1, math.ceil(2 * hx / (4 * g["d"]))), max(1, math.ceil(2 * hy / (4 * g["d"])))
    return gc.dem.stl("sink", gc.stl_walls.tiles(g["z_sink"], -hx, hx, -hy, hy, nx, ny))


def render(variant, dst, v, common, own):
    """Files of template/ (common to both geometries) and of template-<variant>/ into dst."""
    gc.template.render(os.path.join(HERE, "template"), dst, v, only=common)
    gc.template.render(os.path.join(HERE, f"template-{variant}"), dst, v, only=own)


# ------------------------------------------------------------------ stages
def fill_folder(a, variant, keep=False):
    """The fill's folder (--setup-only: keep, a finished fill is kept): the loose packing,
    the scripts. Returns (the particles packed, the packing's CPU seconds)."""
    v, g = values(a.size, variant)
    if keep and os.path.exists(os.path.join(a.out, "runs", variant, "fill", "dem", "fill.restart")):
        return None
    case = gc.runner.clean(os.path.join(a.out, "runs", variant, "fill"))
    c0 = time.process_time()
    atoms = packing(g, a.seed)
    top = max(z for _, _, z, _ in atoms) + g["d"]
    render(variant, case, v, ["dem/in.fill", "dem/in.materials", "dem/floor-closed.liggghts"], ["dem/geometry.liggghts"])
    gc.dem.write_data(os.path.join(case, "dem", "packing.data"), atoms,
                      (-g["half_x"], g["half_x"], -g["half_y"], g["half_y"], g["z_lo"], max(g["z_hi"], top)), P.RHO_P,
                      f"orifice-arch {variant} loose packing: {len(atoms)} spheres of d = {g['d']} m (study.py)")
    return len(atoms), time.process_time() - c0


def fill(a, variant):
    """The fill of a geometry, run once (gc.study.once: log/fill.json and the restart):
    its folder, the settling, the settled top and bulk density (summary.txt). Returns
    the summary's dict."""
    case = os.path.join(a.out, "runs", variant, "fill")
    summary = os.path.join(case, "summary.txt")

    def run():
        t0 = time.time()
        n, pack_cpu = fill_folder(a, variant)
        g = geometry(a.size, variant)
        print(f"orifice-arch {variant} fill: {n} particles packed ({pack_cpu:.0f} CPU-s), settling", flush=True)
        cpu = gc.runner.liggghts(case, "dem/in.fill", "fill")
        settled = gc.dem.fill_report(os.path.join(case, "log", "fill.liggghts"))
        dump = gc.dem.read_dump(os.path.join(case, "dem", "fill.dump"))
        area = math.pi * g["R_s"] ** 2 if variant == "silo" else g["width"] * 2 * g["half_gap"]
        rho_b, top = gc.outlet.bulk_density(dump["z"], dump["mass"], area, g["d"], k_top=200 if variant == "silo" else 20)
        keys = [("variant", variant), ("particles_packed", n), ("settled", settled), ("settled_top_m", top),
                ("settled_top_d", top / g["d"]), ("bulk_density_kg_m3", rho_b), ("solid_fraction", rho_b / P.RHO_P),
                ("packing_cpu_s", round(pack_cpu, 2)), ("fill_cpu_s", round(cpu, 2)), ("fill_wall_s", round(time.time() - t0))]
        gc.series.write_keys(summary, keys, f"orifice-arch {variant} fill (study.py); bulk density between 2 d and "
                             "2 d below the top (the monolayer: per unit volume of the gap)")
        print(f"orifice-arch {variant} fill: {settled}; bulk density {rho_b:.1f} kg/m3 (solid fraction "
              f"{rho_b / P.RHO_P:.3f}), {cpu:.0f} CPU-s", flush=True)
        return dict(gc.series.read_keys(summary), cpu_s=cpu)
    return gc.study.once(os.path.join(case, "log", "fill.json"), run, [os.path.join(case, "dem", "fill.restart")])[0]


def run_name(variant, R_d):
    return f"{variant}_R{R_d:g}"


def run_folder(a, variant, R_d):
    """The folder of one discharge run (--setup-only; a started run's restarts kept): the
    scripts and its walls."""
    v, g = values(a.size, variant, R_d)
    case = os.path.join(a.out, "runs", variant, f"R{R_d:g}")
    os.makedirs(os.path.join(case, "post"), exist_ok=True)
    render(variant, case, v, ["dem/in.liggghts", "dem/in.materials"], ["dem/geometry.liggghts", "dem/floor-open.liggghts"])
    gc.template.write(os.path.join(case, "dem", "bottom.stl"), floor_stl(g, v["R"]))
    gc.template.write(os.path.join(case, "dem", "sink.stl"), sink_stl(g))
    return case


def discharge(a, variant, R_d):
    """One discharge run: the segment chain (resumable), its counts, and CG fields if R_d is
    in the size's cg list. Returns dict(cpu_s: CPU used now, and the run's post-processing)."""
    v, g = values(a.size, variant, R_d)
    st = steps(a.size)
    name = run_name(variant, R_d)
    case = run_folder(a, variant, R_d)
    cg_on = R_d in P.SIZES[a.size][variant]["cg"]
    plan = gc.discharge_counts.plan(st["total"], st["seg"], st["snap"], st["avg_from"], cg_on)
    print(f"orifice-arch {name}: {len(plan)} segments of {st['seg']} steps ({st['seg'] * v['DT'] / P.T_D:.3g} t_d), "
          f"dt = {v['DT']:.4g} s, CG {'on' if cg_on else 'off'}", flush=True)
    rec = gc.chunks.liggghts(case, "dem/in.liggghts", plan, "../fill/dem/fill.restart", label=f"orifice-arch {name}")
    out = dict(cpu_s=sum(c["cpu_s"] for c in rec["chunks"][len(rec["chunks"]) - rec["ran"]:]))
    out.update(flow(a, variant, R_d, case))
    if cg_on:
        out["fields"] = fields.compute(a, variant, R_d, case, g, v["DT"], st, keep_dumps=a.keep_dumps)
        out["cpu_s"] += out["fields"]["cpu_s"]
    return out


# ------------------------------------------------------------------ flow rates
COUNTS = ("step", "atoms", "fed", "removed", "below")         # the columns of post/counts_<k>.txt


def beverloo_form(g):
    """(n, L) of W = C rho_b sqrt(g) L (D - k d)^n: the silo's circular orifice (5/2, 1), the
    monolayer's slit across the gap (Hagen-Beverloo: 3/2, the gap)."""
    return (2.5, 1.0) if g["variant"] == "silo" else (1.5, 2 * g["half_gap"])


def flow(a, variant, R_d, case):
    """Counts, accounting and flow rate of one run; writes OUT/<name>.csv, .flow.csv, .summary.txt."""
    v, g = values(a.size, variant, R_d)
    st = steps(a.size)
    name = run_name(variant, R_d)
    fill_keys = gc.series.read_keys(os.path.join(a.out, "runs", variant, "fill", "summary.txt"))
    packed = int(fill_keys["particles_packed"])
    c = gc.discharge_counts.read(case, math.ceil(st["total"] / st["seg"]), COUNTS)   # strays added to removed
    t = c["step"] * v["DT"]
    discharged = c["removed"] + c["below"]
    acc = gc.discharge_counts.accounting(c, packed)
    balance, last, in_silo = acc["balance"], acc["last"], acc["in_silo"]
    gc.series.write_csv(os.path.join(a.out, f"{name}.csv"),
                        [("t_over_td", t / P.T_D), ("t_s", t), ("present", c["atoms"]), ("reinserted", c["fed"]),
                         ("removed", c["removed"]), ("below_floor", c["below"]), ("discharged", discharged)],
                        fmt=["{:.6g}", "{:.6g}", "{:d}", "{:d}", "{:d}", "{:d}", "{:d}"])
    # dN/dt: means over windows of 1 t_d (the change of the discharged count over each)
    tw, rate = gc.discharge_counts.window_rates(t, discharged, max(1, round(P.T_D / (st["print"] * v["DT"]))))
    mass_flow = rate * P.MASS
    gc.series.write_csv(os.path.join(a.out, f"{name}.flow.csv"),
                        [("t", tw), ("t_over_td", tw / P.T_D), ("rate_per_s", rate), ("mass_flow_kg_s", mass_flow)],
                        fmt="{:.6g}")
    t0 = st["avg_from"] * v["DT"]
    steady, se = gc.discharge_counts.steady_rate(t, discharged, tw, rate, t0)
    rho_b = float(fill_keys["bulk_density_kg_m3"])
    n_exp, length = beverloo_form(g)
    lo, hi = gc.closed_forms.beverloo_band("circular" if variant == "silo" else "slot", 2 * v["R"], P.D, rho_b,
                                           P.K_RANGE, P.BEVERLOO_C, length if variant == "slab" else None)
    bev = {3.0: lo / P.MASS, 1.0: hi / P.MASS}       # particles per s at k = 3 and 1 (Beverloo; a slit: Hagen-Beverloo)
    w = steady * P.MASS
    k_fit = gc.discharge_counts.beverloo_k(w, 2 * v["R"], P.D, rho_b, P.BEVERLOO_C, n_exp, length, P.G)
    cpu, wall, nseg = gc.chunks.cost(case, "segment")
    keys = [("run", name), ("R_over_d", R_d), ("outlet_width_m", 2 * v["R"]), ("dt_s", v["DT"]), ("t_d_s", P.T_D),
            ("t_end_over_td", float(t[-1] / P.T_D)), ("average_from_over_td", t0 / P.T_D),
            ("steady_rate_per_s", steady), ("steady_rate_se_per_s", se), ("steady_rate_per_td", steady * P.T_D),
            ("steady_mass_flow_kg_s", w), ("bulk_density_kg_m3", rho_b),
            ("beverloo_k3_per_s", bev[3.0]), ("beverloo_k1_per_s", bev[1.0]), ("beverloo_k_at_C058", k_fit),
            ("packed", packed), ("reinserted", last["fed"]), ("inserted", acc["inserted"]), ("in_silo", in_silo),
            ("below_floor", last["below"]), ("removed_at_sink", last["removed"]),
            ("of_which_strays", last["stray"]),
            ("discharged", acc["discharged"]),
            ("balance_max_abs", int(np.max(np.abs(balance)))), ("counts", len(t)),
            ("segments", nseg), ("cpu_s", round(cpu, 1)), ("wall_s", round(wall)),
            ("particle_steps_per_cpu_s", float(np.mean(c["atoms"])) * c["step"][-1] / cpu if cpu else math.nan)]
    gc.series.write_keys(os.path.join(a.out, f"{name}.summary.txt"), keys,
                         f"orifice-arch {name} (study.py): counts of particles; inserted = packed + reinserted = "
                         "in_silo + below_floor + removed_at_sink; discharged = below_floor + removed_at_sink; of_which_strays: "
                         "particles a segment found below the sink plane at its start and deleted (template/dem/in.liggghts)")
    if variant == "silo":
        gc.levels.write(os.path.join(a.out, f"{name}.level.json"), case="orifice-arch", level="cg-dem",
                        model=f"DEM at the particle size (s = 1), LIGGGHTS linear spring-dashpot, k_n = {P.K_N:.3g} N/m, "
                              f"e_n = {P.RESTITUTION}, mu = {P.FRICTION_PP}, R = {R_d:g} d, silo R_s = "
                              f"{g['R_s'] / P.D:g} d, {a.size} size, re-inserted at the top, vacuum",
                        b_mm=round(2 * v["R"] * 1e3, 6), air=False, steady_mass_flow_kg_s=w,
                        steady_window_s=[t0, float(t[-1])], outlet_dpdz_Pa_m=None, wall_time_s=round(wall),
                        cores=1, timeseries=f"{name}.flow.csv", cpu_s=round(cpu, 1),
                        steady_rate_per_s=steady, steady_rate_se_per_s=se)
    print(f"orifice-arch {name}: dN/dt = {steady:.1f} +- {se:.1f} 1/s ({steady * P.T_D:.2f} per t_d) over t = "
          f"{t0 / P.T_D:g}-{t[-1] / P.T_D:.3g} t_d; Beverloo {bev[3.0]:.0f}-{bev[1.0]:.0f} 1/s (k = 3..1; k = "
          f"{k_fit:.2f} at C = 0.58); accounting {packed} + {last['fed']} = {in_silo} + {last['below']} + "
          f"{last['removed']} (largest imbalance {int(np.max(np.abs(balance)))}); {cpu:.0f} CPU-s", flush=True)
    return dict(name=name, summary=dict(keys), t=t, discharged=discharged, tw=tw, rate=rate, acc=acc,
                bev=bev, steady=steady, se=se)


def plot_flow(a, variant, results, path):
    plt = gc.plots.pyplot()
    fig, ax = plt.subplots(figsize=(7.5, 4.6))
    gc.profile_plots.rates(ax, [(f"R = {R_d:g} d: {r['steady'] * P.T_D:.1f} per t_d", r["tw"] / P.T_D, r["rate"] * P.T_D,
                                 (r["bev"][3.0] * P.T_D, r["bev"][1.0] * P.T_D)) for R_d, r in sorted(results.items())],
                           steps(a.size)["avg_from"] * law()["DT"] / P.T_D)
    what = "3-D silo, circular outlet" if variant == "silo" else f"monolayer (gap {P.GAP_2D:g} d), slit 2R"
    ax.set(xlabel="t / t_d", ylabel="dN/dt  [particles per t_d]",
           title=f"orifice-arch, {what}, {a.size} size: flow rate (1 t_d means); bands: Beverloo k = 3..1, C = 0.58")
    ax.title.set_fontsize(9)
    ax.legend(fontsize=8, loc="upper right")
    ax.grid(alpha=0.3)
    fig.tight_layout()
    gc.plots.save(fig, path)


# ------------------------------------------------------------------ driver
def check_run(c, r, variant):
    s = r["summary"]
    if variant == "silo":
        c.within(f"{r['name']}: steady dN/dt in the Beverloo band k = 3..1 (C = 0.58) [1/s]", s["steady_rate_per_s"],
                 r["bev"][3.0], r["bev"][1.0], "Beverloo (1961) for a circular orifice, the fill's bulk density; "
                 "the monolayer's slit is reported only (Hagen-Beverloo has no established C, k for one layer)")
    gc.discharge_counts.check_accounting(c, r["name"], r["acc"])


def main():
    ap = gc.cli.parser(__doc__, out_help="results (default: results/ for the study size, run/ for demo; test: required)")
    ap.add_argument("--size", choices=list(P.SIZES), default="study")
    ap.add_argument("--variant", nargs="+", choices=VARIANTS, default=list(VARIANTS))
    ap.add_argument("--R", type=float, nargs="+", default=None, help="outlet radii [d] (default: the size's)")
    ap.add_argument("--stage", choices=("all", "dem", "post"), default="all",
                    help="dem: fills and runs only; post: only the study's tables and plots from finished runs")
    ap.add_argument("--keep-dumps", action="store_true", help="keep the CG dumps after the fields are made")
    ap.add_argument("--seed", type=int, default=1)
    gc.study.options(ap, post_only=False)
    a = gc.study.parse(ap, lambda o: ap.error(f"--size {o.size} needs --out") if o.size in ("test", "full")
                       else os.path.join(HERE, "results" if o.size == "study" else "run"))
    t_start, a.post_only = time.time(), a.stage == "post"
    wanted = {var: [r for r in P.SIZES[a.size][var]["R"] if a.R is None or r in a.R] for var in a.variant}
    for var, rs in wanted.items():
        if a.R is not None and not rs:
            ap.error(f"--R {a.R}: none of the {var} outlets {P.SIZES[a.size][var]['R']} of size {a.size}")
    print(f"orifice-arch: size {a.size}, {', '.join(f'{k} R = {v}' for k, v in wanted.items())} d; out {a.out}",
          flush=True)
    fills = [(f"{var} fill", partial(fill_folder, a, var, True), partial(fill, a, var)) for var in wanted]
    runs = [(run_name(var, R_d), partial(run_folder, a, var, R_d), partial(discharge, a, var, R_d))
            for var, rs in wanted.items() for R_d in rs]
    if gc.study.drive(a, "orifice-arch", fills, runs) is None:
        return
    if a.stage == "dem":
        return print(f"orifice-arch: DEM stage done ({time.time() - t_start:.0f} s)")
    return post(a, wanted)


def post(a, wanted):
    """The study's tables, plots and checks from the finished runs."""
    c = gc.checks.Checks(f"orifice-arch {a.size}")
    keys, bev_rows = [], []
    for var, rs in wanted.items():
        results = {}
        for R_d in rs:
            case = os.path.join(a.out, "runs", var, f"R{R_d:g}")
            results[R_d] = r = flow(a, var, R_d, case)
            check_run(c, r, var)
            if R_d in P.SIZES[a.size][var]["cg"]:
                fields.check(c, a, var, R_d)
        plot_flow(a, var, results, os.path.join(a.out, "flow_rate.png" if var == "silo" else "flow_rate_slab.png"))
        n_exp, length = beverloo_form(geometry(a.size, var))
        C, k = gc.outlet.beverloo_fit([2 * R_d * P.D for R_d in sorted(results)],
                                      [results[R_d]["steady"] * P.MASS for R_d in sorted(results)],
                                      float(np.mean([r["summary"]["bulk_density_kg_m3"] for _, r in sorted(results.items())])),
                                      P.D, n_exp, length, P.G)
        for R_d, r in sorted(results.items()):
            s = r["summary"]
            bev_rows.append(dict(variant=var, R_over_d=R_d, rate_per_td=s["steady_rate_per_td"],
                                 rate_se_per_td=s["steady_rate_se_per_s"] * P.T_D,
                                 beverloo_k3_per_td=s["beverloo_k3_per_s"] * P.T_D,
                                 beverloo_k1_per_td=s["beverloo_k1_per_s"] * P.T_D, k_at_C058=s["beverloo_k_at_C058"],
                                 fit_C=C, fit_k=k, cpu_s=s["cpu_s"]))
        keys += [(f"{var}_beverloo_fit_C", C), (f"{var}_beverloo_fit_k", k)]
    gc.series.write_rows(os.path.join(a.out, "beverloo.csv"), bev_rows, fmt="{:.6g}")
    arch = fields.summarise(a, wanted)
    keys += arch
    gc.series.write_keys(os.path.join(a.out, "summary.txt"), keys, f"orifice-arch {a.size} (study.py)")
    c.report(enforce=a.check)


if __name__ == "__main__":
    gc.cli.main(main)
