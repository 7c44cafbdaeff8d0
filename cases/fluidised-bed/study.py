#!/usr/bin/python3
"""Fluidised bed: glass beads in a periodic air column, the superficial
velocity stepped down through minimum fluidisation (README.md).

    study.py [--out DIR] [--np N] [--check] [--quick] [--voidfraction MODEL] [--bed FILE]
    study.py --rank-independence [--out DIR] [--check]

Full sweep: fill and settle the bed (LIGGGHTS, 1 rank), the coupled run, then
every stage averaged over its window (from SETTLE after its start, or over
its last half if shorter). Writes OUT/fluidised_bed.csv and .png. Checked:
  1. packed stages, inside the bed (planes low-high): dp within 10 % of Ergun
     (1952) at the void fraction counted between the planes;
  2. packed stages, whole bed (distributor plane to outlet): dp within 15 % of
     Ergun at the bed's mean void fraction and height H = 2 z_cm;
  3. fluidised stages: the plateau (their mean dp, less the change of the
     bed's momentum over each window, m dv_cm / (A T)) within 3 % of the
     buoyant weight per area m g (1 - rho_f/rho_p) / A;
  4. U_mf, where the packed-bed line (a U + b U^2 fitted to the packed
     stages) meets the plateau, within 15 % of Wen & Yu (1966);
  and no bead lost.
--quick: the settled bed at 0.5 U_mf, then fluidised at 1.5 U_mf (OUT/quick.csv);
checked: the bed's centre of mass moves < 2 % while packed, no bead lost.
--rank-independence: --quick on 1 and on 2 ranks from the same settled bed
(`centre` void fraction), compared: the same bead count at every step; packed,
the bed pressure drop at every step to 1e-6 relative; fluidised, the mean
bed pressure drop within 5 % of the buoyant weight per area.
"""
import math
import os
import shutil
import time

import granair_cases as gc
import parameters as P

HERE = os.path.dirname(os.path.abspath(__file__))


def schedule(stages):
    """Rows (stage, role, u, start, end, avg_start) and inlet table points (t, u)."""
    u_wy = P.wen_yu_umf()
    rows, points, t = [], [(0.0, 0.0)], 0.0
    for k, (f, dur, role) in enumerate(stages):
        u, start, end = f * u_wy, t, t + dur
        if role == "ramp-up":
            points.append((end, u))
        else:
            if k > 0 or start > 0:
                points.append((start + P.RAMP, u))
            else:
                points[0] = (0.0, u)
            points.append((end, u))
        rows.append(dict(stage=k, role=role, U_s_m_s=u, start_s=start, end_s=end,
                         avg_start_s=start + min(P.SETTLE, 0.5 * dur)))
        t = end
    if abs(round(t / P.DT) * P.DT - t) > 1e-9:
        raise gc.CaseError(f"end time {t} s of the stages is not a whole number of CFD steps ({P.DT} s)")
    return rows, points


def run(out, np, quick, vf, bed, setup_only=False):
    """Write OUT/run from the template, fill (or copy the settled bed), run; returns the run folder."""
    run_dir = os.path.join(out, "run")
    shutil.rmtree(run_dir, ignore_errors=True)
    stages, points = schedule(P.QUICK if quick else P.FULL)
    gc.template.render(os.path.join(HERE, "template"), run_dir, dict(
        VOID_FRACTION=vf, END_TIME=f"{stages[-1]['end_s']:.6f}",
        INLET_TABLE="\n".join(f"            ({t:.6f} (0 0 {u:.8f}))" for t, u in points)))
    os.makedirs(os.path.join(run_dir, "postProcessing"))
    gc.series.write_rows(os.path.join(run_dir, "stages.csv"), [dict(
        r, U_s_m_s=f"{r['U_s_m_s']:.8f}", start_s=f"{r['start_s']:.6f}", end_s=f"{r['end_s']:.6f}",
        avg_start_s=f"{r['avg_start_s']:.6f}") for r in stages])
    if setup_only:
        return run_dir
    if bed:
        shutil.copyfile(bed, os.path.join(run_dir, "dem", "bed.restart"))
    else:
        print("fluidised-bed: filling and settling the bed (LIGGGHTS, 1 rank)", flush=True)
        gc.runner.liggghts(run_dir, "dem/in.fill", "liggghts", "log/fill.liggghts", screen=False)
    gc.runner.mesh(run_dir, np)
    print(f"fluidised-bed: coupled run on {np} rank(s), log: {run_dir}/log/granairFoam.log", flush=True)
    gc.runner.run(["granairFoam"], run_dir, np=np)
    return run_dir


