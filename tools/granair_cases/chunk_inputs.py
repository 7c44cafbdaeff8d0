"""A LIGGGHTS run written as one input per chunk, dem/in.chunk_<k> (each from the restart
the one before wrote), and run in turn through gc.chunks.loop, so a stopped study resumes
at the chunk it was in (cases/two-slot-silo). Why here: where gc.chunks.liggghts passes
one script its chunk's values as -var, this keeps each chunk's input a plain file to
read and run by hand (`--setup-only`), a layout in whole output intervals, and the
fill the chunks start from run once.

    chunks = layout(t_run, t_chunk, interval, per_interval, snapshots=0)   [(k, steps, last)]
    write(run, text, chunks, values, first_restart, where, extra=None)     dem/in.chunk_<k>
    setup, simulate = stage(run, chunks, setup, progress)                 the chunks in turn
    setup, simulate = once(folder, setup, script, restart)                a fill, run once
    cost(run) / finished(run, chunks)                                     the finished chunks
    r = post_once(path, run, fn)                                          a run's post-processing, kept
    d = kept(saved, source, measure, note)                                a run file's measure, kept for a checkout
"""
import json
import os

from . import chunks as chunk_loop, runner, study, template

NAME = "discharge"      # the record: log/discharge.json (gc.chunks)


def layout(t_run, t_chunk, interval, per_interval, snapshots=0):
    """[(index, steps, last)]: t_run in about t_chunk long chunks of whole output
    intervals (per_interval steps each), then, with snapshots > 0, one chunk of
    (snapshots - 1) intervals plus one step that writes them (the first at its start,
    the last inside the run): last = True for it."""
    total = round(t_run / interval)
    n = max(1, round(t_run / t_chunk))
    edges = [round(total * k / n) for k in range(n + 1)]
    out = [(k, (edges[k + 1] - edges[k]) * per_interval, False) for k in range(n)]
    if snapshots:
        out.append((n, (snapshots - 1) * per_interval + 1, True))
    return out


def write(run, text, chunks, values, first_restart, where, extra=None):
    """dem/in.chunk_<k> of every chunk from the template text: values and CHUNK, N_STEPS,
    T_CHUNK (N_STEPS x DEM_DT), RESTART_IN (first_restart, relative to run, then the
    chunk before's), RESTART_OUT, CG_EVERY (SNAP_STEPS in the last chunk of a layout
    with snapshots, else 0) and extra(k)'s."""
    for k, steps, cg in chunks:
        restart_in = os.path.relpath(first_restart, run) if k == 0 else f"dem/chunk_{k - 1}.restart"
        cv = dict(values, CHUNK=k, N_STEPS=steps, T_CHUNK=steps * values["DEM_DT"], RESTART_IN=restart_in,
                  RESTART_OUT=f"dem/chunk_{k}.restart", CG_EVERY=values["SNAP_STEPS"] if cg else 0,
                  **(extra(k) if extra else {}))
        template.write(os.path.join(run, "dem", f"in.chunk_{k}"), template.fill(text, cv, f"{where} ({k})"))


def record_file(run, legacy="cost.json"):
    """What marks a run's progress: log/discharge.json (gc.chunks), or `legacy` in a run
    of an older study that kept its chunks' costs in one file."""
    new, old = os.path.join(run, "log", f"{NAME}.json"), os.path.join(run, legacy)
    return old if os.path.exists(old) and not os.path.exists(new) else new


def cost(run):
    """{chunk_<k>: {cpu_s, wall_s, steps, cg}} of a run's finished chunks."""
    if not record_file(run).endswith(f"{NAME}.json"):
        with open(record_file(run)) as fh:
            return json.load(fh)
    return {f"chunk_{c['k']}": dict(cpu_s=c["cpu_s"], wall_s=round(c["wall_s"], 1), steps=c["steps"], cg=c["cg"])
            for c in chunk_loop.record(run, NAME)["chunks"]}


def finished(run, chunks):
    return f"chunk_{chunks[-1][0]}" in cost(run)


def post_once(path, run, fn):
    """A finished run's post-processing: fn()'s dict saved at path (JSON), or the saved
    one while it is newer than the run's record (a chunk run since makes it again)."""
    if os.path.exists(path) and os.path.getmtime(path) >= os.path.getmtime(record_file(run)):
        with open(path) as fh:
            return json.load(fh)
    r = fn()
    with open(path, "w") as fh:
        json.dump(r, fh, indent=1)
    return r


def kept(saved, source, measure, note):
    """measure()'s dict while the run file `source` exists, then also written to `saved` (a
    small JSON committed with the results, `source`: note); from `saved` once the run
    folders are gone (a clean checkout's --post-only); None if neither exists."""
    if os.path.exists(source):
        d = dict(measure(), source=note)
        template.write(saved, json.dumps(d, indent=1) + "\n")
        return d
    if os.path.exists(saved):
        with open(saved) as fh:
            return json.load(fh)
    return None


def stage(run, chunks, setup, progress=print):
    """(setup, simulate) of a run in chunks (gc.study.drive): setup() writes the folder
    (cleaned first); simulate() writes it unless a chunk has run, runs the chunks left
    (each `gc.runner.liggghts(run, dem/in.chunk_<k>, chunk_<k>)`, the restart two chunks
    back removed) and returns cost()."""
    def write_folder():
        setup(runner.clean(run))

    def step(rec):
        if len(rec["chunks"]) == len(chunks):
            return f"{len(rec['chunks'])} chunks"
        k, steps, cg = chunks[len(rec["chunks"])]
        cpu = runner.liggghts(run, f"dem/in.chunk_{k}", f"chunk_{k}")
        if os.path.exists(os.path.join(run, "dem", f"chunk_{k - 2}.restart")):
            os.remove(os.path.join(run, "dem", f"chunk_{k - 2}.restart"))      # no longer needed
        progress(f"{os.path.basename(run)}: chunk {k} done, {cpu:.0f} s CPU")
        return dict(k=k, cpu_s=round(cpu, 1), steps=steps, cg=cg)

    def simulate():
        if not os.path.exists(record_file(run)):
            write_folder()
        if not finished(run, chunks):        # (the record untouched: a newer post-processing is kept)
            chunk_loop.loop(run, step, NAME)
        return cost(run)
    return write_folder, simulate


def once(folder, setup, script="dem/in.fill", restart="dem/fill.restart"):
    """(setup, simulate) of a stage run once, a fill (gc.study.once: folder/cost.json and
    its restart): setup(folder) writes the cleaned folder; simulate() writes and runs it
    (`gc.runner.liggghts(folder, script, "fill")`) unless both exist, returning {cpu_s, wall_s}."""
    def write_folder():
        setup(runner.clean(folder))

    def run():
        write_folder()
        return {"cpu_s": round(runner.liggghts(folder, script, "fill"), 1)}
    return write_folder, lambda: study.once(os.path.join(folder, "cost.json"), run, [os.path.join(folder, restart)])[0]
