#!/usr/bin/python3
"""The study-size whole discharges of all three widths side by side, against the fill level
(README, "Study size over the whole discharge").

Reads only what reference-study-whole/ commits, one time series per run
(b<b>_<air|noair>.csv, written by `study.py --stage post`) and its level file
(b<b>_<run>.level.json: steady W and window), so it needs none of the run folders, which
are not kept; and the continuum mu(I) level from the same fills
(reference-continuum-study-whole/b<b>_<run>/, `Allrun-continuum --fills study
--until 0.99`), drawn beside the DEM and tabulated against it. For every run and every fill-level band of parameters.py WHOLE_BANDS_MM it
takes the rows whose fill level is in the band, from WHOLE_BANDS_FROM on (the 0.1 s
windows are not yet full before), and averages the mass flow (granairFoam's 0.1 s
window rate) and the 0.1 s trailing means of the outlet dp/dz and of the air pressure
about b above the orifice. The air effect in a band is W with air / W DEM only - 1 at
the same fill level.

Writes reference-study-whole/whole_bands.csv and whole_bands.md (the README's tables)
and whole_widths.png (mass flow against time, and mass flow, air effect, outlet dp/dz
against the fill level; the continuum dashed, its rate as a 0.1 s trailing mean).

    PYTHONPATH=tools python3 cases/wedge-silo/whole_widths.py
"""
import os

import numpy as np

import granair_cases as gc
import parameters as P

HERE = os.path.dirname(os.path.abspath(__file__))
RES = os.path.join(HERE, "reference-study-whole")
CONTINUUM = os.path.join(HERE, "reference-continuum-study-whole")
TWO_FLUID = os.path.join(HERE, "reference-two-fluid-study-whole")
TWO_FLUID_CAL = os.path.join(HERE, "reference-two-fluid-calibrated")
# the calibrated law on 4 cells across the slot at every width (b/4: the b = 10 mm
# runs at the folder's top, b = 5 and 15 mm in their mesh folders)
TWO_FLUID_CAL_4 = {5: os.path.join(TWO_FLUID_CAL, "b5_mesh4"), 10: TWO_FLUID_CAL,
                   15: os.path.join(TWO_FLUID_CAL, "b15_mesh4")}
COLOURS = {5: "tab:blue", 10: "tab:orange", 15: "tab:green"}


def load(csv, level, mean_keys):
    """{(b, air): (series with the 0.1 s trailing means of mean_keys added, level file)}
    of the runs whose series csv(name) exists; name b<b>_<air|noair>, level(name) its level file."""
    out = {}
    for b in (5, 10, 15):
        for air in (True, False):
            name = f"b{b}_{'air' if air else 'noair'}"
            if not os.path.exists(csv(name)):
                continue
            s = gc.series.read_csv(csv(name))
            for k in mean_keys:
                if k in s:      # a dry run has no air pressure columns
                    s[k + "_mean"] = gc.series.trailing_mean(s["t"], s[k], 0.1)
            out[(b, air)] = (s, gc.levels.read(level(name)))
    return out


def runs():
    """The committed DEM runs (granairFoam's rate is already a 0.1 s window rate)."""
    return load(lambda n: os.path.join(RES, f"{n}.csv"), lambda n: os.path.join(RES, f"{n}.level.json"),
                ("outlet_dpdz_Pa_m", "above_p_Pa"))


def continuum_runs(folder=CONTINUUM):
    """The continuum runs (mu(I) or two-fluid) from the study fills in folder (or a
    folder per width {b: folder}): a rate per step or per 1 ms, so its 0.1 s trailing
    mean is drawn and averaged, as the DEM's."""
    where = (lambda n: folder[int(n[1:n.index("_")])]) if isinstance(folder, dict) else (lambda n: folder)
    return load(lambda n: os.path.join(where(n), n, "timeseries.csv"), lambda n: os.path.join(where(n), n, "level.json"),
                ("mass_flow_kg_s", "outlet_dpdz_Pa_m"))


