#!/usr/bin/python3
"""bench/wedge/run.py: the speed targets on the real case, the wedge silo
(cases/wedge-silo), as ratios measured in one run.

    bench/wedge/run.py [--size demo|study] [--b 10] [--np 1] [--t-end 0.3] [--repeat 2]
                       [--configs noair forces-off air] [--full-depth] [--cfd-dt DT] [--work DIR] [--name NAME]

One fill (study.py --stage fill, kept in WORK and reused), then the
discharge from it --repeat times in each configuration, the configurations
of a repeat back to back (so they see the same load), each for --t-end s:
`noair` (DEM only: `air off;`), `forces-off` (the air run with
`forces { applied off; }`: every part of the coupling computed, zeros
stored, so the DEM runs exactly the DEM-only problem) and `air` (coupled).
Reported from each configuration's fastest repeat (granairFoam's own end
report): coupled / DEM-only and forces-off / DEM-only throughput
(particle-steps per second of the coupling loop, wall and CPU), the mapping
+ exchange share of the loop, the DEM's cost per particle-step, the coupling
buffers; into bench/results/NAME.{md,csv} (default wedge-<size>-np<np>).

--full-depth: the silo's whole 60 mm depth between walls instead of the
periodic slice (study.py --full-depth: about 12x the parcels, a 3-D air mesh
11 cells deep; default name wedge-<size>-full-depth-np<np>).

--cfd-dt: the air's (coupling) time step of the runs (study.py --cfd-dt);
the case's 5e-4 s is ~26 DEM steps, 1e-3 s the guide's coupling interval
of ~50 at which its speed targets are stated. The report gives the interval.

--contacts adds one untimed run of `noair` and `air` whose LIGGGHTS script
also sums `compute contact/atom` (printed with thermo at every coupling
step, which is why these runs are not timed): the mean number of contacts
per particle, what the pair kernels' work grows with. The air holds the bed
back, so the coupled run is a different granular problem than DEM only; this
is the measure of how different.
"""
import argparse
import csv
import os
import shutil
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(HERE, "..", "coupled"))
from parse_log import parse_log  # noqa: E402  (bench/coupled's reader of granairFoam's report)

import granair_cases as gc  # noqa: E402

STUDY = os.path.join(ROOT, "cases", "wedge-silo", "study.py")
CONFIGS = ("noair", "forces-off", "air")
# The contact count for --contacts: LIGGGHTS' per-atom contacts, summed, with the thermo output.
CONTACTS = ("compute granairContacts all contact/atom\n"
            "compute granairContactSum all reduce sum c_granairContacts\n"
            "thermo_style    custom step atoms c_granairContactSum\n")


def study(a, *args):
    """cases/wedge-silo/study.py with this benchmark's size, width and ranks."""
    cmd = [sys.executable, STUDY, "--size", a.size, "--b", str(a.b), "--np", str(a.np), "--jobs", "1",
           "--out", a.work] + (["--full-depth"] if a.full_depth else []) + list(args)
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL)


def prepare(a):
    """The fill (once) and fresh run folders of both kinds."""
    fill = os.path.join(a.work, "runs", f"b{a.b}", "fill", "dem", "fill.restart")
    if not os.path.exists(fill):
        print(f"bench/wedge: fill at size {a.size}, b = {a.b} mm", flush=True)
        study(a, "--stage", "fill")
    # the fill is the same at every air step (a DEM-only settling); --cfd-dt sets the runs'
    study(a, "--stage", "runs", "--setup-only", "--t-end", str(a.t_end),
          *(["--cfd-dt", f"{a.cfd_dt:g}"] if a.cfd_dt else []))


def coupling_interval(a):
    """The DEM steps per air step of the prepared air run (its couplingProperties)."""
    return int(gc.foam.read_entry(os.path.join(a.work, "runs", f"b{a.b}", "air", "constant", "couplingProperties"),
                                  "couplingInterval"))


