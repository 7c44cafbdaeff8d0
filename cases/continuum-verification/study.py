#!/usr/bin/python3
"""The continuum solver against closed forms (README.md).

    study.py [--case inclined-plane|couette-coulomb|inclined-plane-dilatancy|all] [--out DIR] [--check]
             [--cells N] [--end T] [--setup-only]

  inclined-plane   steady mu(I) flow down a plane (Bagnold profile), the Jop
                   form and the Barker & Gray (2017) form: 2 runs
  couette-coulomb  plane shear over a Coulomb wall, one run per regime:
                   stick, slide of a sheared layer, rigid sliding: 3 runs
  inclined-plane-dilatancy  the plane with `dilatancy on;` (Dilatancy.H): the
                   layer dilates to phi(I) of the Bagnold I and deepens: 1 run

Each run is template/ (template-couette/ over it for the shear cell) filled in
DIR/runs/<name>; results in DIR: <name>.csv (y, u, u_exact), profiles.png,
summary.txt (key = value). --check exits 1 unless
  inclined plane:  max |u - u_exact| over the powder cells <= 1 % of the
                   exact surface velocity, the flux within 1 %, and steady
                   (the last two written profiles within 1e-4 of each other);
  couette-coulomb: max |u - u_exact| <= 0.5 % of the wall velocity, the
                   regime (stick / slide) as the closed form says, and steady
                   (the last two written profiles within 1e-4 of V);
  dilatancy:       phi within 5e-4 of phi(I) over the lower 90 % of the
                   layer and its mean over the layer within 1e-3, the depth
                   sum(alpha dy) within 0.5 % of h0 phi0 / phi(I), the grains'
                   volume kept to 1e-9, the profile and flux of the dilated
                   layer within 1 % as above, and steady (lower 90 %).
"""
import math
import os
import time

import granair_cases as gc
import exact
import parameters as P

HERE = os.path.dirname(os.path.abspath(__file__))


def common(end, dt_max, regularisation):
    q = P.GLASS
    return dict(END=end, WRITE_INTERVAL=end / P.WRITES, DT_MAX=dt_max, AIR_RHO=P.AIR_RHO, AIR_MU=P.AIR_MU,
                RHO_POWDER=P.PHI * q["rhoP"], MU_S=q["muS"], MU_2=q["mu2"], I0=q["I0"], D=q["d"], RHO_P=q["rhoP"],
                ETA_MAX=q["etaMax"], GAMMA_DOT_MIN=q["gammaDotMin"], REGULARISATION=regularisation,
                DILATANCY="", PHI_LIMITS="")