def band_rows(by, rate="mass_flow_kg_s"):
    """One row per width and band that both runs of the width reach (or the one run);
    rate: the series' 0.1 s rate column."""
    rows = []
    for b in sorted({b for b, _ in by}):
        for lo, hi in P.WHOLE_BANDS_MM:
            row = {"b_mm": b, "fill_from_mm": lo, "fill_to_mm": hi}
            for air in (True, False):
                if (b, air) not in by:
                    continue
                s, _ = by[(b, air)]
                h = s["fill_level_m"] * 1e3
                sel = (h >= lo) & (h <= hi) & (s["t"] >= P.WHOLE_BANDS_FROM)
                if not sel.any():
                    continue
                tag = "air" if air else "noair"
                row[f"W_{tag}_kg_s"] = float(np.mean(s[rate][sel]))
                row[f"duration_{tag}_s"] = float(np.sum(gc.series.step_lengths(s["t"])[sel]))
                if air:
                    row["outlet_dpdz_Pa_m"] = float(np.mean(s["outlet_dpdz_Pa_m_mean"][sel]))
                    if "above_p_Pa_mean" in s:      # the DEM-CFD runs' probe about b above
                        row["above_p_Pa"] = float(np.mean(s["above_p_Pa_mean"][sel]))
            if "W_air_kg_s" in row and "W_noair_kg_s" in row:
                row["air_effect"] = row["W_air_kg_s"] / row["W_noair_kg_s"] - 1.0
            if len(row) > 3:
                rows.append(row)
    return rows


def markdown(by, rows, levels):
    f = lambda r, k, fmt: fmt.format(r[k]) if k in r else "–"   # noqa: E731
    w = lambda runs, b, air: runs[(b, air)][1]["steady_mass_flow_kg_s"]   # noqa: E731
    lines = ["Steady (level files): W with air / DEM only, air effect", ""]
    lines += gc.tables.markdown(
        ["b [mm]", "W with air [kg/s]", "W DEM only [kg/s]", "air effect", "outlet dp/dz [Pa/m]"],
        [[b, f"{w(by, b, True):.4g}" if (b, True) in by else "–", f"{w(by, b, False):.4g}" if (b, False) in by else "–",
          f"{w(by, b, True) / w(by, b, False) - 1:+.1%}" if (b, True) in by and (b, False) in by else "–",
          f"{by[(b, True)][1]['outlet_dpdz_Pa_m']:.0f}" if (b, True) in by else "–"]
         for b in sorted({b for b, _ in by})])
    for title, cont in levels:
        both = [b for b in (5, 10, 15) if all(k in by and k in cont for k in ((b, True), (b, False)))]
        if not both:
            continue
        lines += ["", f"{title.replace(' (', ' from the same fills (')} against the DEM", ""]
        lines += gc.tables.markdown(
            ["b [mm]", "W with air [kg/s]", "W dry [kg/s]", "air effect", "outlet dp/dz [Pa/m]",
             "W / DEM, air / dry", "dp/dz / DEM-CFD's", "air effect, DEM-CFD"],
            [[b, f"{w(cont, b, True):.4g}", f"{w(cont, b, False):.4g}", f"{w(cont, b, True) / w(cont, b, False) - 1:+.1%}",
              f"{cont[(b, True)][1]['outlet_dpdz_Pa_m']:.0f}",
              f"{w(cont, b, True) / w(by, b, True):.2f} / {w(cont, b, False) / w(by, b, False):.2f}",
              f"{cont[(b, True)][1]['outlet_dpdz_Pa_m'] / by[(b, True)][1]['outlet_dpdz_Pa_m']:.2f}",
              f"{w(by, b, True) / w(by, b, False) - 1:+.1%}"] for b in both])
    lines += ["", f"Fill-level bands (rows from t = {P.WHOLE_BANDS_FROM} s, 0.1 s means)", ""]
    lines += gc.tables.markdown(
        ["b [mm]", "fill level [mm]", "W with air [kg/s]", "W DEM only [kg/s]", "air effect",
         "outlet dp/dz [Pa/m]", "p about b above [Pa]"],
        [[r["b_mm"], f"{r['fill_from_mm']}–{r['fill_to_mm']}", f(r, "W_air_kg_s", "{:.4f}"),
          f(r, "W_noair_kg_s", "{:.4f}"), f(r, "air_effect", "{:+.0%}"), f(r, "outlet_dpdz_Pa_m", "{:.0f}"),
          f(r, "above_p_Pa", "{:.1f}")] for r in rows])
    return lines


