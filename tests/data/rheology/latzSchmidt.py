"""latzSchmidt.py: reference values of the rheology latzSchmidt (run by
tests/data/make_reference.py).

The kinetic + plastic closures as printed in the lactose study (reference
case A), with p_y/p_k computed as the ratio of the two pressures (not the
rearranged form of coupling/rheology/LatzSchmidt.cpp); lactose parameters.
"""
import math

LACTOSE = dict(c0=0.5579, cMax=0.5771, T0=0.41, eta0=0.00052, lambda0=0.001, eps0=332.84)
POINTS = [  # (c [-], T [m2/s2])
    (0.0, 0.5), (0.3, 0.01), (0.5, 1.0), (0.5579, 0.1),  # no yield pressure (c <= c0)
    (0.56, 0.1), (0.565, 2.0), (0.57, 1e-3), (0.577, 1e-4),  # plastic; the last near cMax
]


def latz_schmidt(c, T, q):
    """Closures as printed in the lactose study (reference case A)."""
    gc = 1.0 / (1.0 - c / q["cMax"])
    pk = c * T * gc
    py = q["T0"] * (c - q["c0"]) * gc if c > q["c0"] else 0.0
    ratio = py / pk if py > 0 else 0.0
    eta = q["eta0"] * math.sqrt(T * gc) * c * (1 + ratio)
    lam = q["lambda0"] * math.sqrt(T * gc) * c * (1 + ratio)
    eps = q["eps0"] * math.sqrt(T * gc) * (1 + ratio)
    note = "g_c = %.6g, p_y/p_k = %.6g" % (gc, ratio)
    return (pk + py, eta, lam, eps), note


def reference():
    """The data file of latzSchmidt (see make_reference.py)."""
    return [dict(variant="",
                 header="kinetic + plastic closure, lactose parameters; c [-], T [m2/s2] -> "
                        "p [m2/s2], eta [m2/s], lambda [m2/s], epsR [1/s]",
                 parameters=list(LACTOSE.items()), inputs=["c", "T"], outputs=["p", "eta", "lambda", "epsR"],
                 rows=[(x, *latz_schmidt(*x, LACTOSE)) for x in POINTS])]