def setup_plane(run, regularisation, cells, end, dilatant=False):
    """A layer of DEPTH_D grains on a plane at THETA: gravity's normal part in
    constant/g, its along-slope part as the uniform acceleration (periodic in x).
    dilatant: `dilatancy on;` and the phi(I) of P.DILATANT."""
    h = P.DEPTH_D * P.GLASS["d"]
    dy = h / cells
    ny = cells + max(4, cells // 6)
    th = math.radians(P.THETA)
    extra = dict(DILATANCY="dilatancy on;", PHI_LIMITS="".join(
        f"    {k:<11} {v:.10g};\n" for k, v in P.DILATANT.items())) if dilatant else {}
    gc.template.render(os.path.join(HERE, "template"), run, dict(
        common(end, P.PLANE_DT_MAX, regularisation), **extra, LX=2 * h, LY=ny * dy, NY=ny, TOP_TYPE="patch", P_REF="",
        G_Y=-exact.G * math.cos(th), ACC_X=exact.G * math.sin(th),
        ALPHA=gc.foam.nonuniform([1.0 if j < cells else 0.0 for j in range(ny)])))
    return dict(h=h, dy=dy, ny=ny, cells=cells)


def setup_couette(run, mu_w, cells, end):
    H = P.COUETTE_H
    v = dict(common(end, P.COUETTE_DT_MAX, "none"), LX=H, LY=H, NY=cells, TOP_TYPE="wall",
             P_REF=f"pRefCell 0; pRefValue {P.COUETTE_P};", G_Y=0.0, ACC_X=0.0, MU_W=mu_w, V=P.COUETTE_V,
             P=P.COUETTE_P, U0=gc.foam.nonuniform([(P.COUETTE_V * (j + 0.5) / cells, 0, 0) for j in range(cells)]))
    gc.template.render(os.path.join(HERE, "template"), run, dict(v, ALPHA="uniform 1"))
    gc.template.render(os.path.join(HERE, "template-couette"), run, v)
    return dict(H=H, dy=H / cells, ny=cells, cells=cells)


def profiles(run, geo):
    """u_x per cell row, bottom to top, at the last two written times, and those times."""
    tdirs = [p for t, p in gc.foam.time_dirs(run) if t > 0 and os.path.exists(os.path.join(p, "U"))][-2:]
    u = [gc.foam.read_field(os.path.join(p, "U"), geo["ny"])[:, 0] for p in tdirs]
    return u[1], u[0], " ".join(os.path.basename(p) for p in tdirs)


def check_plane(name, regularisation, run, geo, wall):
    q = dict(P.GLASS, regularisation=regularisation)
    h, dy, n = geo["h"], geo["dy"], geo["cells"]
    u, u_prev, times = profiles(run, geo)
    us, I = exact.bagnold(h, h, P.THETA, P.PHI, q)
    rows = [((j + 0.5) * dy, float(u[j]), exact.bagnold((j + 0.5) * dy, h, P.THETA, P.PHI, q)[0]) for j in range(n)]
    err = max(abs(r[1] - r[2]) for r in rows)
    flux, flux_exact = sum(r[1] * dy for r in rows), exact.bagnold_flux(h, P.THETA, P.PHI, q)
    steady = float(max(abs(u[:n] - u_prev[:n]))) / us
    res = dict(name=name, regularisation=regularisation, theta_deg=P.THETA, depth_m=h, cells_in_layer=n,
               inertial_number=I, surface_velocity_exact_m_s=us, surface_cell_velocity_m_s=float(u[n - 1]),
               max_error_over_surface_velocity=err / us, flux_m2_s=flux, flux_exact_m2_s=flux_exact,
               flux_error=(flux - flux_exact) / flux_exact, change_last_two_writes=steady, times=times, run_wall_s=wall)
    ok = err / us <= P.PLANE_PROFILE and abs(res["flux_error"]) <= P.PLANE_FLUX and steady <= P.STEADY
    return res, rows, ok


def check_plane_dilatancy(name, regularisation, run, geo, wall):
    """The dilated steady layer (exact.dilatant_layer) against the run's last write."""
    q = dict(P.GLASS, regularisation=regularisation)
    dy, n0, ny = geo["dy"], geo["cells"], geo["ny"]
    phi_x, h, I = exact.dilatant_layer(geo["h"], P.PHI, P.THETA, q, P.DILATANT["phiMax"], P.DILATANT["phiMin"])
    us, _ = exact.bagnold(h, h, P.THETA, phi_x, q)
    u, u_prev, times = profiles(run, geo)
    last = [p for t, p in gc.foam.time_dirs(run) if t > 0 and os.path.exists(os.path.join(p, "U"))][-1]
    field = lambda f: gc.foam.read_field(os.path.join(last, f), ny)
    alpha, phi, grains = field("alpha.powder"), field("phiPowder"), field("alpha.grains")
    full = int(h // dy)                     # the cells wholly inside the dilated layer
    rows = [((j + 0.5) * dy, float(u[j]), exact.bagnold((j + 0.5) * dy, h, P.THETA, phi_x, q)[0]) for j in range(full)]
    err = max(abs(r[1] - r[2]) for r in rows)
    flux, flux_exact = float(sum(u * alpha) * dy), exact.bagnold_flux(h, P.THETA, phi_x, q)
    bulk = int(P.BULK * h // dy)            # the lower BULK of it (parameters.py: why)
    phi_err = float(max(abs(phi[:bulk] - phi_x)))
    depth = float(sum(alpha) * dy)
    grains_err = float(sum(grains) * dy / (geo["h"] * P.PHI) - 1)
    steady = float(max(abs(u[:bulk] - u_prev[:bulk]))) / us
    res = dict(name=name, regularisation=regularisation, theta_deg=P.THETA, depth_start_m=geo["h"],
               cells_in_layer_start=n0, inertial_number=I, solid_fraction_exact=phi_x,
               solid_fraction_max_error_bulk=phi_err, solid_fraction_max_error_layer=float(max(abs(phi[:full] - phi_x))),
               solid_fraction_mean=float(phi[:full].mean()),
               depth_exact_m=h, depth_m=depth, depth_error=depth / h - 1, grains_error=grains_err,
               surface_velocity_exact_m_s=us, max_error_over_surface_velocity=err / us, flux_m2_s=flux,
               flux_exact_m2_s=flux_exact, flux_error=(flux - flux_exact) / flux_exact,
               change_last_two_writes=steady, times=times, run_wall_s=wall)
    ok = (phi_err <= P.PLANE_PHI and abs(res["solid_fraction_mean"] - phi_x) <= P.PLANE_PHI_MEAN
          and abs(res["depth_error"]) <= P.PLANE_DEPTH and abs(grains_err) <= P.GRAINS
          and err / us <= P.PLANE_PROFILE and abs(res["flux_error"]) <= P.PLANE_FLUX and steady <= P.STEADY)
    return res, rows, ok


def check_couette(name, mu_w, run, geo, wall):
    q = dict(P.GLASS, regularisation="none")
    H, dy, V = geo["H"], geo["dy"], P.COUETTE_V
    u, u_prev, times = profiles(run, geo)
    steady = float(max(abs(u - u_prev))) / V
    rows = []
    for j in range(geo["cells"]):
        ue, regime, gd = exact.couette_coulomb((j + 0.5) * dy, H, V, P.COUETTE_P, mu_w, q)
        rows.append(((j + 0.5) * dy, float(u[j]), ue))
    err = max(abs(r[1] - r[2]) for r in rows)
    slip = float(u[0] - 0.5 * (u[1] - u[0]))      # the run's wall velocity: the two lowest cells extrapolated to y = 0
    run_regime = "stick" if abs(slip) < P.STICK * V else "slide"
    res = dict(name=name, friction_coefficient=mu_w, regime_exact=regime, shear_rate_exact_1_s=gd,
               slip_velocity_exact_m_s=exact.couette_coulomb(0.0, H, V, P.COUETTE_P, mu_w, q)[0],
               slip_velocity_m_s=slip, max_error_over_wall_velocity=err / V, change_last_two_writes=steady,
               times=times, cells=geo["cells"], run_wall_s=wall, regime_run=run_regime)
    ok = err / V <= P.COUETTE_PROFILE and run_regime == regime and steady <= P.STEADY
    return res, rows, ok


def plot(results, out):
    plt = gc.plots.pyplot()
    fig, axes = plt.subplots(1, len(results), figsize=(3.2 * len(results), 3.8), squeeze=False)
    for ax, (res, rows) in zip(axes[0], results):
        y = [r[0] * 1e3 for r in rows]
        ax.plot([r[2] for r in rows], y, "k-", lw=1.5, label="closed form")
        ax.plot([r[1] for r in rows], y, "o", ms=3, mfc="none", color="C0", label="granairContinuumFoam")
        ax.set(xlabel="u [m/s]", ylabel="y [mm]")
        ax.set_title(res["name"], fontsize=9)
        ax.grid(alpha=0.3)
    axes[0][0].legend(fontsize=7, loc="upper left")
    fig.tight_layout()
    gc.plots.save(fig, os.path.join(out, "profiles.png"), dpi=110)


def main():
    ap = gc.cli.parser(__doc__, out_help="results (default: results/ beside this script)")
    ap.add_argument("--case", choices=["inclined-plane", "couette-coulomb", "inclined-plane-dilatancy", "all"],
                    default="all")
    ap.add_argument("--cells", type=int, default=None,
                    help=f"cells across the layer (default {P.PLANE_CELLS} plane, {P.COUETTE_CELLS} Couette)")
    ap.add_argument("--end", type=float, default=None,
                    help=f"simulated time [s] (default {P.PLANE_END:g} plane, {P.COUETTE_END:g} Couette)")
    a = gc.cli.parse(ap, os.path.join(HERE, "results"))
    kinds = ["inclined-plane", "couette-coulomb", "inclined-plane-dilatancy"] if a.case == "all" else [a.case]
    results, failed, summary = [], [], []
    for kind in kinds:
        plane = kind.startswith("inclined-plane")
        dilatant = kind == "inclined-plane-dilatancy"
        for name, param in P.RUNS[kind]:
            run = gc.runner.clean(os.path.join(a.out, "runs", name))
            end = a.end or (P.PLANE_DILATANCY_END if dilatant else P.PLANE_END)
            geo = (setup_plane(run, param, a.cells or P.PLANE_CELLS, end, dilatant) if plane else
                   setup_couette(run, param, a.cells or P.COUETTE_CELLS, a.end or P.COUETTE_END))
            if a.setup_only:
                continue
            print(f"verify: {name} ...", flush=True)
            t0 = time.time()
            gc.runner.run(["blockMesh"], run)
            gc.runner.run(["granairContinuumFoam"], run)
            check = check_plane_dilatancy if dilatant else check_plane if plane else check_couette
            res, rows, ok = check(name, param, run, geo, time.time() - t0)
            gc.series.write_rows(os.path.join(a.out, name + ".csv"),
                                 [dict(y_m=y, u_m_s=u, u_exact_m_s=ue) for y, u, ue in rows])
            results.append((res, rows))
            summary += [f"[{name}]"] + [f"{k} = {v:.6g}" if isinstance(v, float) else f"{k} = {v}"
                                       for k, v in res.items() if k != "name"] + [f"pass = {int(ok)}", ""]
            print("verify: %s %s (%.0f s): %s" % (name, "PASS" if ok else "FAIL", res["run_wall_s"], ", ".join(
                f"{k} {v:.4g}" for k, v in res.items() if isinstance(v, float) and ("error" in k or "velocity" in k))),
                flush=True)
            if not ok:
                failed.append(name)
    if a.setup_only:
        return print(f"verify: run folders written to {os.path.join(a.out, 'runs')}")
    with open(os.path.join(a.out, "summary.txt"), "w") as fh:
        fh.write("\n".join(summary))
    plot(results, a.out)
    print(f"verify: results in {a.out} (summary.txt, profiles.png, one CSV per run)")
    if failed:
        print("verify: FAILED: " + ", ".join(failed), flush=True)
        return 1 if a.check else 0
    return 0


if __name__ == "__main__":
    gc.cli.main(main)
