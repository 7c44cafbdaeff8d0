#!/usr/bin/python3
"""Cross-validation of the continuum with the DEM-calibrated mu(I) against the
coarse-grained DEM's CG fields, b = 10 mm, dry (README, "Cross-validation").

    xval.py [--run DIR] [--dem NAME] [--out DIR] [--dem-run DIR --dem-windows T0:T1 ...]

--run: the continuum run folder (continuum.py --rheology-from calibration
--dem-size demo --b 10 --air off --write-every 0.05; default
reference-continuum-calibrated-demo/runs/b10_noair); --dem: the DEM run's
stem in reference-demo/ (default b10_noair: its <stem>.csv, the discharge,
and <stem>_cg_axis.csv / _cg_orifice.csv, granairCG's fields on the centre
line x = 0 and on the orifice plane z = 0, cg.py on main). For each DEM
field time t > 0 the continuum's written time at the same discharged
fraction of the fill (comparable fill levels) is taken; the continuum's
solid fraction is alpha rho_b / rho_p (the mass it carries, incompressible
at phi_max) and alpha phi(I) (the calibrated dilatancy, not fed back), its
velocity the mixture U_z where alpha >= 0.05, its pressure the mixture p
(the rheology's; the DEM's is the CG mean stress, contacts + kinetic).
Writes OUT/xval_b10.png, OUT/xval_b10_profiles.csv and OUT/xval_b10.json
(the slot means on z = 0 and the bulk means on the axis of both).

--dem-run DIR (a DEM run folder of the same run with CG dumps every few
field steps: study.py --b 10 --runs noair --cg-every 0.05) and --dem-windows:
the DEM's CG fields are instead the uniform time averages of every snapshot
in each window (cg.compute(average=...)), at the mean time of its snapshots;
their profiles go to OUT/cg/ (dem_t<t0>-<t1>_{axis,orifice}.csv; the
grids to OUT/runs/cg/). A single
snapshot's contact pressure scatters by tens of per cent at the orifice,
where only a few parcels touch.
"""
import csv
import json
import os

import numpy as np

import granair_cases as gc
import parameters as P

HERE = os.path.dirname(os.path.abspath(__file__))


def dem_fraction(stem, b_mm):
    """{t: discharged fraction of the fill} of the DEM run (its discharge csv, full depth)."""
    s = gc.series.read_csv(os.path.join(HERE, "reference-demo", stem + ".csv"))
    fill, rho_b = P.FILLS[b_mm]
    m0 = rho_b * P.fill_area(b_mm * 1e-3, fill) * P.DEPTH
    return s["t"], s["discharged_kg"] / m0, m0


def continuum_fraction(run):
    with open(os.path.join(run, "postProcessing", "timeSeries.csv")) as fh:
        rows = list(csv.DictReader(fh))
    t = np.array([float(r["t"]) for r in rows])
    out = np.array([float(r["discharged_kg"]) for r in rows])
    return t, out / float(rows[0]["powder_mass_kg"])


def dem_profiles(stem, kind):
    s = gc.series.read_csv(os.path.join(HERE, "reference-demo", f"{stem}_cg_{kind}.csv"))
    key = "z_m" if kind == "axis" else "x_m"
    return {float(t): {k: s[k][s["t"] == t] for k in (key, "cg_solid_fraction", "cg_velocity_z", "cg_pressure")}
            for t in np.unique(s["t"]) if t > 0}


