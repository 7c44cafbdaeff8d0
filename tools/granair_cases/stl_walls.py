"""Flat walls for LIGGGHTS as quadrilaterals (for gc.dem.stl), cut in pieces: LIGGGHTS
3.8's mesh checks reject long thin triangles, and a counter plane (massflow/mesh) or a
floor with openings needs its facets no larger than a few particles.

    quads = strips(z, x_ranges, y0, y1, piece)     horizontal strips over x ranges, at most `piece` long in x
    quads = tiles(z, x0, x1, y0, y1, nx, ny)       a horizontal rectangle in nx x ny tiles
    quads = annulus(z, R, r1, n)                   a floor around a circular orifice of radius R
    quads = revolution(r0, r1, z0, z1, rows, n)    a cone frustum or a cylinder: rows x n sectors
    tris = disk(r, z, n)                           a horizontal disk of n sectors (a shutter, a counter)
"""
import math


def strips(z, x_ranges, y0, y1, piece):
    """The plane z over y0..y1 and each (a, b) of x_ranges, in strips along x of equal
    length, at most `piece` (a floor between slot openings, a counter plane)."""
    quads = []
    for (a, b) in x_ranges:
        n = max(1, math.ceil((b - a) / piece - 1e-9))
        for k in range(n):
            xa, xb = a + (b - a) * k / n, a + (b - a) * (k + 1) / n
            quads.append([(xa, y0, z), (xb, y0, z), (xb, y1, z), (xa, y1, z)])
    return quads


def tiles(z, x0, x1, y0, y1, nx, ny):
    """The rectangle x0..x1, y0..y1 at height z in nx x ny equal tiles (x outer)."""
    xs = [x0 + (x1 - x0) * i / nx for i in range(nx + 1)]
    ys = [y0 + (y1 - y0) * j / ny for j in range(ny + 1)]
    return [[(a, c, z), (b, c, z), (b, e, z), (a, e, z)] for a, b in zip(xs, xs[1:]) for c, e in zip(ys, ys[1:])]


def annulus(z, R, r1, n=96):
    """The plane z from a circular hole of radius R out to r1: n sectors (the hole an
    n-gon of the circle's area), rings growing geometrically so each cell is about as
    long radially as it is wide."""
    r0 = R * math.sqrt(2 * math.pi / (n * math.sin(2 * math.pi / n)))
    rings = max(1, math.ceil(math.log(r1 / r0) / math.log(1 + 2 * math.pi / n)))
    radii = [r0 * (r1 / r0) ** (k / rings) for k in range(rings + 1)]
    quads = []
    for a, b in zip(radii, radii[1:]):
        for j in range(n):
            t0, t1 = 2 * math.pi * j / n, 2 * math.pi * (j + 1) / n
            quads.append([(a * math.cos(t0), a * math.sin(t0), z), (b * math.cos(t0), b * math.sin(t0), z),
                          (b * math.cos(t1), b * math.sin(t1), z), (a * math.cos(t1), a * math.sin(t1), z)])
    return quads


def revolution(r0, r1, z0, z1, rows, n):
    """The surface of revolution about the z axis from the circle (r0, z0) to (r1, z1)
    (a cone frustum, a cylinder if r0 = r1) as rows x n quadrilaterals, rows along it."""
    quads = []
    for k in range(rows):
        ra, rb = r0 + (r1 - r0) * k / rows, r0 + (r1 - r0) * (k + 1) / rows
        za, zb = z0 + (z1 - z0) * k / rows, z0 + (z1 - z0) * (k + 1) / rows
        for j in range(n):
            a0, a1 = 2 * math.pi * j / n, 2 * math.pi * (j + 1) / n
            quads.append([(ra * math.cos(a0), ra * math.sin(a0), za), (ra * math.cos(a1), ra * math.sin(a1), za),
                          (rb * math.cos(a1), rb * math.sin(a1), zb), (rb * math.cos(a0), rb * math.sin(a0), zb)])
    return quads


def disk(r, z, n):
    """The disk of radius r at height z as n triangles from its centre."""
    return [[(0.0, 0.0, z), (r * math.cos(2 * math.pi * j / n), r * math.sin(2 * math.pi * j / n), z),
             (r * math.cos(2 * math.pi * (j + 1) / n), r * math.sin(2 * math.pi * (j + 1) / n), z)] for j in range(n)]
