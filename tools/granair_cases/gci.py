"""gci:  Roache's grid convergence index of a result on three meshes.

Roache, P.J. (1994). Perspective: a method for uniform reporting of grid
refinement studies. J. Fluids Eng. 116, 405-413; the procedure as Celik et
al. (2008), J. Fluids Eng. 130, 078001, write it (safety factor 1.25 for
three meshes). f1 is the finest mesh's value, h the cell sizes (any common
measure, e.g. 1/N), r21 = h2/h1, r32 = h3/h2 > 1.

    e21 = f2 - f1, e32 = f3 - f2, s = sign(e32/e21)
    order p: p = |ln|e32/e21| + q(p)| / ln r21,
             q(p) = ln((r21^p - s) / (r32^p - s))      (fixed point; q = 0 if r21 = r32)
    extrapolated f_ext = (r21^p f1 - f2) / (r21^p - 1)
    GCI_fine = Fs |e21/f1| / (r21^p - 1)

Monotonic convergence needs 0 < e32/e21 (s = +1, the differences shrink);
oscillatory or diverging sequences are reported as such, with no GCI.
python3 standard library only (gc.gci.gci).
"""
import math

SAFETY = 1.25


def gci(f, h, safety=SAFETY):
    """f = (f1, f2, f3) finest first, h = (h1, h2, h3) cell sizes (h1 < h2 < h3).
    Returns a dict: order, extrapolated, gci_fine (relative), e21, e32, r21, r32,
    convergence ('monotonic' | 'oscillatory' | 'converged' | 'diverging')."""
    f1, f2, f3 = f
    h1, h2, h3 = h
    if not (0 < h1 < h2 < h3):
        raise ValueError("gci: cell sizes must grow from the finest mesh, got %r" % (h,))
    r21, r32 = h2 / h1, h3 / h2
    e21, e32 = f2 - f1, f3 - f2
    out = dict(r21=r21, r32=r32, e21=e21, e32=e32, order=float("nan"), extrapolated=float("nan"),
               gci_fine=float("nan"))
    if e21 == 0 and e32 == 0:
        out.update(convergence="converged", gci_fine=0.0, extrapolated=f1)
        return out
    if e21 == 0 or e32 / e21 <= 0:
        out["convergence"] = "oscillatory"
        return out
    ratio = e32 / e21
    if ratio <= 1:
        out["convergence"] = "diverging"   # the differences do not shrink towards the finest mesh
        return out
    s = 1.0
    p = abs(math.log(abs(ratio))) / math.log(r21)
    for _ in range(200):
        q = math.log((r21 ** p - s) / (r32 ** p - s))
        p_new = abs(math.log(abs(ratio)) + q) / math.log(r21)
        if abs(p_new - p) < 1e-12:
            break
        p = p_new
    rp = r21 ** p
    out.update(order=p, extrapolated=(rp * f1 - f2) / (rp - 1), gci_fine=safety * abs(e21 / f1) / (rp - 1),
               convergence="monotonic")
    return out
