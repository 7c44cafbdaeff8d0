"""The DEM-calibrated mu(I) of a case's DEM material (cases/rheology-calibration).

A continuum run that is compared with the DEM of the same material takes the
material entries of the calibration (mu_s, mu_2, I0, d, rho_p, phi_max,
phi_min; results/calibration.json) in place of those of the case's
literature block, and keeps the block's numerics (cap, floors,
regularisation): the solver's dictionary reader has no #include, so the
entries are replaced in the text.

The viscosity floor stays the literature block's too: muI's default etaMin is
rho_p d sqrt(g d) of the block's d, so replacing d by the parcel's would raise
it with the parcel size (x11 for the MCC parcels, x20 for the wedge silo's)
into the range of the viscosity of the orifice flow, where it throttled the
calibrated runs by 26-31 % (cases/mcc-hopper README, "Cross-validation");
block() writes the literature block's floor as an explicit etaMin.

    fit(material) -> dict (mu_s, mu_2, I0, phi_max, phi_min, d, rho_p, ses, source)
    block(literature_text, material, d=None, where) -> rheology block text
    set_entry(text, key, value, note) -> the block with key set (replaced, or added before etaMax)

and the fits that make it (cases/rheology-calibration), to points (I, mu or phi,
standard error):

    mu_jop(I, f)            mu_s + (mu_2 - mu_s) / (I0 / I + 1) (Jop et al. 2006)
    fit_mu(I, mu, se)       mu_s, mu_2, I0 with standard errors and covariance
    fit_phi(I, phi, se)     phi_max, phi_min of phi = phi_max - (phi_max - phi_min) I
    vs_fit(rows, f)         each point's mu against a fit (another pressure or cell against the reference)

from a plane shear cell's CG profiles across the gap (granairCG, coordinates Z):

    r = shear_bulk(profile, lo, hi, rho_p)           I, mu (three definitions), phi, P ... over the bulk band
    r = shear_point(mean, snapshots, lo, hi, rho_p, wall, area)   the same, block errors, the wall's traction
"""
import json
import math
import os
import re

import numpy as np

from . import CaseError, numerics

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "cases", "rheology-calibration")
RESULTS = os.path.normpath(os.path.join(ROOT, "results", "calibration.json"))
# rheology key of the block -> key of the fit in calibration.json
KEYS = {"muS": "mu_s", "mu2": "mu_2", "I0": "I0", "phiMax": "phi_max", "phiMin": "phi_min"}


def fit(material, path=RESULTS):
    """The P = 500 Pa fit of `material` (a key of calibration.json: 'wedge-silo', 'mcc-hopper')."""
    try:
        with open(path) as fh:
            data = json.load(fh)
    except (OSError, ValueError) as e:
        raise CaseError(f"{path}: cannot read the calibration ({e})")
    if material not in data:
        raise CaseError(f"{path}: no material '{material}' (has: {', '.join(sorted(data))})")
    m = data[material]
    try:
        f = m["fit"]
        out = {k: float(f[k]) for k in KEYS.values()}
        out.update(d=float(m["d_parcel_m"]), rho_p=float(m["rho_p"]), material=m["material"],
                   se={k: float(f[k + "_se"]) for k in KEYS.values()}, source=os.path.relpath(path, os.path.join(ROOT, "..", "..")))
    except (KeyError, TypeError, ValueError) as e:
        raise CaseError(f"{path}: material '{material}': missing or bad entry {e}")
    return out


G = 9.81      # the standard gravity of muI's default floor (coupling/rheology/MuI.hpp)


def entry(text, key, where="rheology block"):
    """The numeric value of `key` in a rheology block's text (None if absent)."""
    m = re.search(r"^\s*" + re.escape(key) + r"\s+([-+0-9.eE]+)\s*;", text, re.M)
    try:
        return float(m.group(1)) if m else None
    except ValueError:
        raise CaseError(f"{where}: entry '{key}' is not a number")


def read_block(path, keys):
    """(text, {key: value}) of a rheology block file; CaseError names the file and
    the keys it lacks."""
    with open(path) as fh:
        text = fh.read()
    values = {k: entry(text, k, path) for k in keys}
    missing = [k for k, x in values.items() if x is None]
    if missing:
        raise CaseError(f"{path}: key(s) {', '.join(missing)} missing")
    return text, values