def dem_profiles_averaged(run, windows, out):
    """{kind: {mean snapshot time: profile}} of the time-averaged CG fields of a DEM run folder."""
    import cg
    with open(os.path.join(run, "case.json")) as fh:
        v = json.load(fh)
    steps = sorted(int(n.split("_")[1].split(".")[0]) for n in os.listdir(os.path.join(run, "dem", "post", "cg"))
                   if n.startswith("particles_"))
    prof = {"axis": {}, "orifice": {}}
    os.makedirs(os.path.join(out, "cg"), exist_ok=True)
    for t0, t1 in windows:
        ts = [s * v["DEM_DT"] for s in steps if t0 - 1e-9 <= s * v["DEM_DT"] <= t1 + 1e-9]
        if len(ts) < 2:
            raise gc.CaseError(f"{run}/dem/post/cg: {len(ts)} CG snapshots in {t0:g}-{t1:g} s, expected >= 2")
        tm = round(float(np.mean(ts)), 6)
        stem = os.path.abspath(os.path.join(out, "runs", "cg", f"dem_t{t0:g}-{t1:g}"))   # the grid (not committed)
        xs, zs, g = cg.read_grid(cg.compute(run, v, None, stem, average=(t0, t1)))
        ix, iz = int(np.argmin(np.abs(xs))), int(np.argmin(np.abs(zs)))
        for kind, key, coord, pick in (("axis", "z_m", zs, lambda f: f[:, ix]), ("orifice", "x_m", xs, lambda f: f[iz, :])):
            p = {key: coord, "cg_solid_fraction": pick(g["volume_fraction"]), "cg_velocity_z": pick(g["velocity_z"]),
                 "cg_pressure": pick(g["pressure"])}
            prof[kind][tm] = p
            gc.series.write_csv(os.path.join(out, "cg", f"dem_t{t0:g}-{t1:g}_{kind}.csv"), list(p.items()), fmt="{:.6g}")
        print(f"wedge-silo xval: DEM CG time average of {len(ts)} snapshots, t = {ts[0]:g}-{ts[-1]:g} s (mean {tm:g})")
    return prof


