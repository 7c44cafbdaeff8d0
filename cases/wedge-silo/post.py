#!/usr/bin/env python3
"""post.py: post-processing of the wedge-silo runs (numpy + matplotlib).

Per run: the results CSV (t, mass_flow_kg_s, outlet_dpdz_Pa_m, ...), the
particle accounting from granairFoam's discharge report, the steady mass flow
and outlet gradient, void fraction (and, with air, air pressure) pictures and
VTK files at the field times. Per study: the bulk density of each settled
fill, the Hagen-Beverloo band and the Crewdson estimate, the plots.
Used by study.py; `post.py RUNDIR OUTDIR NAME` post-processes one run.
"""
import csv
import glob
import json
import math
import os
import re
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt                      # noqa: E402
from matplotlib.collections import PolyCollection    # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import make_case as mc                                # noqa: E402
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools", "pylib"))
from granair_cases import closed_forms as cf         # noqa: E402
import dem_io                                         # noqa: E402

G = mc.G
BEVERLOO_C = 0.58        # Hagen-Beverloo constant used for the slot band (see README)
K_RANGE = (1.0, 3.0)     # the empty-annulus constant k
STEADY_FROM = 0.3        # steady discharge assumed from this time on [s]


# ----------------------------------------------------------------- readers
def case_of(run_dir):
    with open(os.path.join(run_dir, "case.json")) as fh:
        info = json.load(fh)
    case = mc.Case(info["size"], info["b_mm"], air=info["air"], s=info["coarse_graining_factor"],
                   t_end=info["t_end_s"], write_interval=info["write_interval_s"],
                   youngs=info["youngs_Pa"], cohesion=info["cohesion_mode"], np=info["np"],
                   seed=info["seed"], fill=info["fill_height_target_m"],
                   slice_parcels=info["slice_parcels"])
    return case, info


def read_series(run_dir):
    """postProcessing/timeSeries.csv as a dict of numpy arrays."""
    with open(os.path.join(run_dir, "postProcessing", "timeSeries.csv")) as fh:
        rows = list(csv.reader(fh))
    head, data = rows[0], np.array([[float(v) for v in r] for r in rows[1:]])
    return {h: data[:, i] for i, h in enumerate(head)}


def read_balance(log_path):
    """The DEM discharge balance granairFoam prints at the end (tools/pylib/dem_io.py)."""
    return dem_io.read_discharge_balance(log_path, "post")


def read_internal_field(path):
    """internalField of an ASCII OpenFOAM volScalarField (uniform or nonuniform)."""
    with open(path) as fh:
        text = fh.read()
    i = text.index("internalField")
    line = text[i:text.index("\n", i)]
    m = re.search(r"internalField\s+uniform\s+([-+\d.eE]+)", line)
    if m:
        return float(m.group(1))
    rest = text[i:]
    n = int(re.search(r"List<scalar>\s*(\d+)", rest).group(1))
    body = rest[rest.index("(") + 1:rest.index(")")]
    vals = np.array(body.split()[:n], dtype=float)
    if len(vals) != n:
        raise SystemExit(f"post: {path}: {len(vals)} values, expected {n}")
    return vals


def time_dir(run_dir, t):
    for name in os.listdir(run_dir):
        try:
            if abs(float(name) - t) < 1e-9:
                return os.path.join(run_dir, name)
        except ValueError:
            pass
    return None


# --------------------------------------------------------------- analysis
def steady_end(t, particles):
    """End of the steady window: the time half of the fill has left the silo
    (the rate falls once the free surface reaches the hopper and drops to 0
    when the silo is empty), or the end of the run."""
    half = np.nonzero(particles <= 0.5 * particles[0])[0]
    return float(t[half[0]]) if half.size else float(t[-1])


def steady_rate(t, y, t0, t1=None):
    """Least-squares slope of y(t) for t0 <= t <= t1 (the steady discharge rate)."""
    sel = (t >= t0) & (t <= (t[-1] if t1 is None else t1))
    if sel.sum() < 3:
        return float("nan")
    return float(np.polyfit(t[sel], y[sel], 1)[0])


def window_mean(t, y, t0, t1=None):
    sel = (t >= t0) & (t <= (t[-1] if t1 is None else t1))
    return float(np.mean(y[sel])) if sel.any() else float("nan")


def trailing_mean(t, y, window):
    """Mean of y over the trailing window (as MassFlowRate does for the mass)."""
    out = np.empty_like(y)
    j = 0
    for i in range(len(t)):
        while t[j] < t[i] - window + 1e-12:
            j += 1
        out[i] = np.mean(y[j:i + 1])
    return out


