"""The discharge of a silo or hopper, as its runs report it.

    continuum(run)    granairContinuumFoam (cfd-side/continuum/PowderBalance.H):
                      outlet flow integrated to the discharged mass, the mass balance
    dem(run)          granairFoam: the time series and the particle accounting of the log
    flow_windows(...) mass flow (and outlet gradient) as window means, for plots and level.json
    continuum_outputs(...)   a continuum run's window means CSV, steady rate, outlet gradient, level.json
    check_continuum(...)     its checks: finite, the mass balance (outlet flow integrated, the solver's)
    air_balance(run, s, t_end, ...)   a coupled run's air volume balance: air in - out, pore growth, powder out
"""
import os

import numpy as np

from . import dem as dem_io, foam, levels, series


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


def continuum_outputs(r, out, t0, t1, window, keep_last, csv_name, level=None, extra=()):
    """The outputs of a continuum run (r from continuum()) over the steady window
    [t0, t1] (t1 None: to the end): out/csv_name (t, mass_flow_kg_s[, outlet_dpdz_Pa_m],
    then the `extra` per-step columns [(name, values)]: window means; the per-step outlet
    flux oscillates from step to step) and, given `level` (the contract's other keys),
    out/level.json. Returns dict(w: the least-squares slope of the discharged mass, dpdz:
    the time mean of the outlet gradient or None, centres, flow: the window means)."""
    t, dt, s = r["t"], r["dt"], r["series"]
    g = s.get("outlet_dpdz_Pa_m")
    cols = [r["flow"]] + ([g] if g is not None else []) + [c for _, c in extra]
    centres, means = series.window_means(t, dt, cols, window, keep_last)
    os.makedirs(out, exist_ok=True)
    series.write_csv(os.path.join(out, csv_name), [("t", centres), ("mass_flow_kg_s", means[0])]
                     + ([("outlet_dpdz_Pa_m", means[1])] if g is not None else [])
                     + list(zip([n for n, _ in extra], means[len(cols) - len(extra):])), fmt="{:.6g}")
    res = dict(w=series.slope(t, r["out"], t0, t1), centres=centres, flow=means[0],
               dpdz=None if g is None else series.time_mean(t, g, t0, t1, dt))
    if level is not None:
        levels.write(os.path.join(out, "level.json"), **dict(level, level="continuum", air=g is not None,
                     steady_mass_flow_kg_s=res["w"], steady_window_s=[t0, float(t[-1]) if t1 is None else t1],
                     outlet_dpdz_Pa_m=res["dpdz"], timeseries=csv_name))
    return res


def check_continuum(c, name, r, tol=0.005, why="VOF keeps the powder to round-off; more is powder lost elsewhere"):
    """Every value finite; the mass balance within tol: the outlet flow integrated (powder
    leaving through any other boundary counts as error) and the solver's own."""
    c.true(f"{name}: every value of the time series finite", r["finite"], f"{len(r['t'])} rows")
    c.near(f"{name}: powder mass balance (outlet flow integrated)", r["balance"], 0.0, tol, why)
    c.near(f"{name}: solver's mass balance (all boundaries)", r["solver_balance"], 0.0, tol, why)


def air_balance(run, s, t_end, air_rho, rho_p, depth_scale=1.0, inflow="top_air_kg_s", outflow="outlet_air_kg_s"):
    """The air volume balance of a coupled discharge run over 0..t_end (a field time) in
    the silo above the orifice (z > 0): the air drawn in through the top (monitor
    `inflow`) and leaving down through the orifice (`outflow`; monitors' flux along +z),
    the growth of the pore volume sum(eps V) of the cells above z = 0 (0/Cz and 0/V from
    postProcess writeCellCentres, writeCellVolumes), and the powder volume discharged
    (s: the time series; discharged_kg of the full depth, depth_scale times the run's).
    For incompressible air the first difference equals the second, and that the third."""
    t = s["t"]
    k, dt = t <= t_end + 1e-9, series.step_lengths(t)
    z, vol = (foam.read_field(os.path.join(run, "0", f)) for f in ("Cz", "V"))
    eps = [foam.read_field(os.path.join(foam.time_dir(run, x), "voidfraction"), len(z)) for x in (0, t_end)]
    return dict(air_in_top_m3=float(-np.sum((s[inflow] * dt)[k]) / air_rho),
                air_out_orifice_m3=float(-np.sum((s[outflow] * dt)[k]) / air_rho),
                pore_growth_m3=float(np.sum(((eps[1] - eps[0]) * vol)[z > 0])),
                powder_out_m3=float(s["discharged_kg"][k][-1] / depth_scale / rho_p))