def main():
    ap = gc.cli.parser(__doc__)
    ap.add_argument("--run", default=os.path.join(HERE, "reference-continuum-calibrated-demo", "runs", "b10_noair"))
    ap.add_argument("--dem", default="b10_noair")
    ap.add_argument("--dem-run", default=None, help="a DEM run folder with CG dumps (time-averaged DEM fields)")
    ap.add_argument("--dem-windows", nargs="+", default=["0.15:0.35", "0.35:0.5"],
                    help="with --dem-run: the averaging windows T0:T1 [s]")
    a = gc.cli.parse(ap, os.path.join(HERE, "reference-continuum-calibrated-demo"))
    b_mm = 10
    with open(os.path.join(a.run, "silo.json")) as fh:
        v = json.load(fh)
    phi_b = v["RHO_B"] / P.RHO_P
    td, fd, m0 = dem_fraction(a.dem, b_mm)
    tc, fc = continuum_fraction(a.run)
    written = [t for t, _ in gc.foam.time_dirs(a.run) if t > 0]
    if a.dem_run:
        avg = dem_profiles_averaged(a.dem_run, [tuple(float(x) for x in w.split(":")) for w in a.dem_windows], a.out)
        axis, orifice = avg["axis"], avg["orifice"]
    else:
        axis, orifice = dem_profiles(a.dem, "axis"), dem_profiles(a.dem, "orifice")
    pairs = []
    for t in sorted(axis):
        f = float(np.interp(t, td, fd))
        tcw = min(written, key=lambda x: abs(float(np.interp(x, tc, fc)) - f))
        pairs.append((t, f, tcw, float(np.interp(tcw, tc, fc))))
    plt = gc.plots.pyplot()
    fig, axes = plt.subplots(2, 3, figsize=(13, 7.5))
    rows, numbers = [], []
    colours = ["tab:blue", "tab:red", "tab:green"]
    for i, (t, f, tcw, fcw) in enumerate(pairs):
        col = colours[i % len(colours)]
        for r, (kind, prof, key) in enumerate((("axis", axis[t], "z_m"), ("orifice", orifice[t], "x_m"))):
            coord = prof[key]
            pts = [(0.0, c) for c in coord] if kind == "axis" else [(c, 0.0) for c in coord]
            c = gc.foam.line_profile(a.run, tcw, ["alpha.powder", "phiSolid", "U", "p"], pts)
            alpha = c["alpha.powder"]
            solid, dil = alpha * phi_b, alpha * c["phiSolid"]
            uz = np.where(alpha >= 0.05, c["U_z"], np.nan)
            pc = np.where(alpha >= 0.05, c["p"], np.nan)
            x = coord * 1e3
            lab_d, lab_c = f"DEM CG{' avg' if a.dem_run else ''}, t = {t:g} s ({f:.0%} out)", f"continuum, t = {tcw:g} s ({fcw:.0%} out)"
            for k, (dem_y, cont_y, name) in enumerate(((prof["cg_solid_fraction"], solid, "solid fraction"),
                                                       (prof["cg_velocity_z"], uz, "v_z [m/s]"),
                                                       (prof["cg_pressure"], pc, "pressure [Pa]"))):
                ax = axes[r, k]
                ax.plot(x, dem_y, color=col, lw=1.2, marker=".", ms=3, label=lab_d)
                ax.plot(x, cont_y, color=col, lw=1.5, ls="--", label=lab_c)
                if k == 0:
                    ax.plot(x, dil, color=col, lw=0.8, ls=":", label="continuum alpha phi(I)" if i == 0 else None)
                ax.set(xlabel="z [mm] (x = 0)" if kind == "axis" else "x [mm] (z = 0)",
                       title=f"{'centre line' if kind == 'axis' else 'orifice plane'}: {name}")
                ax.axvline(0, color="0.7", lw=0.5) if kind == "axis" else [ax.axvline(s * b_mm / 2, color="0.7", lw=0.5)
                                                                          for s in (-1, 1)]
            for j, cc in enumerate(coord):
                rows.append(dict(profile=kind, t_dem_s=t, t_continuum_s=tcw, coord_m=f"{cc:.6g}",
                                 dem_solid_fraction=f"{prof['cg_solid_fraction'][j]:.5g}",
                                 continuum_solid_fraction=f"{solid[j]:.5g}", continuum_alpha_phiI=f"{dil[j]:.5g}",
                                 dem_velocity_z=f"{prof['cg_velocity_z'][j]:.5g}", continuum_velocity_z=f"{uz[j]:.5g}",
                                 dem_pressure=f"{prof['cg_pressure'][j]:.5g}", continuum_pressure=f"{pc[j]:.5g}"))
            sel = (np.abs(coord) < b_mm / 2 * 1e-3) if kind == "orifice" else (coord > 0.01) & (coord < 0.028)
            numbers.append(dict(profile=kind, where="slot |x| < b/2 on z = 0" if kind == "orifice" else "axis, z = 10-28 mm",
                                t_dem_s=t, t_continuum_s=tcw, fraction_out_dem=f, fraction_out_continuum=fcw,
                                **{f"{who}_{q}": float(np.nanmean(y[sel])) for who, q, y in (
                                    ("dem", "solid_fraction", prof["cg_solid_fraction"]), ("continuum", "solid_fraction", solid),
                                    ("dem", "velocity_z", prof["cg_velocity_z"]), ("continuum", "velocity_z", uz),
                                    ("dem", "pressure", prof["cg_pressure"]), ("continuum", "pressure", pc))}))
    for ax in axes.flat:
        ax.grid(alpha=0.3)
    axes[0, 0].legend(fontsize=7)
    fig.suptitle(f"wedge silo b = {b_mm} mm, dry: coarse-grained DEM (demo, parcels {v['D_LACTOSE'] * 1e3:.3g} mm; "
                 f"granairCG, kernel 1 d{', time averages over ' + ', '.join(a.dem_windows) + ' s' if a.dem_run else ', single snapshots'}) "
                 f"vs continuum with the DEM-calibrated mu(I) (N = {v['N']})", fontsize=9)
    fig.tight_layout()
    os.makedirs(a.out, exist_ok=True)
    gc.plots.save(fig, os.path.join(a.out, f"xval_b{b_mm}.png"))
    gc.series.write_rows(os.path.join(a.out, f"xval_b{b_mm}_profiles.csv"), rows)
    with open(os.path.join(a.out, f"xval_b{b_mm}.json"), "w") as fh:
        json.dump(dict(dem_fill_kg=m0, means=numbers), fh, indent=1)
    for n in numbers:
        print(f"{n['profile']:8s} DEM t = {n['t_dem_s']:g} ({n['fraction_out_dem']:.0%}) | continuum t = "
              f"{n['t_continuum_s']:g} ({n['fraction_out_continuum']:.0%}), {n['where']}: solid fraction "
              f"{n['dem_solid_fraction']:.3f} | {n['continuum_solid_fraction']:.3f}; v_z {n['dem_velocity_z']:.3f} | "
              f"{n['continuum_velocity_z']:.3f} m/s; p {n['dem_pressure']:.1f} | {n['continuum_pressure']:.1f} Pa")


if __name__ == "__main__":
    gc.cli.main(main)