def read_run(run_dir):
    """Per coupling step: the time series (lists) with zcm and nbetween from bed.dat,
    the bed and inside pressure drops; and the stages."""
    cols = {k: v.tolist() for k, v in gc.series.read_csv(os.path.join(run_dir, "postProcessing", "timeSeries.csv")).items()}
    with open(os.path.join(run_dir, "postProcessing", "bed.dat")) as fh:
        bed = [[float(v) for v in line.split()] for line in fh if line.strip() and not line.startswith("#")]
    n = len(cols["t"])          # fix print writes every coupling step (100 DEM steps)
    if len(bed) < n:
        raise gc.CaseError(f"{run_dir}/postProcessing/bed.dat has {len(bed)} rows, timeSeries.csv {n}")
    bed = bed[-n:]
    for k in range(n):
        if abs(bed[k][0] - cols["t"][k]) > 1e-9:
            raise gc.CaseError(f"bed.dat time {bed[k][0]} != timeSeries time {cols['t'][k]}")
    cols["zcm"], cols["nbetween"] = [b[1] for b in bed], [b[2] for b in bed]
    cols["dp_bed"] = [p - q for p, q in zip(cols["bed_p_Pa"], cols["outlet_p_Pa"])]
    cols["dp_inside"] = [p - q for p, q in zip(cols["low_p_Pa"], cols["high_p_Pa"])]
    stages = [{k: (v if k == "role" else float(v)) for k, v in r.items()}
              for r in gc.series.read_table(os.path.join(run_dir, "stages.csv"))]
    return cols, stages


def mean_std(v):
    m = sum(v) / len(v)
    return m, math.sqrt(sum((x - m) ** 2 for x in v) / len(v))


def stage_stats(series, stage, n_particles):
    idx = [k for k, t in enumerate(series["t"]) if stage["avg_start_s"] < t <= stage["end_s"] + 1e-12]

    def get(c):
        return [series[c][k] for k in idx]
    dp, dp_sd = mean_std(get("dp_bed"))
    # Newton for the whole bed over the window [k0, k1]: the mean air force is
    # the buoyant weight, less what the distributor carries, plus the change of
    # the bed's momentum m (v1 - v0) / T (what a finite window of a slugging bed
    # adds; the plateau is taken without it). v_cm: central difference over +-2 steps.
    t, z = series["t"], series["zcm"]
    k0, k1 = idx[0] - 1, idx[-1]

    def v_cm(k):
        a, b = max(k - 2, 0), min(k + 2, len(t) - 1)
        return (z[b] - z[a]) / (t[b] - t[a])
    mass = n_particles * P.RHO_P * P.particle_volume()
    momentum = mass * (v_cm(k1) - v_cm(k0)) / ((t[k1] - t[k0]) * P.AREA)
    dp_in, zcm, nb = mean_std(get("dp_inside"))[0], mean_std(get("zcm"))[0], mean_std(get("nbetween"))[0]
    u, vp, height = stage["U_s_m_s"], P.particle_volume(), 2.0 * zcm
    eps_bed = 1.0 - n_particles * vp / (P.AREA * height)
    eps_in = 1.0 - nb * vp / (P.AREA * (P.Z_HIGH - P.Z_LOW))
    return {"stage": int(stage["stage"]), "role": stage["role"], "U_s_m_s": u, "steps_averaged": len(idx),
            "dp_bed_Pa": dp, "dp_bed_std_Pa": dp_sd, "momentum_term_Pa": momentum, "dp_bed_steady_Pa": dp - momentum,
            "bed_height_m": height, "eps_bed": eps_bed, "ergun_bed_Pa": P.ergun_dp(u, eps_bed, height),
            "dp_inside_Pa": dp_in, "eps_inside": eps_in,
            "ergun_inside_Pa": P.ergun_dp(u, eps_in, P.Z_HIGH - P.Z_LOW)}


