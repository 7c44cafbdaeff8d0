"""parse_log.py: the numbers granairFoam prints at the end of a run (timing
breakdown, coupling loop, peak memory, coupling buffers), read from its log.
Shared by bench/coupled/report.py and bench/memory/report.py."""

import re

STAGES = {
    "DEM (LIGGGHTS)": "dem_s",
    "CFD (air solver)": "cfd_s",
    "void fraction + mapping": "mapping_s",
    "exchange (MPI)": "exchange_s",
    "output": "output_s",
    "other (setup, waits)": "other_s",
    "total wall time": "total_s",
}

_NUM = r"([-+0-9.eE]+)"


def parse_log(path):
    """Dict of the figures in a granairFoam log; raises ValueError naming
    the log and the line that is missing."""
    with open(path, errors="replace") as f:
        text = f.read()
    out = {}
    for label, key in STAGES.items():
        m = re.search(r"^\s+" + re.escape(label) + r"\s+" + _NUM + r" s", text, re.M)
        if not m:
            raise ValueError(f"{path}: no timing line '{label}' (did the run finish?)")
        out[key] = float(m.group(1))
        # CPU time of the stage (max over ranks), where the log has it.
        m = re.search(r"^\s+" + re.escape(label) + r"\s+" + _NUM + r" s(?:\s+" + _NUM + r" %)?\s+cpu\s+" + _NUM +
                      r" s", text, re.M)
        out["cpu_" + key] = float(m.group(3)) if m else float("nan")
    # the summary lines: (pattern, the line's name for the error, the keys of its numbers, their types)
    for pattern, what, keys in (
            (r"Coupling loop: " + _NUM + r" s wall for (\d+) coupling steps, " + _NUM + r" particle-steps, " + _NUM +
             r" particle-steps/s", "Coupling loop:", (("loop_s", float), ("coupling_steps", int),
                                                      ("particle_steps", float), ("throughput", float))),
            (r"Coupling loop CPU time \(user \+ system\): " + _NUM + r" s on the busiest rank, " + _NUM +
             r" s on all ranks", "Coupling loop CPU time", (("cpu_max_s", float), ("cpu_sum_s", float))),
            (r"Peak memory \(VmHWM\): " + _NUM + r" MiB on the largest rank, " + _NUM + r" MiB on all (\d+) rank",
             "Peak memory", (("hwm_max_mib", float), ("hwm_sum_mib", float), ("ranks", int))),
            (r"Coupling buffers \(all ranks\): " + _NUM + r" B/particle \(run " + _NUM + r", exchange " + _NUM +
             r", coupling step " + _NUM + r"\) for " + _NUM + r" particles; " + _NUM + r" B/cell for " + _NUM +
             r" cells", "Coupling buffers", tuple((k, float) for k in (
                 "buf_per_particle", "buf_run", "buf_exchange", "buf_step", "buf_particles", "buf_per_cell",
                 "buf_cells")))):
        m = re.search(pattern, text)
        if not m:
            raise ValueError(f"{path}: no '{what}' line")
        out.update({k: kind(v) for (k, kind), v in zip(keys, m.groups())})
    return out
