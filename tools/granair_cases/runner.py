"""Running the steps of a case: one log per step, mpirun, CPU times, a job pool.

    run(["blockMesh"], case, "blockMesh")           -> CPU seconds of the step
    run(["granairFoam"], case, np=2)                 mpirun -np 2 granairFoam -parallel
    mesh(case, np)                                   blockMesh (+ decomposePar for np > 1)
    pool([(name, fn, args), ...], jobs)              independent jobs, a line per finished one
    liggghts(case, "dem/in.fill", "fill")            a stand-alone LIGGGHTS stage (its log and screen in log/)
    run(cmd, case, stop_when=done)                   stop an OpenFOAM run (stopAt writeNow) once done()

Every step writes case/log/<name>.log; a failure raises CaseError with the
command, the folder and the last lines of its log. CPU time is user + system
of the step and all it waited for: a cost that does not depend on how busy a
shared machine is, unlike wall time.
"""
import concurrent.futures
import os
import shutil
import subprocess
import time

from . import CaseError, foam

TAIL = 25


def mpi(cmd, np=1, parallel=True):
    """cmd under `mpirun -np np` (with OpenFOAM's -parallel unless parallel=False)."""
    if np <= 1:
        return list(cmd)
    # A waiting rank yields its core instead of spinning: on a shared machine a
    # spinning rank takes the CPU its partner needs (LIGGGHTS synchronises
    # every step); on an idle machine yielding costs next to nothing.
    os.environ.setdefault("OMPI_MCA_mpi_yield_when_idle", "1")
    return ["mpirun", "-np", str(np)] + list(cmd) + (["-parallel"] if parallel else [])


def _tail(path):
    with open(path, errors="replace") as fh:
        return "".join(fh.readlines()[-TAIL:])


def run(cmd, cwd, log=None, np=1, parallel=True, stop_when=None, poll=1.0):
    """Run cmd (a list) in cwd with its output in cwd/log/<log>.log (log: the
    program's name by default); under mpirun when np > 1. With stop_when (a
    function of nothing), an OpenFOAM run is stopped once it returns true:
    `stopAt writeNow` in its controlDict (which must have runTimeModifiable
    yes), so it writes its fields and ends. Returns the CPU seconds it used."""
    cmd = mpi(cmd, np, parallel)
    log = log or os.path.basename(cmd[3] if np > 1 else cmd[0])
    os.makedirs(os.path.join(cwd, "log"), exist_ok=True)
    path = os.path.join(cwd, "log", log + ".log")
    control = os.path.join(cwd, "system", "controlDict")
    with open(path, "w") as fh:
        try:
            # PWD must match cwd, or OpenFOAM warns that it does not
            proc = subprocess.Popen(cmd, cwd=cwd, stdout=fh, stderr=subprocess.STDOUT,
                                    env=dict(os.environ, PWD=os.path.abspath(cwd)))
        except OSError as e:
            raise CaseError(f"{cmd[0]}: cannot start ({e.strerror}); is the environment set "
                            f"(./granair exec, or run the case's Allrun)?")
        stopped = 0
        while True:
            pid, status, usage = os.wait4(proc.pid, 0 if stop_when is None else os.WNOHANG)
            if pid:
                break
            time.sleep(poll)
            if stopped:
                # OpenFOAM re-reads a modified controlDict by its time stamp;
                # once (of eight runs) it missed the change: touch it again.
                stopped += 1
                if stopped % 5 == 0:
                    os.utime(control)
            elif stop_when():
                foam.set_entry(control, "stopAt", "writeNow")
                stopped = 1
    proc.returncode = code = os.waitstatus_to_exitcode(status)
    if code != 0:
        raise CaseError(f"'{' '.join(cmd)}' failed in {cwd} (exit {code}); last lines of {path}:\n"
                        + _tail(path))
    return usage.ru_utime + usage.ru_stime


def liggghts(case, script, step, log=None, screen=None, np=1, var=()):
    """A stand-alone LIGGGHTS stage: `liggghts -in script -log <log> -screen <screen>` in
    case, LIGGGHTS' log at `log` (default log/<step>.liggghts), its screen output at
    `screen` (default log/<step>.screen; False: into the step's log, log/<step>.log),
    `-var name value` for each item of var (a dict or pairs); under mpirun for np > 1.
    Returns the CPU seconds."""
    cmd = ["liggghts", "-in", script, "-log", log or f"log/{step}.liggghts"]
    if screen is not False:
        cmd += ["-screen", screen or f"log/{step}.screen"]
    for key, value in (var.items() if isinstance(var, dict) else var):
        cmd += ["-var", str(key), str(value)]
    return run(cmd, case, step, np=np, parallel=False)


def clean(path):
    """An empty folder at path (a study's runs start from nothing)."""
    shutil.rmtree(path, ignore_errors=True)
    os.makedirs(path)
    return path


def decompose(case, np):
    """decomposePar into np subdomains (numberOfSubdomains set to np); nothing for np = 1."""
    if np > 1:
        foam.set_entry(os.path.join(case, "system", "decomposeParDict"), "numberOfSubdomains", np)
        run(["decomposePar", "-force"], case, "decomposePar")


def mesh(case, np=1):
    """blockMesh, and decomposePar for np > 1."""
    run(["blockMesh"], case, "blockMesh")
    decompose(case, np)


def pool(tasks, jobs, label="granair"):
    """Run tasks [(name, fn, args)] with at most `jobs` at a time, re-raising
    the first failure; prints a line per finished task. Returns
    {name: result}. A task's result, if a dict, may carry 'cpu_s'."""
    t0 = time.time()
    results = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, jobs)) as ex:
        futures = {ex.submit(fn, *args): (name, time.time()) for name, fn, args in tasks}
        for k, f in enumerate(concurrent.futures.as_completed(futures), 1):
            name, started = futures[f]
            results[name] = r = f.result()
            cpu = f", {r['cpu_s']:.0f} s CPU" if isinstance(r, dict) and "cpu_s" in r else ""
            print(f"{label}: [{k}/{len(futures)}] {name} done{cpu} ({time.time() - t0:.0f} s since start)",
                  flush=True)
    return results
