"""Long granairFoam runs in chunks, each one continuing from the newest restart
point (docs/case-format.md, Restart), until the case says it is finished.

    latest_restart(case)            time of the newest complete restart point, or None
    run(case, chunk, finished, t_max, np=1)
                                    granairFoam chunk by chunk until finished(case)
                                    returns a reason (or t >= t_max); resumes a run
                                    that was stopped or killed; returns its record
    record(case)                    what log/chunks.json holds: chunks, CPU, reason

A killed run loses at most the time since its last field write: the next call
starts from the newest complete restart point (`coupling`, written last, marks
it complete) with `startFrom startTime; startTime <it>`, so a field folder
written after it is simply overwritten. Each chunk's log is kept as
log/granairFoam_<from>-<to>.log; log/granairFoam.log is the last one (its end
holds the accounting over the whole run: the restart carries the counts on).
A chunk in which every particle left ends the run (granairFoam stops there,
without a restart point, and says so in its log): reason "no particles left".
Older restart points are deleted (the newest two are kept): a point holds the
whole DEM state, and the fields stay in their time folders.
"""
import json
import math
import os
import shutil
import time

from . import CaseError, foam, runner


def _restart_times(case):
    d = os.path.join(case, "restart")
    if not os.path.isdir(d):
        return []
    out = []
    for name in os.listdir(d):
        try:
            t = float(name)
        except ValueError:
            continue
        if os.path.exists(os.path.join(d, name, "coupling")):
            out.append((t, name))
    return sorted(out)


def latest_restart(case):
    """(time, folder name) of the newest complete restart point, or None."""
    times = _restart_times(case)
    return times[-1] if times else None


def _prune(case, keep=2):
    for _, name in _restart_times(case)[:-keep]:
        shutil.rmtree(os.path.join(case, "restart", name), ignore_errors=True)


def _emptied(log):
    """The time granairFoam's log says every particle had left the DEM domain, or None."""
    key = "granairFoam: no particles left in the DEM domain at t = "
    with open(log, errors="replace") as fh:
        for line in fh:
            if line.startswith(key):
                return float(line[len(key):].split()[0])
    return None


def record(case):
    path = os.path.join(case, "log", "chunks.json")
    if os.path.exists(path):
        with open(path) as fh:
            return json.load(fh)
    return dict(chunks=[], reason=None)


def _save(case, rec):
    with open(os.path.join(case, "log", "chunks.json"), "w") as fh:
        json.dump(rec, fh, indent=1)


def run(case, chunk, finished, t_max, np=1, progress=print):
    """Run granairFoam in case (meshed, controlDict with startFrom/startTime/endTime)
    chunk [s] at a time until finished(case) gives a reason (a string) or the time
    reaches t_max; chunk must be a whole number of field write intervals (a chunk
    ends on a restart point). Returns the record: chunks [{from, to, cpu_s, wall_s}],
    cpu_s (all chunks, this and earlier calls), reason, t_end."""
    rec = record(case)
    if str(rec.get("reason")).startswith("t_max") and rec.get("t_end", t_max) < t_max - 1e-9:
        rec["reason"] = None            # stopped at an earlier t_max: go on to the new one
    control = os.path.join(case, "system", "controlDict")
    while rec.get("reason") is None:
        point = latest_restart(case)
        t0 = point[0] if point else 0.0
        if point and t0 >= t_max - 1e-9:
            rec["reason"], rec["t_end"] = f"t_max = {t_max:g} s", t0
            break
        t1 = min(t_max, (math.floor(t0 / chunk + 1e-6) + 1) * chunk)
        if point:
            foam.set_entry(control, "startFrom", "startTime")
            foam.set_entry(control, "startTime", point[1])
        foam.set_entry(control, "endTime", f"{t1:.10g}")
        last = os.path.join(case, "log", "granairFoam.log")
        progress(f"{os.path.basename(os.path.dirname(case))}/{os.path.basename(case)}: "
                 f"granairFoam {t0:g} -> {t1:g} s")
        start = time.time()
        cpu = runner.run(["granairFoam"], case, np=np)
        rec["chunks"].append({"from": t0, "to": t1, "cpu_s": cpu, "wall_s": time.time() - start})
        shutil.copyfile(last, os.path.join(case, "log", f"granairFoam_{t0:g}-{t1:g}.log"))
        got = latest_restart(case)
        emptied = _emptied(last)
        if emptied is not None:         # every particle left: a normal end (no restart point)
            rec["reason"], rec["t_end"] = f"no particles left at t = {emptied:g} s", emptied
            _save(case, rec)
            break
        if not got or got[0] < t1 - 1e-9:
            raise CaseError(f"{case}: granairFoam ended at t = {t1:g} s without a restart point there "
                            f"(is the chunk {chunk:g} s a whole number of write intervals?)")
        _prune(case)
        # judged right after a whole chunk (a killed chunk's rows past its restart point are not)
        why = finished(case)
        if why:
            rec["reason"], rec["t_end"] = why, got[0]
        _save(case, rec)
    rec["cpu_s"] = sum(c["cpu_s"] for c in rec["chunks"])
    _save(case, rec)
    return rec
