#!/usr/bin/python3
"""Ergun packed-bed study of the air solver (README.md).

Packed bed (default): granairAirFoam through a fixed bed (template/) over a
sweep of superficial velocities for two particle diameters and two drag laws;
the pressure drop per length between two planes inside the bed against Ergun
(1952). Writes OUT/ergun.csv, OUT/ergun.png. Checked: every ErgunGidaspow
point within 2 % of Ergun (the law is Ergun's equation for eps < 0.8, so the
solver must return it; Di Felice is reported only).

--short-bed: a bed only 4 or 6 cells tall (template-short-bed/ over template/)
between a particle-free plenum and freeboard, so eps jumps 1 -> 0.4 -> 1
between neighbouring cells; --on-inlet puts the bed on the inlet patch (no
plenum; voidfraction fixedValue 1 there so the inflow stays U_s A). Writes
OUT/short_bed[_on_inlet].csv and .png. Checked at every (d, bed height, Re)
with ErgunGidaspow, 2 % each: the total pressure drop (plenum mean - freeboard
mean; the inlet patch's face pressure with --on-inlet) against Ergun x H (the
steady 1-D solution has no other pressure change), and the air velocity of
every bed cell, edge cells included, against U_s/eps (continuity fixes it).
"""
import os
import time

import granair_cases as gc
import parameters as P

HERE = os.path.dirname(os.path.abspath(__file__))
SETUP_ONLY = False


def run_case(case, values, np=1, overlay=None):
    """Write the case from the template (and the overlay's files over it) and run it;
    False with --setup-only (written, not run)."""
    gc.template.render(os.path.join(HERE, "template"), case, values)
    if overlay:
        gc.template.render(os.path.join(HERE, overlay), case, values)
    if SETUP_ONLY:
        return False
    gc.runner.run(["blockMesh"], case)
    gc.runner.run(["setFields"], case)
    gc.runner.decompose(case, np)
    gc.runner.run(["granairAirFoam"], case, np=np)
    return True


def values(law, d, u_s, dz, **extra):
    dt = 0.5 * dz / (u_s / P.EPS)
    return dict(dict(EPS=P.EPS, END_TIME=P.STEPS * dt, DT=dt, RHO=P.RHO, MU=P.MU, DRAG_LAW=law, D=d, U_S=u_s,
                     NP=1, WRITE_EVERY=100000, INLET_VOIDFRACTION="type zeroGradient;"), **extra)


def packed_bed(a, work, checks):
    rows, k, n = [], 0, len(a.laws) * len(a.diameters) * len(a.reynolds)
    for law in a.laws:
        for d in a.diameters:
            for re in a.reynolds:
                k += 1
                u_s = re * P.MU / (P.RHO * d)
                name = f"{law}_d{d * 1e6:.0f}um_Re{re:g}"
                case = os.path.join(work, name)
                if not run_case(case, values(law, d, u_s, P.DZ, NP=a.np), a.np):
                    continue
                mon = gc.series.read_csv(os.path.join(case, "postProcessing", "monitors.csv"), min_rows=2)
                dpl, prev = [float(mon["low_p_Pa"][i] - mon["high_p_Pa"][i]) / (P.Z_HIGH - P.Z_LOW) for i in (-1, -2)]
                ref = P.ergun(u_s, d)
                rows.append(dict(law=law, d_m=d, Re=re, U_s_m_s=u_s, dpL_sim_Pa_m=dpl, dpL_ergun_Pa_m=ref,
                                 rel_err=(dpl - ref) / ref, steady_change=abs(dpl - prev) / abs(dpl)))
                print(f"[{k:2d}/{n}] {name:32s} U_s={u_s:9.3e} m/s  dp/L={dpl:11.4e} Pa/m  Ergun={ref:11.4e}"
                      f"  err={100 * (dpl - ref) / ref:+7.3f} %", flush=True)
                if law == "ErgunGidaspow":
                    checks.close(f"{name} dp/L vs Ergun", dpl, ref, P.TOLERANCE,
                                 "the law is Ergun's equation below eps 0.8: the solver must return it")
    if SETUP_ONLY:
        return rows
    for d in a.diameters if "DiFelice" in a.laws else []:
        errs = [r["rel_err"] for r in rows if r["law"] == "DiFelice" and r["d_m"] == d]
        print(f"DiFelice, d={d * 1e6:.0f} um: deviation from Ergun {', '.join(f'{100 * e:+.1f}%' for e in errs)}"
              " (reported, not asserted)")
    plot_packed(rows, os.path.join(a.out, "ergun.png"), a.diameters, a.laws)
    return rows


