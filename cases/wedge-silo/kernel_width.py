#!/usr/bin/python3
"""DEM-CFD's sensitivity to the Gaussian void-fraction kernel's width (issue 17):
the same fill, the same cells, the air run with the kernel's width times each
factor, and the dry run once; W, the outlet and above pressures and gradients
over the study's steady window.

    kernel_width.py [--size demo|study] [--b 10] [--factors 0.5 1 2] [--dry-w W] [--out DIR] [--results DIR]

Why: the two-fluid level's outlet dp/dz is checked against DEM-CFD's (within
20 %), and DEM-CFD's is a gradient of a void fraction smoothed over 1.6
parcel diameters (parameters.KERNEL_WIDTHS; the cells near the orifice are
as wide). If the reference moves with the smoothing, the target carries that
uncertainty. The cells stay (study.py makes them as wide as the kernel): only
couplingProperties' `width` changes.

--dry-w W: the dry rate [kg/s] from a committed reference of the same set-up
(e.g. reference-study-b10's b10_noair) instead of running it (~15 CPU-min
at study size).

Run folders in OUT (default build/kernel-width-<size>-b<b>; a finished run is
kept and read again); RESULTS/kernel_width.{md,csv} (default
cases/wedge-silo/reference-kernel-width/<size>-b<b>).
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "tools"))
import granair_cases as gc  # noqa: E402
import parameters as P  # noqa: E402
from study import MONITORS, steady_rates  # noqa: E402  (the figures a study run reports)


def study(a, *args):
    subprocess.run([sys.executable, os.path.join(HERE, "study.py"), "--size", a.size, "--b", str(a.b), "--np", "1",
                    "--jobs", "1", "--out", a.out] + list(args), check=True, stdout=subprocess.DEVNULL)


def run(d):
    """granairFoam in d once (a `done` file marks a finished run)."""
    if not os.path.exists(os.path.join(d, "done")):
        gc.runner.mesh(d, 1)
        cpu = gc.runner.run(["granairFoam"], d)
        with open(os.path.join(d, "done"), "w") as fh:
            fh.write(f"{cpu:.1f}\n")


def widened(src, d, factor):
    """A copy of the air run src with the kernel's width times factor (kept as it is
    once run); the width used [m]."""
    props = os.path.join(d, "constant", "couplingProperties")
    if os.path.exists(os.path.join(d, "done")):
        return float(_width(props).group(2))
    shutil.rmtree(d, ignore_errors=True)
    shutil.copytree(src, d)
    m = _width(props)
    width = float(m.group(2)) * factor
    with open(props, "w") as fh:
        fh.write(m.string[:m.start(2)] + f"{width:.9g}" + m.string[m.end(2):])
    return width


def _width(props):
    """The match of the voidFraction block's width in couplingProperties (group 2: the value)."""
    with open(props) as fh:
        m = re.search(r"(voidFraction\s*\{[^}]*\bwidth\s+)([^;\s]+)", fh.read())
    if not m:
        raise gc.CaseError(f"{props}: no voidFraction width")
    return m


def rates(d, air):
    """W over the steady window and, with air, the monitors' means there (study.py's)."""
    r = gc.powder.dem(d)
    out = steady_rates(r["t"], r["series"], air)
    out["window"] = f"{out['steady_from_s']:.3f}-{out['steady_to_s']:.3f}"
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--size", default="demo", choices=sorted(P.SIZES))
    ap.add_argument("--b", type=int, default=10, choices=[5, 10, 15])
    ap.add_argument("--factors", type=float, nargs="+", default=[0.5, 1.0, 2.0])
    ap.add_argument("--dry-w", type=float, default=None, help="dry rate [kg/s] from a reference, not run")
    ap.add_argument("--out", default=None)
    ap.add_argument("--results", default=None, help="default reference-kernel-width/<size>-b<b>")
    a = ap.parse_args()
    a.results = a.results or os.path.join(HERE, "reference-kernel-width", f"{a.size}-b{a.b}")
    if any(not f > 0 for f in a.factors):
        ap.error(f"--factors {a.factors}: expected factors > 0 of the kernel's width")
    build = os.environ.get("GRANAIR_BUILD", os.path.join(HERE, "..", "..", "build"))
    a.out = os.path.abspath(a.out or os.path.join(build, f"kernel-width-{a.size}-b{a.b}"))
    work = os.path.join(a.out, "runs", f"b{a.b}")
    if not os.path.exists(os.path.join(work, "fill", "dem", "fill.restart")):
        study(a, "--stage", "fill")
    if not (os.path.exists(os.path.join(work, "air")) and os.path.exists(os.path.join(work, "noair"))):
        study(a, "--stage", "runs", "--setup-only")
    if a.dry_w is None:
        run(os.path.join(work, "noair"))
        dry = rates(os.path.join(work, "noair"), air=False)
        dry["window"] += " s"
    else:
        dry = dict(W_kg_s=a.dry_w, window="given by --dry-w")
    print(f"kernel_width: dry W {dry['W_kg_s']:.4f} kg/s ({dry['window']})", flush=True)
    rows = []
    for f in a.factors:
        d = os.path.join(work, f"air_w{f:g}")
        width = widened(os.path.join(work, "air"), d, f)
        run(d)
        r = dict(factor=f, width_mm=1e3 * width, **rates(d, air=True))
        r["air_effect_pct"] = 100 * (r["W_kg_s"] / dry["W_kg_s"] - 1)
        rows.append(r)
        print(f"kernel_width: x{f:g} ({r['width_mm']:.3g} mm): W {r['W_kg_s']:.4f} kg/s ({r['air_effect_pct']:+.1f} %), "
              f"outlet dp/dz {r['outlet_dpdz_Pa_m']:.0f} Pa/m", flush=True)
    os.makedirs(a.results, exist_ok=True)
    cols = ["factor", "width_mm", "window", "W_kg_s", "air_effect_pct"] + list(MONITORS)
    gc.series.write_csv(os.path.join(a.results, "kernel_width.csv"), [(c, [r[c] for r in rows]) for c in cols],
                        ["{}" if c == "window" else "{:.6g}" for c in cols])
    lines = [f"# DEM-CFD against the void-fraction kernel's width ({a.size}, b = {a.b} mm)", "",
             f"`kernel_width.py --size {a.size} --b {a.b} --factors {' '.join(f'{f:g}' for f in a.factors)}"
             f"{f' --dry-w {a.dry_w:g}' if a.dry_w else ''}`: one fill, "
             f"the same cells; dry W {dry['W_kg_s']:.4f} kg/s ({dry['window']}).", "",
             "| width factor | width [mm] | W [kg/s] | air effect | outlet dp/dz [Pa/m] | outlet p [Pa] | "
             "p one b above [Pa] | dp/dz one b above [Pa/m] |", "|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        lines.append(f"| {r['factor']:g} | {r['width_mm']:.3g} | {r['W_kg_s']:.4f} | {r['air_effect_pct']:+.1f} % | "
                     f"{r['outlet_dpdz_Pa_m']:.0f} | {r['outlet_p_Pa']:.2f} | {r['above_p_Pa']:.2f} | "
                     f"{r['above_dpdz_Pa_m']:.0f} |")
    with open(os.path.join(a.results, "kernel_width.md"), "w") as fh:
        fh.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    gc.cli.main(main)