def fit_packed_line(points):
    """Least-squares a, b of dp = a U + b U^2 (the Ergun form) through the packed points."""
    s11, s12, s22 = (sum(u ** k for u, _ in points) for k in (2, 3, 4))
    r1, r2 = sum(u * p for u, p in points), sum(u ** 2 * p for u, p in points)
    det = s11 * s22 - s12 ** 2
    return (r1 * s22 - r2 * s12) / det, (s11 * r2 - s12 * r1) / det


def intersect(a, b, level):
    """U > 0 with a U + b U^2 = level."""
    if abs(b) < 1e-12 * abs(a):
        return level / a
    return (-a + math.sqrt(a * a + 4 * b * level)) / (2 * b)


def analyse_sweep(series, stages, out, c):
    n = int(series["particles"][-1])
    c.exact("beads at every step", sorted({int(p) for p in series["particles"]}), [n], "none lost or added")
    w, u_wy = P.buoyant_weight_per_area(n), P.wen_yu_umf()
    rows = [stage_stats(series, s, n) for s in stages]
    packed = [r for r in rows if r["role"] == "packed"]
    fluid = [r for r in rows if r["role"] == "fluidised"]
    plateau = sum(r["dp_bed_steady_Pa"] for r in fluid) / len(fluid)
    ab = fit_packed_line([(r["U_s_m_s"], r["dp_bed_Pa"]) for r in packed])
    u_mf = intersect(*ab, plateau)
    eps_mf = sum(r["eps_bed"] for r in packed) / len(packed)
    h_mf = sum(r["bed_height_m"] for r in packed) / len(packed)
    gc.series.write_rows(os.path.join(out, "fluidised_bed.csv"),
                         [dict(r, buoyant_weight_per_area_Pa=w) for r in rows], fmt="{:.6g}")
    plot(series, rows, w, u_wy, u_mf, ab, eps_mf, h_mf, os.path.join(out, "fluidised_bed.png"))
    print(f"beads {n}, buoyant weight per area W = {w:.2f} Pa, Wen-Yu U_mf = {u_wy:.4f} m/s")
    print(" stage role        U [m/s]  dp_bed [Pa] (std)  eps_bed  H [mm]  Ergun_bed  dp_in [Pa]  eps_in  Ergun_in")
    for r in rows:
        print(f" {r['stage']:5d} {r['role']:11s} {r['U_s_m_s']:.4f}  {r['dp_bed_Pa']:8.2f} ({r['dp_bed_std_Pa']:5.2f})"
              f"  {r['eps_bed']:.4f}  {1e3 * r['bed_height_m']:6.2f}  {r['ergun_bed_Pa']:8.2f}  {r['dp_inside_Pa']:8.2f}"
              f"  {r['eps_inside']:.4f} {r['ergun_inside_Pa']:8.2f}")
        if r["role"] == "packed":
            c.close(f"stage {r['stage']} ({r['U_s_m_s']:.3f} m/s): dp inside the bed vs Ergun", r["dp_inside_Pa"],
                    r["ergun_inside_Pa"], P.TOL_ERGUN_INSIDE, "the count of bead centres sets eps to about +-5 %")
            c.close(f"stage {r['stage']} ({r['U_s_m_s']:.3f} m/s): whole-bed dp vs Ergun at H = 2 z_cm",
                    r["dp_bed_Pa"], r["ergun_bed_Pa"], P.TOL_ERGUN_BED, "H from z_cm and the bed's two ends add to it")
    for r in fluid:
        print(f"fluidised stage {r['stage']}: mean dp {r['dp_bed_Pa']:.2f} Pa, bed momentum change "
              f"{r['momentum_term_Pa']:+.2f} Pa, without it {r['dp_bed_steady_Pa']:.2f} Pa")
    print(f"packed-bed fit dp = {ab[0]:.1f} U + {ab[1]:.1f} U^2; bed at U_mf: eps {eps_mf:.4f}, H {1e3 * h_mf:.2f} mm")
    c.close(f"plateau (mean of {len(fluid)} fluidised stages, momentum change removed) vs buoyant weight / area",
            plateau, w, P.TOL_PLATEAU, "the distributor carries ~1 % while beads rest on it")
    c.close("U_mf (packed-bed line meets the plateau) vs Wen & Yu (1966)", u_mf, u_wy, P.TOL_UMF,
            "+-0.01 in eps_mf is +-10 % in U_mf")