def short_bed(a, work, checks):
    plenum = 0 if a.on_inlet else P.PLENUM_CELLS
    rows, profiles, k = [], {}, 0
    total = len(a.diameters) * len(a.bed_cells) * len(a.reynolds)
    for d in a.diameters:
        for n_bed in a.bed_cells:
            for re in a.reynolds:
                k += 1
                dz, u_s = P.cell_size(d), re * P.MU / (P.RHO * d)
                n = plenum + n_bed + P.FREEBOARD_CELLS
                z0, z1, zp, zf = plenum * dz, (plenum + n_bed) * dz, 2 * dz, (n - 2) * dz
                mon = ("{ type patch; patch inlet; normal (0 0 1); }" if a.on_inlet else
                       f"{{ type plane; point (0 0 {zp!r}); normal (0 0 1); "
                       f"boxMin (-1 -1 {zp - 0.1 * dz!r}); boxMax (1 1 {zp + 0.1 * dz!r}); }}")
                v = values("ErgunGidaspow", d, u_s, dz, N=n, DZ=dz, H=n * dz, BED_LO=z0 + 0.25 * dz,
                           BED_HI=z1 - 0.25 * dz, PLENUM_MONITOR=mon, ZF=zf, ZF_LO=zf - 0.1 * dz,
                           ZF_HI=zf + 0.1 * dz)
                v.update(WRITE_EVERY=P.STEPS, INLET_VOIDFRACTION="type fixedValue; value uniform 1;"
                         if a.on_inlet else "type zeroGradient;")
                name = f"{'inlet' if a.on_inlet else 'short'}_d{d * 1e6:.0f}um_N{n_bed}_Re{re:g}"
                case = os.path.join(work, name)
                if not run_case(case, v, overlay="template-short-bed"):
                    continue
                last = gc.foam.time_dirs(case)[-1][1]
                p = list(gc.foam.read_field(os.path.join(last, "p"), n))
                U = gc.foam.read_field(os.path.join(last, "U"), n)
                bed, free = range(plenum, plenum + n_bed), [i for i in range(n) if not plenum <= i < plenum + n_bed]
                freeboard = range(plenum + n_bed + P.AWAY, n)
                if plenum:
                    p_below = sum(p[i] for i in range(plenum - P.AWAY)) / (plenum - P.AWAY)
                else:       # the inlet patch monitor: mean face pressure of the inlet
                    p_below = float(gc.series.read_csv(os.path.join(case, "postProcessing", "monitors.csv"))
                                    ["plenum_p_Pa"][-1])
                dp = float(p_below - sum(p[i] for i in freeboard) / len(freeboard))
                ref = P.ergun(u_s, d) * n_bed * dz
                u_bed = [float(U[i][2] / (u_s / P.EPS) - 1) for i in bed]
                worst_bed = max(u_bed, key=abs)
                dev_free = max(float(((U[i][0] ** 2 + U[i][1] ** 2 + (U[i][2] - u_s) ** 2) ** 0.5) / u_s) for i in free)
                # the momentum-flux change across the two jumps that first-order
                # upwind convection does not recover (reported): rho (U_s/eps - U_s)^2
                upwind = P.RHO * (u_s / P.EPS - u_s) ** 2
                rows.append(dict(d_m=d, bed_cells=n_bed, dz_m=dz, Re=re, U_s_m_s=u_s, dp_sim_Pa=dp, dp_ergun_Pa=ref,
                                 rel_err_dp=(dp - ref) / ref, U_edge_low_rel_err=u_bed[0],
                                 U_edge_high_rel_err=u_bed[-1], U_bed_worst_rel_err=worst_bed,
                                 free_max_dev_rel=dev_free, upwind_share=upwind / ref, cont_err=continuity_error(case)))
                profiles[(d, n_bed, re)] = ([(i + 0.5) * dz for i in range(n)], p, dz, u_s, plenum)
                print(f"[{k:2d}/{total}] {name:28s} dp={dp:11.4e} Pa Ergun*H={ref:11.4e} err={100 * (dp - ref) / ref:+7.3f} %"
                      f"  U edge {100 * u_bed[0]:+7.3f} % {100 * u_bed[-1]:+7.3f} %  free |U-Us| {100 * dev_free:.1e} %",
                      flush=True)
    if SETUP_ONLY:
        return rows
    worst_dp = max(rows, key=lambda r: abs(r["rel_err_dp"]))
    worst_u = max(rows, key=lambda r: abs(r["U_bed_worst_rel_err"]))
    at = "(worst of {} points: d = {:.0f} um, {} cells, Re {:g})"
    checks.close("total pressure drop vs Ergun x H " + at.format(len(rows), worst_dp["d_m"] * 1e6, worst_dp["bed_cells"],
                 worst_dp["Re"]), worst_dp["dp_sim_Pa"], worst_dp["dp_ergun_Pa"], P.TOLERANCE,
                 "the steady 1-D solution has no pressure change but the bed's")
    checks.near("bed-cell air velocity / (U_s/eps) - 1 " + at.format(len(rows), worst_u["d_m"] * 1e6,
                worst_u["bed_cells"], worst_u["Re"]), worst_u["U_bed_worst_rel_err"], 0.0, P.TOLERANCE,
                "continuity fixes it in steady 1-D flow, the edge cells included")
    print(f"particle-free cells: max |U - U_s|/U_s = {max(r['free_max_dev_rel'] for r in rows):.2e}; "
          f"continuity error (cumulative): max |.| = {max(abs(r['cont_err']) for r in rows):.2e} (reported)")
    plot_short(profiles, os.path.join(a.out, ("short_bed_on_inlet" if a.on_inlet else "short_bed") + ".png"))
    return rows