def level_bands(rows, levels):
    """The continuum levels' fill-level bands beside DEM-CFD's (rows: band_rows of the DEM):
    one row per level, width and band that both have; and its markdown lines."""
    dem = {(r["b_mm"], r["fill_from_mm"]): r for r in rows}
    out = []
    for title, cont in levels:
        for r in band_rows(cont, "mass_flow_kg_s_mean"):
            d = dem.get((r["b_mm"], r["fill_from_mm"]))
            if d is None or "air_effect" not in r or "air_effect" not in d:
                continue
            out.append(dict(level=title.split(" (")[0], **r, dem_air_effect=d["air_effect"], dem_outlet_dpdz_Pa_m=d["outlet_dpdz_Pa_m"]))
    lines = ["", "Continuum levels by fill-level band against DEM-CFD's (the same bands and means; "
             "air effect: each level's own W with air / dry - 1 at the same fill level)", ""]
    lines += gc.tables.markdown(
        ["level", "b [mm]", "fill level [mm]", "W with air [kg/s]", "W dry [kg/s]", "air effect",
         "air effect DEM-CFD", "difference [points]", "outlet dp/dz [Pa/m]", "dp/dz / DEM-CFD's"],
        [[r["level"], r["b_mm"], f"{r['fill_from_mm']}–{r['fill_to_mm']}", f"{r['W_air_kg_s']:.4f}",
          f"{r['W_noair_kg_s']:.4f}", f"{r['air_effect']:+.1%}", f"{r['dem_air_effect']:+.1%}",
          f"{100 * (r['air_effect'] - r['dem_air_effect']):+.1f}", f"{r['outlet_dpdz_Pa_m']:.0f}",
          f"{r['outlet_dpdz_Pa_m'] / r['dem_outlet_dpdz_Pa_m']:.2f}"] for r in out])
    return out, lines


def plot_levels(by, levels, path):
    """One column per width: W, the air effect and the outlet dp/dz against the fill level,
    DEM-CFD and every continuum level (the DEM solid, the others dashed and dotted)."""
    plt = gc.plots.pyplot()
    widths = sorted({b for b, _ in by})
    fig, axes = plt.subplots(3, len(widths), figsize=(5 * len(widths), 10), squeeze=False)
    styles = [("DEM-CFD", "-", 1.4)] + [(t.split(" (")[0], ls, 1.0) for (t, _), ls in zip(levels, ("--", ":", "-.", (0, (6, 1, 1, 1, 1, 1))))]
    for (title, ls, lw), runs in zip(styles, [by] + [c for _, c in levels]):
        rate = "mass_flow_kg_s" if runs is by else "mass_flow_kg_s_mean"
        for j, b in enumerate(widths):
            for air, colour in ((True, "tab:red"), (False, "tab:blue")):
                if (b, air) not in runs:
                    continue
                h, w, dpdz, effect = level_curves(runs, b, air, rate)
                kw = dict(ls=ls, lw=lw, color=colour)
                axes[0, j].plot(h, w, label=f"{title}, {'with air' if air else 'dry'}", **kw)
                if air:
                    axes[2, j].plot(h, dpdz, label=title, **dict(kw, color="k"))
                    if effect is not None:
                        axes[1, j].plot(h, effect, label=title, **dict(kw, color="k"))
    for j, b in enumerate(widths):
        for i, y in enumerate(["mass flow, full 60 mm depth [kg/s]", "air effect at the same fill level [%]",
                               "outlet air dp/dz [Pa/m] (0.1 s mean)"]):
            ax = axes[i, j]
            ax.set(xlabel="fill level [mm] (falls as the silo empties)", ylabel=y)
            ax.grid(alpha=0.3)
            ax.legend(fontsize=6)
        axes[0, j].set_title(f"b = {b} mm")
        axes[1, j].set_ylim(-40, 5)
    fig.suptitle("Wedge silo, study fills, whole discharges: DEM-CFD and the continuum levels", fontsize=10)
    fig.tight_layout()
    gc.plots.save(fig, path)


def level_curves(runs, b, air, rate):
    """One run's curves against the fill level [mm], once the 0.1 s windows are full and
    while a bed is left: (h, its rate, and with air its outlet dp/dz and its air effect [%]
    against its own dry rate at the same fill level, which falls monotonically; None where
    there is no air or no dry run)."""
    s = runs[(b, air)][0]
    late = (s["t"] >= P.WHOLE_BANDS_FROM) & (s["fill_level_m"] > 1e-3)
    h, w = s["fill_level_m"][late] * 1e3, s[rate][late]
    if not air:
        return h, w, None, None
    effect = None
    if (b, False) in runs:
        s0 = runs[(b, False)][0]
        w0 = np.interp(h, s0["fill_level_m"][::-1] * 1e3, s0[rate][::-1], left=np.nan, right=np.nan)
        effect = 100 * (w / w0 - 1)
    return h, w, s["outlet_dpdz_Pa_m_mean"][late], effect