def analyse_quick(series, stages, out, c, tag=""):
    keys = ["t", "particles", "dp_bed", "dp_inside", "zcm"]
    gc.series.write_csv(os.path.join(out, "quick.csv"), [(k, series[c_]) for k, c_ in
                        zip(["t_s", "particles", "dp_bed_Pa", "dp_inside_Pa", "zcm_m"], keys)], fmt="{!r}")
    z = [zc for t, zc in zip(series["t"], series["zcm"]) if t <= stages[0]["end_s"] + 1e-12]
    c.within(f"{tag}largest move of the bed's centre of mass / its height, packed stage",
             max(abs(v - z[0]) for v in z) / z[0], 0.0, P.TOL_BED_AT_REST,
             "the soft bed springs back by ~0.4 % as the air lifts half its weight")
    c.exact(f"{tag}beads at every step", sorted(set(series["particles"])), [series["particles"][0]], "none lost or added")


def compare_ranks(a, b, stages, c):
    if a["t"] != b["t"]:
        raise gc.CaseError("the 1- and 2-rank runs have different coupling steps")
    c.exact("bead count at every step, 1 vs 2 ranks", a["particles"] == b["particles"], True,
            "no bead lost or duplicated by the decomposition")
    packed, fluid = stages[0], stages[-1]
    diff = [(abs(p - q) / abs(p), t) for t, p, q in zip(a["t"], a["dp_bed"], b["dp_bed"]) if t <= packed["end_s"] + 1e-12]
    worst = max(diff)
    c.within(f"packed stage: largest relative difference of the bed dp (t = {worst[1]:.4f} s)", worst[0], 0.0,
             P.TOL_RANKS_PACKED, "deterministic; round-off grows in the frictional contacts to ~5e-8")
    means = []
    for s in (a, b):
        v = [p for t, p in zip(s["t"], s["dp_bed"]) if fluid["avg_start_s"] < t <= fluid["end_s"] + 1e-12]
        means.append(sum(v) / len(v))
    w = P.buoyant_weight_per_area(int(a["particles"][-1]))
    c.near("fluidised stage: mean bed dp, 2 ranks - 1 rank, / W", (means[1] - means[0]) / w, 0.0,
           P.TOL_RANKS_FLUIDISED, "chaotic: only statistics compare; a lost or doubled force would be ~1/N of W per bead")


