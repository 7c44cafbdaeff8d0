"""Long runs in chunks, each continuing from the restart the one before left:
one resumable loop for either program (docs/cases.md, "Long runs").

    loop(case, step, name)          the loop: step(rec) runs the next chunk and returns its
                                    entry, or a string (why the run is finished); resumes
    record(case, name)              log/<name>.json: the chunks run, CPU and wall s, the reason
    cost(case, name)                (CPU s, wall s, chunks) of the finished chunks
    foam(case, chunk, finished, t_max, np)
                                    granairFoam chunk [s] at a time from its newest restart
                                    point until finished(case) gives a reason or t_max
    liggghts(case, script, segments, first, name)
                                    stand-alone LIGGGHTS as segments, each from the previous
                                    one's write_restart (segments: a list, or a function)
    latest_restart(case)            granairFoam's newest complete restart point
    pack(case, path, skip) / unpack(path, case)
                                    a run's resumable state as one .tar.xz (a run folder is
                                    lost with the machine; the pack is committed) and back

The record is written after every chunk, so a stopped or killed run loses at
most the chunk in hand: the next call goes on after the last finished one.

granairFoam (docs/case-format.md, Restart): a chunk starts from the newest
complete restart point (`coupling`, written last, marks it complete) with
`startFrom startTime; startTime <it>`, so a field folder written after it is
simply overwritten. Each chunk's log is kept as log/granairFoam_<from>-<to>.log;
log/granairFoam.log is the last one (its end holds the accounting over the
whole run: the restart carries the counts on). Older restart points are deleted
(the newest two kept): a point holds the whole DEM state, the fields stay in
their time folders.
A chunk in which every particle left ends the run: granairFoam stops there
without a restart point and says so in its log; the reason is "no particles
left at t = ...".

LIGGGHTS: segment k = 1, 2, ... gets its values as `-var` plus seg = k,
restart_in (`first` for k = 1, else the restart of k - 1) and restart_out; the
script must end with `write_restart ${restart_out}`. The restart is written
under a temporary name and kept once LIGGGHTS ends without error; only the
newest is kept (restart/<name>_<k>.restart). Logs: log/<name>_<k>.log (the
command's output), log/<name>_<k>.liggghts (LIGGGHTS' log).
"""
import json
import math
import os
import shutil
import tarfile
import time

from . import CaseError, foam as _foam, runner


def _say(line):
    print(line, flush=True)


def record(case, name="chunks"):
    """What log/<name>.json holds: chunks [entries], reason (None while running).
    A run chained before the record existed has only restart/<name>_<k>.done
    markers: their entries (read, not saved), so cost() counts those runs too."""
    path = os.path.join(case, "log", name + ".json")
    if os.path.exists(path):
        with open(path) as fh:
            return json.load(fh)
    return dict(chunks=_marker_chunks(case, name), reason=None)


def _save(case, rec, name):
    os.makedirs(os.path.join(case, "log"), exist_ok=True)
    with open(os.path.join(case, "log", name + ".json"), "w") as fh:
        json.dump(rec, fh, indent=1)


def cost(case, name="chunks"):
    """(CPU seconds, wall seconds, number) of the finished chunks of a run."""
    chunks = record(case, name)["chunks"]
    return (sum(c["cpu_s"] for c in chunks), sum(c["wall_s"] for c in chunks), len(chunks))


def loop(case, step, name="chunks", after=None):
    """Run chunks until step says the run is finished. step(rec) runs the next
    chunk of the run recorded in rec and returns its entry (a dict with cpu_s
    and whatever the case keeps: times, counts; 'reason' in it ends the run
    after this chunk), or a string: the run is finished (nothing run). The wall
    time is added to the entry and rec saved after each chunk. Returns rec with
    cpu_s (all chunks, this call and earlier ones) and ran (chunks run now).
    after(rec), if given, is called once rec is saved after each chunk (nothing
    runs then: e.g. pack the folder)."""
    rec = record(case, name)
    ran = 0
    while True:
        t0 = time.time()
        got = step(rec)
        if isinstance(got, str):
            rec["reason"] = got
            break
        got["wall_s"] = time.time() - t0
        why = got.pop("reason", None)
        rec["chunks"].append(got)
        rec["reason"] = why
        ran += 1
        _save(case, rec, name)
        if after:
            after(rec)
        if why:
            break
    rec["cpu_s"] = sum(c["cpu_s"] for c in rec["chunks"])
    _save(case, rec, name)
    rec["ran"] = ran
    return rec