def set_entry(text, key, value, note):
    """`text` with `key value;` (and the comment note): the entry replaced if the block has
    it, else added before its etaMax line."""
    line = f"{key:<11} {value:.6g};   // {note}"
    text, n = re.subn(r"^(\s*)" + re.escape(key) + r"\s+[^;\n]*;.*$", lambda m: m.group(1) + line, text, count=1,
                      flags=re.M)
    if n:
        return text
    text, n = re.subn(r"^(\s*)(etaMax\b)", lambda m: f"{m.group(1)}{line}\n{m.group(1)}{m.group(2)}", text, count=1,
                      flags=re.M)
    if not n:
        raise CaseError(f"rheology block: no etaMax entry to put {key} before")
    return text


def block(text, material, d=None, where="rheology block"):
    """`text` (a filled muI rheology block) with its material entries replaced by the
    calibration of `material`; d [m] overrides the calibration's parcel diameter (the
    dimensionless law for another parcel size). Every entry must be in `text` once."""
    f = fit(material)
    values = {k: f[v] for k, v in KEYS.items()}
    values.update(d=f["d"] if d is None else d, rhoP=f["rho_p"])
    if not re.search(r"^\s*type\s+muI\s*;", text, re.M):
        raise CaseError(f"{where}: the calibration replaces a muI block ('type muI;' not found)")
    if entry(text, "etaMin", where) is None:        # the literature floor, before d changes (module docstring)
        d_lit, rho_lit = entry(text, "d", where), entry(text, "rhoP", where)
        if d_lit is None or rho_lit is None:
            raise CaseError(f"{where}: no entry '{'d' if d_lit is None else 'rhoP'}' (the viscosity floor needs it)")
        text = set_entry(text, "etaMin", rho_lit * d_lit * math.sqrt(G * d_lit),
                         f"the literature block's floor rho_p d sqrt(g d), d = {d_lit:g} m (kept)")
    for key, value in values.items():
        note = "DEM parcel diameter of the calibration" if key == "d" and d is None else (
            "set by the run (the calibrated law at this parcel size)" if key == "d" else f"DEM calibration, {f['source']}")
        text, n = re.subn(r"^(\s*)" + re.escape(key) + r"\s+[^;\n]*;.*$",
                          lambda m: f"{m.group(1)}{key:<11} {value:.6g};   // {note}", text, count=1, flags=re.M)
        if n != 1:
            raise CaseError(f"{where}: no entry '{key}' to replace with the calibration")
    start = re.search(r"^\s*rheology\b", text, re.M)     # the literature block's own header comment goes
    text = text[start.start():] if start else text
    return f"// mu(I) of {f['material']}: cases/rheology-calibration (DEM shear cell, P = 500 Pa)\n" + text


def mu_jop(i, f):
    """Jop, Forterre & Pouliquen (2006): mu(I) of f (mu_s, mu_2, I0)."""
    return f["mu_s"] + (f["mu_2"] - f["mu_s"]) / (f["I0"] / i + 1)


def _weights(se):
    return 1.0 / np.maximum(se, 1e-4) ** 2          # a floor: one point with a tiny error does not take the fit


def fit_mu(i, mu, se):
    """Weighted least squares of mu = mu_s + dmu I / (I0 + I): linear in (mu_s, dmu)
    for a given I0, profiled over log I0 (a grid, then golden section); covariance
    from the Jacobian at the optimum, scaled by the reduced chi^2 when it exceeds 1."""
    w = _weights(se)

    def solve(i0):
        a = np.column_stack([np.ones_like(i), i / (i0 + i)])
        c, *_ = np.linalg.lstsq(a * np.sqrt(w)[:, None], mu * np.sqrt(w), rcond=None)
        return c, float(np.sum(w * (mu - a @ c) ** 2))
    grid = np.logspace(-4, 1, 501)
    k = int(np.argmin([solve(g)[1] for g in grid]))
    i0 = numerics.golden(lambda g: solve(g)[1], grid[max(0, k - 1)], grid[min(len(grid) - 1, k + 1)], log=True)
    (mu_s, dmu), chi2 = solve(i0)
    jac = np.column_stack([np.ones_like(i), i / (i0 + i), -dmu * i / (i0 + i) ** 2])   # d/d(mu_s, dmu, I0)
    dof = max(1, len(i) - 3)
    cov = np.linalg.pinv(jac.T @ (jac * w[:, None])) * max(1.0, chi2 / dof)
    t = np.array([[1, 0, 0], [1, 1, 0], [0, 0, 1]])            # (mu_s, dmu, I0) -> (mu_s, mu_2, I0)
    cov = t @ cov @ t.T
    return dict(mu_s=mu_s, mu_2=mu_s + dmu, I0=i0, mu_s_se=math.sqrt(cov[0, 0]), mu_2_se=math.sqrt(cov[1, 1]),
                I0_se=math.sqrt(cov[2, 2]), chi2_reduced=chi2 / dof, covariance=cov.tolist())