def plot(series, rows, w, u_wy, u_mf, ab, eps_mf, h_mf, path):
    plt = gc.plots.pyplot()
    fig, (ax, axt) = plt.subplots(1, 2, figsize=(12, 4.8))
    colours = {"fluidised": "tab:red", "transition": "tab:grey", "packed": "tab:blue"}
    for role in ("packed", "transition", "fluidised"):
        sel = [r for r in rows if r["role"] == role]
        if sel:
            ax.errorbar([r["U_s_m_s"] for r in sel], [r["dp_bed_Pa"] for r in sel], yerr=[r["dp_bed_std_Pa"] for r in sel],
                        fmt="o", color=colours[role], capsize=3, label=f"CFD-DEM, {role} stages (mean, std)")
    sel = [r for r in rows if r["role"] == "fluidised"]
    ax.plot([r["U_s_m_s"] for r in sel], [r["dp_bed_steady_Pa"] for r in sel], "s", mfc="none", color="tab:red",
            label="fluidised, bed momentum change removed")
    umax = 1.1 * max(r["U_s_m_s"] for r in rows)
    us = [umax * k / 200 for k in range(201)]
    ax.plot(us, [P.ergun_dp(u, eps_mf, h_mf) for u in us], "k--", label=f"Ergun, eps = {eps_mf:.3f}, H = {1e3 * h_mf:.1f} mm")
    uf = [u for u in us if u <= u_mf * 1.15]
    ax.plot(uf, [ab[0] * u + ab[1] * u * u for u in uf], "b:", label="packed-bed fit a U + b U$^2$")
    ax.axhline(w, color="tab:red", ls="-.", label=f"buoyant weight / area = {w:.1f} Pa")
    ax.axvline(u_wy, color="tab:green", ls="--", label=f"Wen & Yu U$_{{mf}}$ = {u_wy:.3f} m/s")
    ax.axvline(u_mf, color="tab:purple", ls=":", label=f"measured U$_{{mf}}$ = {u_mf:.3f} m/s")
    ax.set(xlim=(0, umax), ylim=(0, 1.6 * w), xlabel="superficial air velocity U [m/s]", ylabel="bed pressure drop [Pa]",
           title="Pressure drop vs velocity (stepped down from fluidised)")
    ax.legend(fontsize=7, loc="upper left")
    axt.plot(series["t"], series["dp_bed"], lw=0.8, color="k", label="bed pressure drop")
    axt.axhline(w, color="tab:red", ls="-.", lw=1)
    axt.set(xlabel="t [s]", ylabel="bed pressure drop [Pa]", ylim=(0, 2.0 * w), title="Time series")
    ax2 = axt.twinx()
    u_in = [m / (P.RHO_F * P.AREA) for m in series["inlet_air_kg_s"]]
    ax2.plot(series["t"], u_in, color="tab:green", lw=1, label="inlet U")
    ax2.set_ylabel("superficial velocity U [m/s]", color="tab:green")
    ax2.set_ylim(0, 1.1 * max(u_in))
    fig.tight_layout()
    gc.plots.save(fig, path)


def main():
    ap = gc.cli.parser(__doc__)
    ap.add_argument("--quick", action="store_true", help="the short run: packed, then fluidised")
    ap.add_argument("--voidfraction", default="divided", help="void-fraction model (default divided)")
    ap.add_argument("--bed", default=None, help="start from this settled-bed restart instead of filling")
    ap.add_argument("--rank-independence", action="store_true", help="--quick on 1 and 2 ranks, compared")
    a = gc.cli.parse(ap, os.path.join(HERE, "results"))
    t0 = time.time()
    c = gc.checks.Checks("fluidised-bed")
    if a.rank_independence:
        # centre: a bead's volume goes to the cell holding its centre whatever the
        # decomposition (divided counts satellite points beyond a processor
        # boundary in the centre cell, which would mask round-off-level agreement)
        runs = []
        for np_ in (1, 2):
            out = os.path.join(a.out, f"np{np_}")
            os.makedirs(out, exist_ok=True)
            bed = os.path.join(a.out, "np1", "run", "dem", "bed.restart") if np_ == 2 else None
            runs.append(read_run(run(out, np_, True, "centre", bed)))
            analyse_quick(*runs[-1], out, c, f"{np_} rank(s): ")
        compare_ranks(runs[0][0], runs[1][0], runs[0][1], c)
    else:
        run_dir = run(a.out, a.np, a.quick, a.voidfraction, a.bed, a.setup_only)
        if a.setup_only:
            return print(f"fluidised-bed: case written to {run_dir}")
        (analyse_quick if a.quick else analyse_sweep)(*read_run(run_dir), a.out, c)
    print(f"fluidised-bed: finished in {time.time() - t0:.0f} s")
    c.report(enforce=a.check)


if __name__ == "__main__":
    gc.cli.main(main)
