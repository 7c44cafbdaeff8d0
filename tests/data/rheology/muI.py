"""muI.py: reference values of the rheology muI (run by tests/data/make_reference.py).

mu(I) in the (I0/I + 1) form of Jop, Forterre & Pouliquen (2006) with the
numerical limits of coupling/rheology/MuI.hpp applied as stated there, and the
Barker & Gray (2017) partial regularisation with I1 from an independent
bisection; MCC spheres (Remmelgas et al. 2019). Writes muI.dat and
muI.barkerGray2017.dat.
"""
import math

# MCC spheres (Remmelgas et al. 2019) and the numerical limits
MCC = dict(muS=0.401, mu2=0.908, I0=0.0465, d=660e-6, rhoP=1500.0, phiMax=0.632, phiMin=0.443,
           etaMax=1e5, pMin=1.0, gammaDotMin=1e-6)
BG = dict(alphaReg=1.9, muInf=0.05)


def mu_jop(I, q):
    """Jop, Forterre & Pouliquen (2006): mu_s + (mu_2 - mu_s)/(I0/I + 1)."""
    return q["muS"] + (q["mu2"] - q["muS"]) / (q["I0"] / I + 1.0)


def barker_c_jop(I, q):
    """Barker et al. (2015) C(I) for the Jop form; > 0 ill posed."""
    mu = mu_jop(I, q)
    dmu = (q["mu2"] - q["muS"]) * q["I0"] / (q["I0"] + I) ** 2
    nu = I * dmu / mu
    return 4 * nu * nu - 4 * nu + mu * mu * (1 - nu / 2) ** 2


def barker_gray_i1(q):
    """Lower root of C(I) = 0 (Barker & Gray 2017): bisection on
    [1e-12, I_zeta], where mu(I_zeta) = tan of the mean friction angle."""
    tz = math.tan((math.atan(q["muS"]) + math.atan(q["mu2"])) / 2)
    # invert mu_jop(I) = tz:  (mu2 - muS) I = (tz - muS)(I0 + I)
    hi = (tz - q["muS"]) * q["I0"] / (q["mu2"] - tz)
    lo = 1e-12
    assert barker_c_jop(lo, q) > 0 > barker_c_jop(hi, q)
    for _ in range(400):
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        if barker_c_jop(mid, q) < 0:
            hi = mid
        else:
            lo = mid
    return hi


def mu_barker_gray(I, q, i1):
    a = i1 * math.exp(q["alphaReg"] * (q["I0"] + i1) ** 2
                      / (q["muS"] * q["I0"] + q["mu2"] * i1 + q["muInf"] * i1 ** 2) ** 2)
    if I < i1:
        return math.sqrt(q["alphaReg"] / math.log(a / I))
    return (q["muS"] * q["I0"] + q["mu2"] * I + q["muInf"] * I * I) / (q["I0"] + I)


def mu_i(p, gd, q, regularised):
    """(I, mu, eta, phi) at pressure p [Pa] and shear rate gd [1/s]."""
    notes = []
    p_eff = p
    if p < q["pMin"]:
        p_eff = q["pMin"]
        notes.append("p floored")
    gd_eff = gd
    if gd < q["gammaDotMin"]:
        gd_eff = q["gammaDotMin"]
        notes.append("gammaDot floored")
    I = gd_eff * q["d"] / math.sqrt(p_eff / q["rhoP"])
    if regularised:
        i1 = barker_gray_i1(q)
        mu = mu_barker_gray(I, q, i1)
        notes.append("low-I branch" if I < i1 else "high-I branch")
    else:
        mu = mu_jop(I, q)
    eta = mu * p_eff / gd_eff
    if eta > q["etaMax"]:
        eta = q["etaMax"]
        notes.append("eta capped")
    phi = q["phiMax"] - (q["phiMax"] - q["phiMin"]) * I
    if phi < q["phiMin"]:
        phi = q["phiMin"]
        notes.append("phi clamped")
    return (I, mu, eta, phi), ", ".join(notes) or "no limit active"


MUI_POINTS = [  # (p [Pa], gammaDot [1/s])
    (1000.0, 10.0), (500.0, 1.0), (100.0, 50.0), (2000.0, 0.5), (50.0, 0.01),
    (5.0, 200.0),      # I > 1: phi clamped to phiMin
    (1300.0, 1e-3),    # quasi-static: eta capped
    (0.2, 5.0), (-40.0, 5.0),  # below pMin: floored
    (800.0, 0.0),      # at rest: gammaDot floored, eta capped
]
BG_POINTS = [
    (1000.0, 1e-6), (1000.0, 0.05), (1000.0, 1.0), (300.0, 1.5),  # I < I1
    (1000.0, 10.0), (100.0, 50.0), (10.0, 500.0), (2000.0, 0.5),  # I >= I1
]
UNITS = "p [Pa], gammaDot [1/s] -> I [-], mu [-], eta [Pa s], phi [-]"
INPUTS = ["p", "gammaDot"]
OUTPUTS = ["I", "mu", "eta", "phi"]


def reference():
    """The data files of muI: one dict per file (see make_reference.py)."""
    q = dict(MCC, **BG)
    return [
        dict(variant="", header="mu(I) of MCC spheres, Jop form; " + UNITS,
             parameters=list(MCC.items()), inputs=INPUTS, outputs=OUTPUTS,
             rows=[(x, *mu_i(*x, MCC, False)) for x in MUI_POINTS]),
        dict(variant="barkerGray2017",
             header="mu(I) of MCC spheres, Barker & Gray (2017) partial regularisation; " + UNITS,
             parameters=list(MCC.items()) + [("regularisation", "barkerGray2017")] + list(BG.items()),
             inputs=INPUTS, outputs=OUTPUTS,
             rows=[(x, *mu_i(*x, q, True)) for x in BG_POINTS],
             extra=["", "// I1: lower root of C(I) = 0 for the Jop form (bisection here)",
                    "regularisationI1 %r;" % barker_gray_i1(q)]),
    ]