def fill_stats(fill_dir, case):
    """Bulk density of the settled fill (parcels with centres between 5 mm above the
    orifice and 3 parcel diameters below the top, divided by that silo volume), the
    settled fill height (mean over x-bins of the highest parcel top) and the mass."""
    atoms = mc.read_dump(os.path.join(fill_dir, "dem", "fill.dump"))
    x = np.array([a["x"] for a in atoms])
    z = np.array([a["z"] for a in atoms])
    r = np.array([a["radius"] for a in atoms])
    m = np.array([a["mass"] for a in atoms])
    edges = np.linspace(-mc.WIDTH / 2, mc.WIDTH / 2, 6)
    tops = []
    for lo, hi in zip(edges[:-1], edges[1:]):
        sel = (x >= lo) & (x < hi)
        if sel.any():
            tops.append(float(np.max(z[sel] + r[sel])))
    top = float(np.mean(tops))
    z0, z1 = 0.005, top - 3 * case.d_parcel_mean
    sel = (z >= z0) & (z < z1)
    vol = (case.fill_area(z1) - case.fill_area(z0)) * case.slice
    rho_b = float(m[sel].sum() / vol)
    return dict(rho_b=rho_b, solid_fraction=rho_b / mc.RHO_P, fill_top_m=top, n_parcels=len(atoms),
                mass_slice_kg=float(m.sum()), mass_full_depth_kg=float(m.sum() * case.depth_scale),
                full_silo_primaries_d225=case.full_silo_particles(225e-6, fill=top))


def beverloo(b, d, rho_b, k):
    """Hagen-Beverloo for a slot, scaled to the full depth: C rho_b sqrt(g) (b - k d)^1.5 L."""
    return cf.beverloo_slot(b, d, rho_b, mc.DEPTH, k, BEVERLOO_C, G)


def crewdson(w0, dpdz, rho_b):
    """Air-impeded rate W0 sqrt(1 + (dp/dz)/(rho_b g)) (Crewdson et al. 1977), z up;
    dp/dz a number or an array (the time series)."""
    return np.vectorize(lambda x: cf.crewdson(w0, x, rho_b, G))(dpdz)


# ------------------------------------------------------------------ output
def write_run_csv(series, case, path):
    """The results table of one run. Without air there is no air pressure: the
    pressure columns are 0 by definition."""
    n = len(series["t"])
    zero = np.zeros(n)
    cols = [("t", series["t"]), ("mass_flow_kg_s", series["mass_flow_kg_s"]),
            ("outlet_dpdz_Pa_m", series.get("outlet_dpdz_Pa_m", zero)),
            ("outlet_p_Pa", series.get("outlet_p_Pa", zero)),
            ("above_p_Pa", series.get("above_p_Pa", zero)),
            ("above_dpdz_Pa_m", series.get("above_dpdz_Pa_m", zero)),
            ("discharged_kg", series["discharged_kg"]), ("particles", series["particles"])]
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow([c for c, _ in cols])
        for i in range(n):
            w.writerow([f"{v[i]:.8g}" for _, v in cols])


def particle_snapshot(run_dir, case, t):
    step = round(t / case.dem_dt)
    path = os.path.join(run_dir, "dem", "post", f"particles_{step}.txt")
    return mc.read_dump(path) if os.path.exists(path) else None


def write_vtk_polydata(path, case, cell_data):
    """Legacy ASCII VTK of the 2-D cells (polygons in the mid-plane y = slice/2)."""
    polys = case.cell_polygons()
    y = case.slice / 2
    with open(path, "w") as fh:
        fh.write("# vtk DataFile Version 3.0\nwedge silo cells (make_case.py layout)\nASCII\n"
                 "DATASET POLYDATA\n")
        fh.write(f"POINTS {4 * len(polys)} double\n")
        for poly in polys:
            for (x, z) in poly:
                fh.write(f"{x:.9g} {y:.9g} {z:.9g}\n")
        fh.write(f"POLYGONS {len(polys)} {5 * len(polys)}\n")
        for i in range(len(polys)):
            fh.write(f"4 {4 * i} {4 * i + 1} {4 * i + 2} {4 * i + 3}\n")
        fh.write(f"CELL_DATA {len(polys)}\n")
        for name, vals in cell_data.items():
            fh.write(f"SCALARS {name} double 1\nLOOKUP_TABLE default\n")
            fh.write("\n".join(f"{v:.8g}" for v in vals) + "\n")


def field_times(case):
    n = int(math.floor(case.t_end / case.write_interval + 1e-9))
    return [round(k * case.write_interval, 9) for k in range(n + 1)]


def fields_of_run(run_dir, case):
    """{t: {'voidfraction': array, 'p': array or None, 'source': str}} at the field times.
    With air: OpenFOAM's fields (t = 0: the settled bed and air at rest). Without air:
    the void fraction of the particle snapshots with the coupling's model."""
    mapper = None
    out = {}
    for t in field_times(case):
        td = time_dir(run_dir, t)
        if case.air and td and os.path.exists(os.path.join(td, "voidfraction")):
            eps = read_internal_field(os.path.join(td, "voidfraction"))
            p = read_internal_field(os.path.join(td, "p"))
            n = case.n_cells()
            eps = np.full(n, eps) if np.isscalar(eps) else eps
            p = np.full(n, p) if np.isscalar(p) else p
            out[t] = dict(voidfraction=eps, p=p, source="OpenFOAM")
            continue
        atoms = particle_snapshot(run_dir, case, t)
        if atoms is None:
            continue
        mapper = mapper or mc.VoidFractionMapper(case)
        out[t] = dict(voidfraction=np.array(mapper.void_fraction(atoms, floor=0.3)),
                      p=None, source="particles")
    return out