def run_one(a, config, repeat, contacts=False):
    """One discharge run of a configuration; its granairFoam report (with
    contacts: the mean contacts per particle over the thermo lines too)."""
    src = os.path.join(a.work, "runs", f"b{a.b}", "noair" if config == "noair" else "air")
    d = os.path.join(a.work, "runs", f"b{a.b}", f"{config}_{repeat}")
    shutil.rmtree(d, ignore_errors=True)
    shutil.copytree(src, d)
    if contacts:
        script = os.path.join(d, "dem", "in.liggghts")
        with open(script) as fh:
            text = fh.read()
        start = text.index("thermo_style")
        with open(script, "w") as fh:
            fh.write(text[:start] + CONTACTS + text[text.index("\n", start) + 1:])
    if config == "forces-off":
        props = os.path.join(d, "constant", "couplingProperties")
        with open(props) as fh:
            text = fh.read()
        if "forces " not in text:
            raise gc.CaseError(f"{props}: no forces entry to switch off")
        with open(props, "w") as fh:
            fh.write(_forces_off(text))
    gc.runner.mesh(d, a.np)
    gc.runner.run(["granairFoam"], d, np=a.np)
    r = parse_log(os.path.join(d, "log", "granairFoam.log"))
    if contacts:
        r["contacts_per_particle"] = contacts_per_particle(os.path.join(d, "log", "log.liggghts"))
        print(f"bench/wedge: {config}: {r['contacts_per_particle']:.3f} contacts per particle", flush=True)
        return r
    print(f"bench/wedge: {config} repeat {repeat}: loop {r['loop_s']:.2f} s, {r['throughput']:.4g} particle-steps/s",
          flush=True)
    return r


def contacts_per_particle(log):
    """Mean over the thermo lines of a LIGGGHTS log (step, atoms, contact sum; each step once) of
    contacts per particle (every contact counted for both its particles, as contact/atom does)."""
    steps = {}
    with open(log, errors="replace") as fh:
        for line in fh:
            f = line.split()
            if len(f) == 3 and f[0].isdigit() and f[1].isdigit():
                steps[int(f[0])] = (int(f[1]), float(f[2]))
    if not steps:
        raise gc.CaseError(f"{log}: no thermo lines with the contact sum")
    return sum(n for _, n in steps.values()) / sum(p for p, _ in steps.values())


def _forces_off(text):
    """couplingProperties with `applied off;` added to its forces entry."""
    start = text.index("forces ")
    brace = text.index("{", start)
    return text[:brace + 1] + " applied off;" + text[brace + 1:]


def share(r):
    """Mapping + exchange, share of the coupling loop: wall and CPU."""
    return ((r["mapping_s"] + r["exchange_s"]) / r["loop_s"],
            (r["cpu_mapping_s"] + r["cpu_exchange_s"]) / r["cpu_max_s"])


def per_repeat(runs, c):
    """The wall-throughput ratio c / noair of each repeat (its configurations ran back to back, so they saw
    about the same load) and their median: less swayed by a slow spell than the ratio of the fastest runs."""
    pairs = [r["throughput"] / n["throughput"] for r, n in zip(runs[c], runs["noair"])]
    if len(pairs) < 2:
        return ""
    return f"; per repeat {', '.join(f'{x:.3f}' for x in pairs)}, median **{statistics.median(pairs):.3f}**"


