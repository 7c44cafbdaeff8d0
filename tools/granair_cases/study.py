"""The driver of a study of many stand-alone LIGGGHTS runs (cases/corn-silo,
two-slot-silo, orifice-arch; docs/cases.md "A study of many runs"): the options,
a fill run once, the fills and runs --jobs at a time, --setup-only, --post-only."""
import json
import os
import time

from . import cli, runner


def options(ap, fresh=False, post_only=True):
    """The study options beyond gc.cli's: --jobs, --post-only, and --fresh if asked."""
    ap.add_argument("--jobs", type=int, default=2, help="LIGGGHTS runs at a time, one rank each (default 2)")
    if post_only:
        ap.add_argument("--post-only", action="store_true", help="post-process the finished runs, run nothing")
    if fresh:
        ap.add_argument("--fresh", action="store_true", help="start every run again (default: resume)")
    return ap


def parse(ap, default_out, argv=None):
    """gc.cli.parse, and the runs' limits: LIGGGHTS runs serially here (--np 1), --jobs >= 1."""
    a = cli.parse(ap, default_out, argv)
    if a.np != 1:
        ap.error(f"--np {a.np}: the runs are serial LIGGGHTS jobs, one rank each (use --jobs for more at a time)")
    if a.jobs < 1:
        ap.error(f"--jobs {a.jobs}: expected a whole number >= 1")
    return a


def once(path, fn, needs=()):
    """A stage run once (a fill): fn()'s dict (CPU s, what the study keeps) saved at path
    (JSON) with its wall_s; while path and the files of needs (its restart) exist, a later
    call returns that instead. Returns (dict, ran now)."""
    if os.path.exists(path) and all(os.path.exists(p) for p in needs):
        with open(path) as fh:
            return json.load(fh), False
    t0 = time.time()
    rec = dict(fn())
    rec.setdefault("wall_s", round(time.time() - t0, 1))
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w") as fh:
        json.dump(rec, fh, indent=1)
    return rec, True


def drive(a, label, fills, runs):
    """fills and runs: [(name, setup, simulate[, post])]. setup() writes the folder and
    runs nothing; simulate() sets up what has not started, runs what is left and returns
    its result (cpu_s in it for the pool's line); post() post-processes a finished run.
    --setup-only: every setup (returns None); --post-only: the runs' post(); else every
    fill, then every run, a.jobs at a time (gc.runner.pool). Returns {name: result}."""
    if a.setup_only:
        for stage in fills + runs:
            stage[1]()
        print(f"{label}: {len(fills) + len(runs)} folders written to {os.path.join(a.out, 'runs')}", flush=True)
        return None
    if a.post_only:
        return runner.pool([(s[0], s[3], ()) for s in runs if len(s) > 3 and s[3]], a.jobs, label)
    runner.pool([(s[0], s[2], ()) for s in fills], a.jobs, label)
    return runner.pool([(s[0], s[2], ()) for s in runs], a.jobs, label)