def plot_fields(fields, case, title, path):
    """One row per field (void fraction; air pressure with air), one panel per time,
    cropped to the fill height plus 30 mm; one colour bar per row."""
    times = sorted(fields)
    has_p = any(f["p"] is not None for f in fields.values())
    rows = 2 if has_p else 1
    ztop = min(case.hopper_height + mc.SHAFT_HEIGHT, case.fill_height + 0.03) * 1e3
    zbot = -mc.BOX_BELOW * 1e3
    aspect = (ztop - zbot) / (mc.WIDTH * 1e3)
    fig, axes = plt.subplots(rows, len(times), squeeze=False,
                             figsize=(1.9 * len(times) + 1.4, 1.9 * aspect * rows + 0.8))
    polys = [[(x * 1e3, z * 1e3) for (x, z) in poly] for poly in case.cell_polygons()]
    plim = max([float(np.max(np.abs(f["p"]))) for f in fields.values() if f["p"] is not None] + [1e-6])
    for j, t in enumerate(times):
        f = fields[t]
        pc0 = PolyCollection(polys, array=f["voidfraction"], cmap="viridis", edgecolors="face",
                             linewidths=0.2)
        pc0.set_clim(0.35, 1.0)
        axes[0][j].add_collection(pc0)
        axes[0][j].set_title(f"t = {t:g} s", fontsize=9)
        if has_p:
            vals = f["p"] if f["p"] is not None else np.zeros(case.n_cells())
            pc1 = PolyCollection(polys, array=vals, cmap="RdBu_r", edgecolors="face", linewidths=0.2)
            pc1.set_clim(-plim, plim)
            axes[1][j].add_collection(pc1)
            axes[1][j].set_title(f"t = {t:g} s", fontsize=9)
    fig.colorbar(pc0, ax=list(axes[0]), fraction=0.04, pad=0.02, label="void fraction")
    if has_p:
        fig.colorbar(pc1, ax=list(axes[1]), fraction=0.04, pad=0.02, label="air pressure - ambient [Pa]")
    for ax in axes.flat:
        ax.set_xlim(-mc.WIDTH / 2 * 1e3, mc.WIDTH / 2 * 1e3)
        ax.set_ylim(zbot, ztop)
        ax.set_aspect("equal")
        ax.set_xlabel("x [mm]", fontsize=8)
        ax.tick_params(labelsize=7)
    for row in axes:
        row[0].set_ylabel("z [mm]", fontsize=8)
    fig.suptitle(title, fontsize=10)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def post_run(run_dir, out_dir, name):
    """Everything per run; returns its summary dict."""
    case, info = case_of(run_dir)
    series = read_series(run_dir)
    bal = read_balance(os.path.join(run_dir, "log", "granairFoam.log"))
    os.makedirs(out_dir, exist_ok=True)
    write_run_csv(series, case, os.path.join(out_dir, f"{name}.csv"))
    t = series["t"]
    t1 = steady_end(t, series["particles"])
    t0 = min(STEADY_FROM, 0.5 * t1)
    summary = dict(name=name, b_mm=case.b_mm, air=case.air, s=case.s, size=case.size, np=case.np,
                   t_end=float(t[-1]), steady_from_s=t0, steady_to_s=t1,
                   W_kg_s=steady_rate(t, series["discharged_kg"], t0, t1),
                   balance=bal)
    if case.air:
        for key in ("outlet_dpdz_Pa_m", "outlet_p_Pa", "above_p_Pa", "above_dpdz_Pa_m"):
            summary[key] = window_mean(t, series[key], t0, t1)
        # "while discharging": from the first discharged particle on
        first = np.argmax(series["discharged_kg"] > 0)
        summary["outlet_p_mean_discharging_Pa"] = float(np.mean(series["outlet_p_Pa"][first:]))
        summary["above_p_mean_discharging_Pa"] = float(np.mean(series["above_p_Pa"][first:]))
    fields = fields_of_run(run_dir, case)
    vtk_dir = os.path.join(out_dir, "vtk", name)
    os.makedirs(vtk_dir, exist_ok=True)
    for tt, f in fields.items():
        data = {"voidfraction": f["voidfraction"]}
        if f["p"] is not None:
            data["p"] = f["p"]
        write_vtk_polydata(os.path.join(vtk_dir, f"{name}_cells_t{tt:g}.vtk"), case, data)
    png = os.path.join(out_dir, f"{name}_fields.png")
    if fields:
        plot_fields(fields, case, f"{name}: b = {case.b_mm} mm, "
                    f"{'with air' if case.air else 'DEM only (void fraction from the particles)'}",
                    png)
    summary["field_times"] = sorted(fields)
    summary["png"] = png if fields else None
    return summary


def main():
    if len(sys.argv) != 4:
        raise SystemExit("usage: post.py RUNDIR OUTDIR NAME")
    print(json.dumps(post_run(*sys.argv[1:]), indent=1, default=float))


if __name__ == "__main__":
    main()
