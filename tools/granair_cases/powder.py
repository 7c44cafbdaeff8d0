"""The discharge of a silo or hopper, as its runs report it.

    continuum(run)    granairContinuumFoam (cfd-side/continuum/PowderBalance.H):
                      outlet flow integrated to the discharged mass, the mass balance
    dem(run)          granairFoam: the time series and the particle accounting of the log
    flow_windows(...) mass flow (and outlet gradient) as window means, for plots and level.json
"""
import os

import numpy as np

from . import dem as dem_io, series


def continuum(run):
    """The powder of a continuum run. Row i covers (t[i-1], t[i]], the first from
    t = 0; `out` is the outlet mass passed up to each row, `initial` the powder at
    t = 0, `balance` (m(end) + out(end) - m(0)) / m(0) (powder leaving through
    any other boundary counts as error), `solver_balance` the largest of the
    solver's own mass_balance_error column (all boundaries)."""
    s = series.read_csv(os.path.join(run, "postProcessing", "timeSeries.csv"), min_rows=2)
    t = s["t"]
    dt = series.step_lengths(t)
    out = np.cumsum(s["mass_flow_kg_s"] * dt)
    mass = s["powder_mass_kg"]
    initial = float(mass[0] + out[0])
    return dict(series=s, t=t, dt=dt, flow=s["mass_flow_kg_s"], out=out, mass=mass, initial=initial,
                balance=float((mass[-1] + out[-1] - initial) / initial),
                solver_balance=float(np.max(np.abs(s["mass_balance_error"]))),
                finite=bool(all(np.all(np.isfinite(v)) for v in s.values())))


def dem(run):
    """A granairFoam discharge run: its time series (t, discharged_kg, mass_flow_kg_s,
    particles, monitors) and the accounting at the end of log/granairFoam.log."""
    s = series.read_csv(os.path.join(run, "postProcessing", "timeSeries.csv"), min_rows=2)
    return dict(series=s, t=s["t"], balance=dem_io.discharge_balance(os.path.join(run, "log", "granairFoam.log")))


def flow_windows(t, discharged, width, extra=(), keep_last=0.0, tol=0.0):
    """Window means of the mass flow (the change of the discharged mass over each
    window) and of any `extra` per-step columns: (centres, [flow, *extra])."""
    dt = series.step_lengths(t)
    rate = np.diff(np.concatenate([[0.0], discharged])) / dt
    return series.window_means(t, dt, [rate] + list(extra), width, keep_last, tol)
