#!/usr/bin/env python3
"""Ergun packed-bed study: run granairAirFoam through a fixed bed over a sweep
of superficial velocities for two particle diameters and two drag laws, then
compare the pressure drop per length with the Ergun (1952) equation.

Writes <out>/ergun.csv and <out>/ergun.png. With --check, exits 1 unless every
ErgunGidaspow point is within 2 % of Ergun (Di Felice is reported only).
"""
import argparse
import csv
import math
import os
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))

EPS = 0.4                      # bed void fraction
RHO, MU = 1.2, 1.8e-5          # air [kg/m3], [Pa s]
DIAMETERS = [225e-6, 2e-3]     # lactose-like fine powder, coarse beads [m]
REYNOLDS = [0.1, 0.3, 1, 3, 10, 30, 100]   # particle Re = rho U_s d / mu
LAWS = ["ErgunGidaspow", "DiFelice"]
TOLERANCE = 0.02               # Ergun law must match Ergun within 2 %
DZ = 1e-3                      # cell height [m]
Z_LOW, Z_HIGH = 0.02, 0.04     # monitor planes inside the bed [m]
STEPS = 300


def ergun(u_s, d):
    """Ergun (1952) pressure drop per length [Pa/m], U_s superficial."""
    return (150 * MU * u_s * (1 - EPS) ** 2 / (EPS ** 3 * d ** 2)
            + 1.75 * RHO * u_s ** 2 * (1 - EPS) / (EPS ** 3 * d))


def fill_template(src, dst, values):
    shutil.copytree(src, dst)
    for root, _, files in os.walk(dst):
        for f in files:
            p = os.path.join(root, f)
            with open(p) as fh:
                text = fh.read()
            for k, v in values.items():
                text = text.replace(k, v)
            with open(p, "w") as fh:
                fh.write(text)


def run(cmd, cwd, log):
    with open(os.path.join(cwd, log), "w") as fh:
        # PWD must match cwd, or OpenFOAM warns that it does not
        env = dict(os.environ, PWD=cwd)
        r = subprocess.run(cmd, cwd=cwd, stdout=fh, stderr=subprocess.STDOUT, env=env)
    if r.returncode != 0:
        with open(os.path.join(cwd, log)) as fh:
            tail = fh.readlines()[-20:]
        sys.exit(f"ergun-packed-bed: {' '.join(cmd)} failed in {cwd}:\n{''.join(tail)}")