def report(a, runs, load, counts):
    best = {c: min(rs, key=lambda r: r["loop_s"]) for c, rs in runs.items()}
    rows, lines = [], [
        f"# Wedge silo ({a.size}, b = {a.b} mm, {'full 60 mm depth, ' if a.full_depth else ''}{a.np} rank(s)): "
        "the speed targets on the real case",
        "",
        f"Written by `bench/wedge/run.py --size {a.size} --b {a.b} --np {a.np} --t-end {a.t_end:g} --repeat {a.repeat}"
        f"{' --configs ' + ' '.join(a.configs) if list(a.configs) != list(CONFIGS) else ''}"
        f"{' --full-depth' if a.full_depth else ''}{f' --cfd-dt {a.cfd_dt:g}' if a.cfd_dt else ''}` "
        "(see its docstring and bench/README.md): one settled fill, then the first "
        f"{a.t_end:g} s of the discharge in each configuration, the fastest of {a.repeat} repeat(s) shown (slowest in "
        "brackets). `forces-off` is the air run with `forces { applied off; }`: every part of the coupling computed "
        "and zeros stored, so its DEM runs exactly the DEM-only problem.",
        "",
        f"Machine: {load}",
        "",
        "| config | loop s | particle-steps | Mps/s (wall) | DEM s | DEM ns per particle-step | CFD s | "
        "void fraction + mapping s | exchange s | mapping + exchange, wall / CPU | B/particle | B/cell |",
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for c in a.configs:
        r, slow = best[c], max(runs[c], key=lambda r: r["loop_s"])
        w, cpu = share(r)
        lines.append(f"| {c} | {r['loop_s']:.2f} ({slow['loop_s']:.2f}) | {r['particle_steps']:.4g} | "
                     f"{r['throughput'] / 1e6:.3f} | {r['dem_s']:.2f} | {1e9 * r['dem_s'] / r['particle_steps']:.0f} | "
                     f"{r['cfd_s']:.2f} | {r['mapping_s']:.2f} | {r['exchange_s']:.2f} | {100 * w:.2f} % / "
                     f"{100 * cpu:.2f} % | {r['buf_per_particle']:.1f} | {r['buf_per_cell']:.1f} |")
        rows.append(dict(config=c, **{k: r[k] for k in sorted(r)}))
    lines.append("")

    def ratio(c, key):
        return best[c][key] / best["noair"][key]

    if "noair" in best:
        for c, what in (("air", "coupled / DEM-only throughput (target >= 0.90)"),
                        ("forces-off", "forces-off / DEM-only throughput: the coupling's own cost on the same DEM "
                                       "problem")):
            if c in best:
                lines.append(f"- {what}: **{ratio(c, 'throughput'):.3f}** by wall time, "
                             f"{(best[c]['particle_steps'] / best[c]['cpu_max_s']) / (best['noair']['particle_steps'] / best['noair']['cpu_max_s']):.3f} "
                             f"by CPU time; DEM time per particle-step {ratio(c, 'dem_s') / ratio(c, 'particle_steps'):.3f}x DEM-only's"
                             + per_repeat(runs, c))
    if counts:
        z = {c: r["contacts_per_particle"] for c, r in counts.items()}
        lines.append("- contacts per particle (untimed runs, the mean over every coupling step): "
                     + ", ".join(f"{c} {v:.3f}" for c, v in z.items())
                     + (f"; air / noair {z['air'] / z['noair']:.3f}" if len(z) == 2 else ""))
    for c in ("air", "forces-off"):
        if c in best:
            w, cpu = share(best[c])
            lines.append(f"- mapping + exchange, {c}: **{100 * w:.2f} %** of the loop's wall time, {100 * cpu:.2f} % of "
                         f"its CPU (target <= 2 %)")
    os.makedirs(a.results, exist_ok=True)
    with open(os.path.join(a.results, a.name + ".md"), "w") as fh:
        fh.write("\n".join(lines) + "\n")
    keys = sorted({k for row in rows for k in row})
    with open(os.path.join(a.results, a.name + ".csv"), "w", newline="") as fh:
        w = csv.DictWriter(fh, keys)
        w.writeheader()
        w.writerows(rows)
    print("\n".join(lines))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--size", default="demo", choices=["demo", "study"])
    ap.add_argument("--b", type=int, default=10, choices=[5, 10, 15])
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--t-end", type=float, default=0.3, help="discharge time of each run [s]")
    ap.add_argument("--repeat", type=int, default=2)
    ap.add_argument("--cfd-dt", type=float, default=None,
                    help="the air's (coupling) step [s]: default the case's 5e-4 (interval ~26); 1e-3 gives the "
                         "guide's interval of ~50 (study.py --cfd-dt)")
    ap.add_argument("--configs", nargs="+", default=list(CONFIGS), choices=CONFIGS)
    ap.add_argument("--work", default=None, help="work folder (default build/bench-wedge-<size>[-full-depth])")
    ap.add_argument("--contacts", action="store_true", help="also count the contacts (untimed runs)")
    ap.add_argument("--full-depth", action="store_true",
                    help="the silo's whole depth between walls, not the periodic slice (study.py --full-depth)")
    ap.add_argument("--results", default=os.path.join(ROOT, "bench", "results"))
    ap.add_argument("--name", default=None, help="results file name (default wedge-<size>[-full-depth]-np<np>)")
    a = ap.parse_args()
    build = os.environ.get("GRANAIR_BUILD", os.path.join(ROOT, "build"))
    depth = "-full-depth" if a.full_depth else ""
    a.work = os.path.abspath(a.work or os.path.join(build, f"bench-wedge-{a.size}{depth}"))
    if a.cfd_dt is not None and not a.cfd_dt > 0:
        ap.error(f"--cfd-dt {a.cfd_dt:g}: expected the air's time step > 0 [s]")
    a.name = a.name or f"wedge-{a.size}{depth}-np{a.np}" + (f"-cfd-dt{a.cfd_dt:g}" if a.cfd_dt else "")
    load = f"{time.strftime('%Y-%m-%dT%H:%MZ', time.gmtime())}, {os.cpu_count()} cores, load average at start " \
           f"{' '.join(open('/proc/loadavg').read().split()[:3])}"
    prepare(a)
    load += f"; coupling interval {coupling_interval(a)} DEM steps per air step"
    runs = {c: [] for c in a.configs}
    for k in range(1, a.repeat + 1):
        for c in a.configs:
            runs[c].append(run_one(a, c, k))
    load += f", at end {' '.join(open('/proc/loadavg').read().split()[:3])}"
    counts = {c: run_one(a, c, "contacts", contacts=True) for c in ("noair", "air")} if a.contacts else {}
    report(a, runs, load, counts)


if __name__ == "__main__":
    gc.cli.main(main)