def continuity_error(case):
    with open(os.path.join(case, "log", "granairAirFoam.log")) as fh:
        found = [ln.split()[-1] for ln in fh if "air continuity error (cumulative)" in ln]
    return float(found[-1]) if found else float("nan")


def plot_packed(rows, path, diameters, laws):
    plt = gc.plots.pyplot()
    fig, axes = plt.subplots(1, len(diameters), figsize=(5.5 * len(diameters), 4.2), squeeze=False)
    for ax, d in zip(axes[0], diameters):
        us = sorted(r["U_s_m_s"] for r in rows if r["d_m"] == d)
        if len(us) < 2:
            continue
        fine = [us[0] * (us[-1] / us[0]) ** (i / 100) for i in range(101)]
        ax.loglog(fine, [P.ergun(u, d) for u in fine], "k-", label="Ergun (1952)")
        for law, m in zip(laws, "os^vd"):
            sel = [r for r in rows if r["d_m"] == d and r["law"] == law]
            ax.loglog([r["U_s_m_s"] for r in sel], [r["dpL_sim_Pa_m"] for r in sel], m, mfc="none",
                      label=f"granairAirFoam, {law}")
        ax.set(xlabel="superficial air velocity $U_s$ [m/s]", ylabel="pressure drop per length $\\Delta p/L$ [Pa/m]",
               title=f"packed bed, d = {d * 1e6:.0f} µm, ε = {P.EPS}")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    gc.plots.save(fig, path)


def plot_short(profiles, path):
    """Pressure along the column at Re = 1 (or the first Re run) against the exact profile."""
    plt = gc.plots.pyplot()
    res = sorted({k[2] for k in profiles})
    sel = [k for k in sorted(profiles) if k[2] == (1.0 if 1.0 in res else res[0])]
    fig, axes = plt.subplots(1, len(sel), figsize=(3.6 * len(sel), 4.2), squeeze=False)
    for ax, key in zip(axes[0], sel):
        d, n_bed, re = key
        z, p, dz, u_s, plenum = profiles[key]
        g, z0, z1 = P.ergun(u_s, d), plenum * dz, (plenum + n_bed) * dz
        pe = [g * (z1 - z0) - g * (min(max(zz, z0), z1) - z0) for zz in z]
        off = p[-1] - pe[-1]
        ax.plot([pp - off for pp in pe], [1e3 * zz for zz in z], "k-", label="exact (Ergun in the bed)")
        ax.plot(p, [1e3 * zz for zz in z], "o", mfc="none", label="granairAirFoam, cell p")
        ax.axhspan(1e3 * z0, 1e3 * z1, color="0.9")
        ax.set(xlabel="p [Pa]", ylabel="z [mm]")
        ax.set_title(f"d = {d * 1e6:.0f} µm, {n_bed} bed cells, Re {re:g}", fontsize=9)
        ax.legend(fontsize=7)
    fig.tight_layout()
    gc.plots.save(fig, path)


def main():
    ap = gc.cli.parser(__doc__)
    ap.add_argument("--laws", nargs="+", default=P.LAWS)
    ap.add_argument("--diameters", nargs="+", type=float, default=P.DIAMETERS)
    ap.add_argument("--reynolds", nargs="+", type=float, default=P.REYNOLDS)
    ap.add_argument("--short-bed", action="store_true", help="the short bed with sharp edges")
    ap.add_argument("--on-inlet", action="store_true", help="with --short-bed: the bed rests on the inlet")
    ap.add_argument("--bed-cells", nargs="+", type=int, default=P.BED_CELLS, help="with --short-bed")
    a = gc.cli.parse(ap, os.path.join(HERE, "results"))
    if a.on_inlet and not a.short_bed:
        ap.error("--on-inlet goes with --short-bed")
    tag = ("short_bed_on_inlet" if a.on_inlet else "short_bed") if a.short_bed else "ergun"
    work = os.path.join(a.out, {"ergun": "runs", "short_bed": "runs-short"}.get(tag, "runs-on-inlet"))
    gc.runner.clean(work)
    t0 = time.time()
    checks = gc.checks.Checks(f"ergun-packed-bed ({tag.replace('_', ' ')})")
    global SETUP_ONLY
    SETUP_ONLY = a.setup_only
    rows = (short_bed if a.short_bed else packed_bed)(a, work, checks)
    if a.setup_only:
        return print(f"ergun-packed-bed: cases written to {work}")
    path = gc.series.write_rows(os.path.join(a.out, tag + ".csv"), rows)
    print(f"wrote {path} and {path[:-4]}.png ({time.time() - t0:.0f} s)")
    checks.report(enforce=a.check)


if __name__ == "__main__":
    gc.cli.main(main)
