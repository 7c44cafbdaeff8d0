"""level.json: one run as a fidelity level of `./granair compare` (docs/fidelity-levels.md).

    write(path, case="wedge-silo", level="cg-dem-cfd", model="...", b_mm=10, air=True,
          steady_mass_flow_kg_s=..., steady_window_s=[t0, t1], outlet_dpdz_Pa_m=...,
          wall_time_s=..., cores=1, timeseries="b10_air.csv", **extra)
"""
import json

from . import CaseError

LEVELS = ["closed-form", "continuum", "two-fluid", "cg-dem", "cg-dem-cfd", "dem-cfd"]
KEYS = ("case", "level", "model", "b_mm", "air", "steady_mass_flow_kg_s",
        "steady_window_s", "outlet_dpdz_Pa_m", "wall_time_s", "cores", "timeseries")


def check(d, where):
    """d is a level (the keys of the contract, a known level); CaseError names `where`."""
    missing = [k for k in KEYS if k not in d]
    if missing:
        raise CaseError(f"{where}: key(s) {', '.join(missing)} missing (see docs/fidelity-levels.md)")
    if d["level"] not in LEVELS:
        raise CaseError(f"{where}: level {d['level']!r} unknown; known: {', '.join(LEVELS)}")
    return d


def write(path, **level):
    """Write one level (the contract's keys first, extra keys kept for people)."""
    check(level, path)
    with open(path, "w") as fh:
        json.dump(dict({k: level[k] for k in KEYS}, **level), fh, indent=1, default=float)
        fh.write("\n")


def read(path):
    with open(path) as fh:
        try:
            d = json.load(fh)
        except json.JSONDecodeError as e:
            raise CaseError(f"{path}: not valid JSON ({e})")
    return check(d, path)