# ---- granairFoam ----

def _restart_times(case):
    d = os.path.join(case, "restart")
    out = []
    for name in os.listdir(d) if os.path.isdir(d) else []:
        try:
            t = float(name)
        except ValueError:
            continue
        if os.path.exists(os.path.join(d, name, "coupling")):
            out.append((t, name))
    return sorted(out)


def _emptied(log):
    """The time granairFoam's log says every particle had left the DEM domain, or None."""
    key = "granairFoam: no particles left in the DEM domain at t = "
    with open(log, errors="replace") as fh:
        for line in fh:
            if line.startswith(key):
                return float(line[len(key):].split()[0])
    return None


def latest_restart(case):
    """(time, folder name) of granairFoam's newest complete restart point, or None."""
    times = _restart_times(case)
    return times[-1] if times else None


def foam(case, chunk, finished, t_max, np=1, progress=_say, after=None):
    """granairFoam in case (meshed, controlDict with startFrom/startTime/endTime)
    chunk [s] at a time until finished(case) gives a reason (a string) or the time
    reaches t_max; chunk must be a whole number of field write intervals (a chunk
    ends on a restart point). A run stopped at an earlier t_max goes on to a later
    one. Returns the record (log/chunks.json): chunks [{from, to, cpu_s, wall_s}],
    cpu_s, reason, t_end. after: as for loop()."""
    control = os.path.join(case, "system", "controlDict")
    label = f"{os.path.basename(os.path.dirname(case))}/{os.path.basename(case)}"

    def step(rec):
        why = rec.get("reason")
        if why and not (why.startswith("t_max") and rec.get("t_end", t_max) < t_max - 1e-9):
            return why
        point = latest_restart(case)
        t0 = point[0] if point else 0.0
        if point and t0 >= t_max - 1e-9:
            rec["t_end"] = t0
            return f"t_max = {t_max:g} s"
        t1 = min(t_max, (math.floor(t0 / chunk + 1e-6) + 1) * chunk)
        if point:
            _foam.set_entry(control, "startFrom", "startTime")
            _foam.set_entry(control, "startTime", point[1])
        _foam.set_entry(control, "endTime", f"{t1:.10g}")
        progress(f"{label}: granairFoam {t0:g} -> {t1:g} s")
        cpu = runner.run(["granairFoam"], case, np=np)
        shutil.copyfile(os.path.join(case, "log", "granairFoam.log"),
                        os.path.join(case, "log", f"granairFoam_{t0:g}-{t1:g}.log"))
        got = latest_restart(case)
        emptied = _emptied(os.path.join(case, "log", "granairFoam.log"))
        if emptied is not None:         # every particle left: a normal end, no restart point
            rec["t_end"] = emptied
            return {"from": t0, "to": emptied, "cpu_s": cpu, "reason": f"no particles left at t = {emptied:g} s"}
        if not got or got[0] < t1 - 1e-9:
            raise CaseError(f"{case}: granairFoam ended at t = {t1:g} s without a restart point there "
                            f"(is the chunk {chunk:g} s a whole number of write intervals?)")
        for _, old in _restart_times(case)[:-2]:
            shutil.rmtree(os.path.join(case, "restart", old), ignore_errors=True)
        entry = {"from": t0, "to": t1, "cpu_s": cpu}
        # judged right after a whole chunk (a killed chunk's rows past its restart point are not)
        why = finished(case)
        if why:
            entry["reason"], rec["t_end"] = why, got[0]
        return entry

    return loop(case, step, "chunks", after)


# ---- packs ----

def pack(case, path, skip=()):
    """case's folder as one xz-compressed tar at path (replaced only once complete),
    without granairFoam's restart points but the newest complete one (it holds
    the whole DEM state; the fields, the time series and log/chunks.json are in
    the folder) and without the paths in skip (relative to case). Take it when
    nothing runs in case (loop's after, or a finished fill). Returns its size [B]."""
    newest = latest_restart(case)
    rdir = os.path.join(case, "restart")
    drop = {os.path.join("restart", n) for n in (os.listdir(rdir) if os.path.isdir(rdir) else [])
            if not newest or n != newest[1]} | {os.path.normpath(x) for x in skip}
    root = os.path.basename(os.path.normpath(case))

    def keep(info):
        rel = os.path.normpath(os.path.relpath(info.name, root))
        return None if rel in drop else info

    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with tarfile.open(path + ".part", "w:xz") as tar:
        tar.add(case, arcname=root, filter=keep)
    os.replace(path + ".part", path)
    return os.path.getsize(path)