def draw(axes, runs, rate, style, label, tag):
    """One level's curves: its rate against time, and against the fill level what
    level_curves gives."""
    for (b, air), (s, _) in sorted(runs.items()):
        c, kw = COLOURS[b], style(b, air)
        axes[0, 0].plot(s["t"], s[rate], color=c, label=label(b, air), **kw)
        h, w, dpdz, effect = level_curves(runs, b, air, rate)
        axes[0, 1].plot(h, w, color=c, label=label(b, air), **kw)
        if air:
            axes[1, 1].plot(h, dpdz, color=c, label=f"b = {b} mm{tag}", **kw)
            if effect is not None:
                axes[1, 0].plot(h, effect, color=c, label=f"b = {b} mm{tag}", **kw)


def plot(by, cont, path):
    plt = gc.plots.pyplot()
    fig, axes = plt.subplots(2, 2, figsize=(12, 8.5))
    draw(axes, cont, "mass_flow_kg_s_mean", lambda b, air: dict(ls="--" if air else "-.", lw=0.9, alpha=0.8),
         lambda b, air: f"b = {b} mm, continuum mu(I), {'with air' if air else 'dry'}", ", continuum")
    draw(axes, by, "mass_flow_kg_s", lambda b, air: dict(ls="-" if air else ":", lw=1.4),
         lambda b, air: f"b = {b} mm, {'with air' if air else 'DEM only'}", "")
    titles = [("time since the shutter opened [s]", "mass flow, full 60 mm depth [kg/s]"),
              ("fill level [mm]", "mass flow, full 60 mm depth [kg/s]"),
              ("fill level [mm]", "air effect: W with air / W DEM only at that level - 1 [%]"),
              ("fill level [mm]", "outlet air dp/dz [Pa/m] (0.1 s mean)")]
    for ax, (x, y) in zip(axes.flat, titles):
        ax.set(xlabel=x, ylabel=y)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=6, ncol=2 if ax in axes[0] else 1)
    for ax in axes.flat[1:]:
        ax.set_xlabel("fill level: bed height above the orifice [mm] (falls as the silo empties)")
    axes[0, 0].set_ylim(0, 0.5)     # room for the legends above the curves
    axes[0, 1].set_ylim(0, 0.5)
    axes[1, 0].set_ylim(-40, 5)
    fig.suptitle("Wedge silo, study size, whole discharges (reference-study-whole/)", fontsize=10)
    fig.tight_layout()
    gc.plots.save(fig, path)


def main():
    by = runs()
    if not by:
        raise gc.CaseError(f"{RES}: no b<b>_<air|noair>.csv (run study.py --size study --whole --stage post first)")
    rows, cont, tf = band_rows(by), continuum_runs(), continuum_runs(TWO_FLUID)
    levels = [("Continuum mu(I) (reference-continuum-study-whole/)", cont),
              ("Two-fluid (reference-two-fluid-study-whole/)", tf),
              ("Two-fluid, DEM-calibrated mu(I) (reference-two-fluid-calibrated/)", continuum_runs(TWO_FLUID_CAL)),
              ("Two-fluid, DEM-calibrated mu(I), 4 cells across (reference-two-fluid-calibrated/b5_mesh4, b10, "
               "b15_mesh4)", continuum_runs(TWO_FLUID_CAL_4))]
    gc.series.write_rows(os.path.join(RES, "whole_bands.csv"), rows, fmt="{:.6g}")
    lines = markdown(by, rows, levels)
    lb, more = level_bands(rows, levels)
    if lb:
        gc.series.write_rows(os.path.join(RES, "whole_bands_levels.csv"), lb, fmt="{:.6g}")
        lines += more
    # the two-fluid runs before gc.two_fluid.orifice_probes whose fields are gone
    lines += ["", "Outlet dp/dz: the mean over the orifice's faces (cells) for DEM-CFD, the continuum and the "
              "calibrated two-fluid runs; the literature two-fluid runs (reference-two-fluid-study-whole/, set up "
              "before 2026-12-07, their fields not kept) give their axis cell's, which the later runs' fields put at "
              "0.74-0.89x the orifice's mean on 3-10 cells across (docs/two-fluid-model.md)."]
    plot_levels(by, levels, os.path.join(RES, "whole_levels.png"))
    with open(os.path.join(RES, "whole_bands.md"), "w") as fh:
        fh.write("\n".join(lines) + "\n")
    plot(by, cont, os.path.join(RES, "whole_widths.png"))
    print("\n".join(lines))
    print(f"whole_widths: {RES}/whole_bands.csv, whole_bands.md, whole_widths.png")


if __name__ == "__main__":
    gc.cli.main(main)
