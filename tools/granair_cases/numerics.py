"""Small numerical tools the closed forms and the fits of the cases share.

    bisect(f, lo, hi)          the root of a monotonic f between lo and hi
    golden(f, lo, hi)          the minimum of a unimodal f between lo and hi
"""
import math

GOLDEN = (math.sqrt(5.0) - 1.0) / 2.0


def bisect(f, lo, hi, n=200, increasing=True, geometric=False, rtol=0.0):
    """The root of f on [lo, hi] (f changes sign once there: from below zero to
    above if increasing, else the other way) by n halvings, or fewer once
    hi - lo <= rtol hi; geometric halves in log (lo > 0: roots over decades).
    Returns the midpoint of the last interval."""
    for _ in range(n):
        mid = math.sqrt(lo * hi) if geometric and lo > 0 else 0.5 * (lo + hi)
        if (f(mid) < 0) == increasing:
            lo = mid
        else:
            hi = mid
        if hi - lo <= rtol * hi:
            break
    return 0.5 * (lo + hi)


def golden(f, lo, hi, n=80, log=False):
    """The minimum of f on [lo, hi] by n golden-section steps (log: in log x,
    lo > 0; the midpoint returned is then geometric)."""
    if log:
        x = golden(lambda u: f(math.exp(u)), math.log(lo), math.log(hi), n)
        return math.exp(x)
    for _ in range(n):
        m1, m2 = hi - GOLDEN * (hi - lo), lo + GOLDEN * (hi - lo)
        if f(m1) < f(m2):
            hi = m2
        else:
            lo = m1
    return 0.5 * (lo + hi)