def unpack(path, case):
    """A pack(...) file back as the folder case (which must not exist yet: a
    folder with state of its own is never overwritten)."""
    if os.path.exists(case):
        raise CaseError(f"{case}: exists; not unpacking {path} over it (remove it to resume from the pack)")
    parent = os.path.dirname(os.path.abspath(case))
    tmp = os.path.join(parent, ".unpack-" + os.path.basename(case))
    shutil.rmtree(tmp, ignore_errors=True)
    with tarfile.open(path) as tar:
        roots = {m.name.split("/")[0] for m in tar.getmembers()}
        if len(roots) != 1 or any(m.name.startswith("/") or ".." in m.name.split("/") for m in tar.getmembers()):
            raise CaseError(f"{path}: expected one folder of relative paths (a pack of gc.chunks.pack)")
        tar.extractall(tmp, **({"filter": "data"} if hasattr(tarfile, "data_filter") else {}))
    os.replace(os.path.join(tmp, roots.pop()), case)
    os.rmdir(tmp)


# ---- LIGGGHTS ----

def liggghts(case, script, segments, first, name="segment", label="granair", collect=None, progress=_say):
    """The stand-alone LIGGGHTS `script` in `case` as segments (module doc).
    segments: a list of dicts (LIGGGHTS variables per segment; a longer list
    later goes on after the last finished one), or a function (k, rec) -> dict,
    or None when the run is finished (it sees the entries of the finished
    segments and may prepare the folder, e.g. remove what a killed segment
    wrote). collect(case, k), if given, returns what to keep in segment k's
    entry (counts read from its outputs). Returns the record (log/<name>.json):
    chunks [{k, cpu_s, wall_s, ...}], cpu_s, ran."""
    rdir = os.path.join(case, "restart")
    os.makedirs(rdir, exist_ok=True)
    restart = lambda k: os.path.join("restart", f"{name}_{k}.restart")       # noqa: E731
    t_start = time.time()

    def step(rec):
        k = len(rec["chunks"]) + 1
        values = segments(k, rec) if callable(segments) else (segments[k - 1] if k <= len(segments) else None)
        if values is None:
            return f"{k - 1} segments"
        src = first if k == 1 else restart(k - 1)
        if not os.path.exists(os.path.join(case, src)):
            raise CaseError(f"{case}: segment {k} needs the restart {src}, which does not exist "
                            f"(a finished segment's restart was removed: run again from a clean folder)")
        tmp = restart(k) + ".part"
        cpu = runner.liggghts(case, script, f"{name}_{k}", var=dict(values, seg=k, restart_in=src, restart_out=tmp))
        if not os.path.exists(os.path.join(case, tmp)):
            raise CaseError(f"{case}: segment {k} ended without writing {tmp} (does {script} end with "
                            f"`write_restart ${{restart_out}}`?)")
        os.replace(os.path.join(case, tmp), os.path.join(case, restart(k)))
        if k > 1 and os.path.exists(os.path.join(case, restart(k - 1))):
            os.remove(os.path.join(case, restart(k - 1)))
        entry = dict(k=k, cpu_s=cpu, **(collect(case, k) if collect else {}))
        of = "" if callable(segments) else f"/{len(segments)}"
        progress(f"{label}: segment {k}{of} done ({cpu:.0f} CPU-s, {time.time() - t_start:.0f} s since start)")
        return entry

    _markers(case, name)
    return loop(case, step, name)


def _markers(case, name):
    """A chain run before the record existed left restart/<name>_<k>.done markers
    (`key = value` lines): their segments become the record's entries."""
    if os.path.exists(os.path.join(case, "log", name + ".json")):
        return
    chunks = _marker_chunks(case, name)
    if chunks:
        _save(case, dict(chunks=chunks, reason=None), name)


def _marker_chunks(case, name):
    """The entries of the old restart/<name>_<k>.done markers (`key = value` lines)."""
    rdir = os.path.join(case, "restart")
    chunks = []
    while os.path.exists(os.path.join(rdir, f"{name}_{len(chunks) + 1}.done")):
        with open(os.path.join(rdir, f"{name}_{len(chunks) + 1}.done")) as fh:
            kv = dict(line.split(" = ") for line in fh.read().splitlines() if " = " in line)
        chunks.append(dict(k=len(chunks) + 1, cpu_s=float(kv["cpu_s"]), wall_s=float(kv["wall_s"])))
    return chunks