def last_row(csv_path):
    with open(csv_path) as fh:
        rows = list(csv.DictReader(fh))
    return rows[-1], rows[-2]


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--out", default=os.path.join(HERE, "results"))
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--np", type=int, default=1, help="MPI ranks per run (decomposePar)")
    ap.add_argument("--laws", nargs="+", default=LAWS)
    ap.add_argument("--diameters", nargs="+", type=float, default=DIAMETERS)
    ap.add_argument("--reynolds", nargs="+", type=float, default=REYNOLDS)
    args = ap.parse_args()
    out = os.path.abspath(args.out)
    work = os.path.join(out, "runs")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)

    rows = []
    t0 = time.time()
    n = len(args.laws) * len(args.diameters) * len(args.reynolds)
    k = 0
    for law in args.laws:
        for d in args.diameters:
            for re in args.reynolds:
                k += 1
                u_s = re * MU / (RHO * d)
                dt = 0.5 * DZ / (u_s / EPS)
                name = f"{law}_d{d*1e6:.0f}um_Re{re:g}"
                case = os.path.join(work, name)
                fill_template(os.path.join(HERE, "template"), case, {
                    "BED_EPS": repr(EPS), "END_TIME": repr(STEPS * dt), "DELTA_T": repr(dt),
                    "RHO": repr(RHO), "MU": repr(MU), "DRAG_LAW": law,
                    "DIAMETER": repr(d), "U_SUPERFICIAL": repr(u_s)})
                run(["blockMesh"], case, "log.blockMesh")
                run(["setFields"], case, "log.setFields")
                if args.np > 1:
                    decomp = os.path.join(case, "system", "decomposeParDict")
                    with open(decomp) as fh:
                        text = fh.read().replace("numberOfSubdomains 2;", f"numberOfSubdomains {args.np};")
                        text = text.replace("n (1 1 2);", f"n (1 1 {args.np});")
                    with open(decomp, "w") as fh:
                        fh.write(text)
                    run(["decomposePar"], case, "log.decomposePar")
                    run(["mpirun", "-np", str(args.np), "granairAirFoam", "-parallel"], case,
                        "log.granairAirFoam")
                else:
                    run(["granairAirFoam"], case, "log.granairAirFoam")
                last, prev = last_row(os.path.join(case, "postProcessing", "monitors.csv"))
                dpl = (float(last["low_p_Pa"]) - float(last["high_p_Pa"])) / (Z_HIGH - Z_LOW)
                dpl_prev = (float(prev["low_p_Pa"]) - float(prev["high_p_Pa"])) / (Z_HIGH - Z_LOW)
                ref = ergun(u_s, d)
                rows.append(dict(law=law, d_m=d, Re=re, U_s_m_s=u_s, dpL_sim_Pa_m=dpl,
                                 dpL_ergun_Pa_m=ref, rel_err=(dpl - ref) / ref,
                                 steady_change=abs(dpl - dpl_prev) / abs(dpl)))
                print(f"[{k:2d}/{n}] {name:32s} U_s={u_s:9.3e} m/s  dp/L={dpl:11.4e} Pa/m"
                      f"  Ergun={ref:11.4e}  err={100*(dpl-ref)/ref:+7.3f} %", flush=True)

    csv_path = os.path.join(out, "ergun.csv")
    with open(csv_path, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    plot([r for r in rows], os.path.join(out, "ergun.png"), args.diameters, args.laws)
    print(f"wrote {csv_path} and {os.path.join(out, 'ergun.png')} ({time.time()-t0:.0f} s)")

    worst = max((abs(r["rel_err"]) for r in rows if r["law"] == "ErgunGidaspow"), default=0.0)
    print(f"ErgunGidaspow: worst deviation from Ergun {100*worst:.2e} % (tolerance {100*TOLERANCE:.0f} %)")
    for d in args.diameters if "DiFelice" in args.laws else []:
        errs = [r["rel_err"] for r in rows if r["law"] == "DiFelice" and r["d_m"] == d]
        print(f"DiFelice, d={d*1e6:.0f} um: deviation from Ergun "
              f"{', '.join(f'{100*e:+.1f}%' for e in errs)} (reported, not asserted)")
    if args.check and not worst <= TOLERANCE:
        sys.exit("ergun-packed-bed: FAILED, ErgunGidaspow misses Ergun by more than 2 %")


def plot(rows, path, diameters, laws):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib missing: no plot")
        return
    fig, axes = plt.subplots(1, len(diameters), figsize=(5.5 * len(diameters), 4.2), squeeze=False)
    for ax, d in zip(axes[0], diameters):
        us = sorted(r["U_s_m_s"] for r in rows if r["d_m"] == d)
        if len(us) < 2:
            continue
        fine = [us[0] * (us[-1] / us[0]) ** (i / 100) for i in range(101)]
        ax.loglog(fine, [ergun(u, d) for u in fine], "k-", label="Ergun (1952)")
        for law, m in zip(laws, ["o", "s", "^", "v", "d"]):
            sel = [r for r in rows if r["d_m"] == d and r["law"] == law]
            ax.loglog([r["U_s_m_s"] for r in sel], [r["dpL_sim_Pa_m"] for r in sel], m,
                      mfc="none", label=f"granairAirFoam, {law}")
        ax.set_xlabel("superficial air velocity $U_s$ [m/s]")
        ax.set_ylabel("pressure drop per length $\\Delta p/L$ [Pa/m]")
        ax.set_title(f"packed bed, d = {d*1e6:.0f} µm, ε = {EPS}")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


if __name__ == "__main__":
    main()
