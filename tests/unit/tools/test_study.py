#!/usr/bin/env python3
"""The case layer's study driver (tools/granair_cases/study.py) with stand-in
stages that record what was called: --setup-only sets up every stage and runs
none, --post-only post-processes the runs only, a study runs every fill before
any run (each stage's simulate only); a stage run once keeps its
record and runs again when its restart is gone; the options and their limits."""
import argparse
import contextlib
import io
import json
import os
import sys
import tempfile

from granair_cases import cli, study

failures = []


def expect(name, got, want):
    if got != want:
        failures.append(f"{name}: got {got!r}, expected {want!r}")


def stages(calls, prefix, n):
    """n stand-in stages: (name, setup, simulate, post) appending to calls."""
    def stage(k):
        name = f"{prefix}{k}"
        return (name, lambda: calls.append(("setup", name)), lambda: calls.append(("run", name)) or {"cpu_s": 0.0},
                lambda: calls.append(("post", name)) or name)
    return [stage(k) for k in range(n)]


def args(**kw):
    return argparse.Namespace(**dict(dict(setup_only=False, post_only=False, jobs=2, out="/nonexistent"), **kw))


quiet = contextlib.redirect_stdout(io.StringIO())
with quiet:
    calls = []
    expect("setup-only returns", study.drive(args(setup_only=True), "t", stages(calls, "f", 2), stages(calls, "r", 3)), None)
    expect("setup-only: every setup in order, nothing run", calls,
           [("setup", n) for n in ("f0", "f1", "r0", "r1", "r2")])

    calls = []
    done = study.drive(args(post_only=True), "t", stages(calls, "f", 2), stages(calls, "r", 3))
    expect("post-only: the runs' post only", sorted(calls), [("post", f"r{k}") for k in range(3)])
    expect("post-only results", done, {f"r{k}": f"r{k}" for k in range(3)})
    expect("post-only, runs without post()", study.drive(args(post_only=True), "t", [], [s[:3] for s in stages([], "r", 2)]), {})

    calls = []
    done = study.drive(args(jobs=2), "t", stages(calls, "f", 2), stages(calls, "r", 3))
    expect("every fill before any run", max(i for i, c in enumerate(calls) if c[1][0] == "f")
           < min(i for i, c in enumerate(calls) if c[1][0] == "r"), True)
    expect("a run: simulate only (it sets up what it needs)", sorted(c[0] for c in calls), ["run"] * 5)
    expect("the runs' results", sorted(done), ["r0", "r1", "r2"])

with tempfile.TemporaryDirectory() as tmp:
    path, restart = os.path.join(tmp, "fill", "log", "fill.json"), os.path.join(tmp, "fill.restart")
    ran = []

    def fill():
        ran.append(1)
        open(restart, "w").close()
        return dict(cpu_s=1.5)
    rec, now = study.once(path, fill, [restart])
    expect("once: first call runs", (len(ran), now, rec["cpu_s"], "wall_s" in rec), (1, True, 1.5, True))
    with open(path) as fh:
        expect("once: the record saved", json.load(fh), rec)
    rec2, now = study.once(path, fill, [restart])
    expect("once: a second call returns the record", (len(ran), now, rec2), (1, False, rec))
    os.remove(restart)
    study.once(path, fill, [restart])
    expect("once: runs again when its restart is gone", len(ran), 2)

    def parse(argv):
        ap = study.options(cli.parser("test"), fresh=True)
        with contextlib.redirect_stderr(io.StringIO()):
            try:
                return study.parse(ap, tmp, argv)
            except SystemExit as e:
                return e.code
    a = parse(["--jobs", "3", "--post-only", "--fresh"])
    expect("options", (a.jobs, a.post_only, a.fresh, a.np, a.out), (3, True, True, 1, tmp))
    expect("--np 2 refused (serial runs)", parse(["--np", "2"]), 2)
    expect("--jobs 0 refused", parse(["--jobs", "0"]), 2)

if failures:
    print("\n".join(failures))
    sys.exit(1)
print("study driver: all checks passed")