def fit_phi(i, phi, se):
    """Weighted least squares of phi = phi_max - span I; phi_min = phi_max - span."""
    w = _weights(se)
    aw = np.column_stack([np.ones(len(i)), -i]) * np.sqrt(w)[:, None]
    c, *_ = np.linalg.lstsq(aw, phi * np.sqrt(w), rcond=None)
    chi2 = float(np.sum(w * (phi - (c[0] - c[1] * i)) ** 2))
    dof = max(1, len(i) - 2)
    t = np.array([[1, 0], [1, -1]])
    cov = t @ np.linalg.pinv(aw.T @ aw) @ t.T * max(1.0, chi2 / dof)
    return dict(phi_max=c[0], phi_min=c[0] - c[1], phi_max_se=math.sqrt(cov[0, 0]), phi_min_se=math.sqrt(cov[1, 1]),
                chi2_reduced=chi2 / dof)


def vs_fit(rows, f):
    """Each point (I, mu, mu_se) of rows against the fit f: [dict(I, mu, mu_se, mu_reference_fit,
    difference)]."""
    return [dict(I=r["I"], mu=r["mu"], mu_se=r["mu_se"], mu_reference_fit=mu_jop(r["I"], f),
                 difference=r["mu"] - mu_jop(r["I"], f)) for r in rows]


def shear_bulk(table, lo, hi, rho_p_fallback):
    """Bulk values of one granairCG profile across the gap of steady plane shear (a dict of
    columns: z, velocity_x, pressure, shear_stress, stress_xz, stress_zz, volume_fraction,
    mean_diameter, particle_density if written) over lo <= z <= hi: the shear rate (the
    slope of V_x), P = tr(sigma)/3, I = gammaDot d / sqrt(P / rho_p) and
    mu = |sigma_xz| / P: the shear stress along the shear (coaxial with D, what
    tau = 2 eta D of the continuum solver carries) over the isotropic pressure (the
    solver's p); also mu_J2 = sqrt(J2) / P (with the normal-stress differences) and
    mu_xz = sigma_xz / sigma_zz (the plane-shear convention, GDR MiDi 2004), and the rms
    deviation of sigma_xz across the band over its mean (uniform in steady shear)."""
    z = table["z"]
    sel = (z >= lo) & (z <= hi)
    gdot = np.polyfit(z[sel], table["velocity_x"][sel], 1)[0]
    p = float(np.mean(table["pressure"][sel]))
    tau = float(np.mean(table["shear_stress"][sel]))
    sxz = float(np.mean(table["stress_xz"][sel]))
    szz = float(np.mean(table["stress_zz"][sel]))
    phi = float(np.mean(table["volume_fraction"][sel]))
    dm = float(np.mean(table["mean_diameter"][sel]))
    rho_p = float(np.mean(table["particle_density"][sel])) if "particle_density" in table else rho_p_fallback
    i = abs(gdot) * dm / math.sqrt(p / rho_p)
    return dict(I=i, mu=abs(sxz) / p, mu_J2=tau / p, mu_xz=abs(sxz) / szz, P=p, tau=tau, sigma_xz=sxz, sigma_zz=szz,
                phi=phi, gamma_dot=abs(gdot), d=dm,
                uniformity=float(np.sqrt(np.mean((table["stress_xz"][sel] - sxz) ** 2)) / abs(sxz)))


SE_KEYS = ("I", "mu", "mu_J2", "mu_xz", "phi", "P", "sigma_xz", "sigma_zz")


def shear_point(mean, snapshots, lo, hi, rho_p, wall, area, blocks=5):
    """One point of a shear-cell sweep: shear_bulk of the time-mean profile, the standard
    errors of SE_KEYS from `blocks` blocks of the snapshots' profiles (gc.series.block_errors),
    and the top wall's traction from its force rows `wall` (columns f_x, _, f_z) over the
    cell's area: wall_tau = -<f_x>/A, wall_sigma = <f_z>/A, wall_mu = -<f_x>/<f_z>."""
    from . import series
    res = shear_bulk(mean, lo, hi, rho_p)
    se = series.block_errors(snapshots, lambda t: shear_bulk(t, lo, hi, rho_p), SE_KEYS, blocks)
    res.update({f"{k}_se": v for k, v in se.items()})
    res.update(wall_tau=float(-np.mean(wall[:, 0]) / area), wall_sigma=float(np.mean(wall[:, 2]) / area),
               wall_mu=float(-np.mean(wall[:, 0]) / np.mean(wall[:, 2])))
    return res
