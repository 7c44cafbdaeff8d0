"""The regions a loose packing fills (gc.dem.loose_packing's sample and inside) for the
common shapes: a vertical cylinder about the z axis and an upright box centred on it,
from z = floor up, every sphere `gap` clear of the walls and of the floor.

    sample, inside = cylinder(R, gap)            |(x, y)| <= R - r - gap, z >= floor + r + gap
    sample, inside = box(half_x, half_y, gap)    |x| <= half_x - r - gap, |y| <= half_y - r - gap

sample(rng, r, top) draws x and y uniformly in the square or rectangle that holds the
section and z in floor + r + gap .. top (top grows when the region is crowded); inside
rejects what lies outside. The draws are in that order (x, y, z), so a packing is
reproduced bit for bit from its seed.
"""


def cylinder(R, gap, floor=0.0):
    """sample, inside of the cylinder of radius R above floor (cases/orifice-arch's silo)."""
    def sample(rng, r, top):
        rmax = R - r - gap
        return rng.uniform(-rmax, rmax), rng.uniform(-rmax, rmax), rng.uniform(floor + r + gap, top)

    def inside(x, y, z, r):
        rmax = R - r - gap
        return x * x + y * y <= rmax * rmax and z >= floor + r + gap
    return sample, inside


def box(half_x, half_y, gap, floor=0.0):
    """sample, inside of the box |x| <= half_x, |y| <= half_y above floor (a monolayer between
    plates: half_y the half gap)."""
    def sample(rng, r, top):
        xmax, ymax = half_x - r - gap, half_y - r - gap
        return rng.uniform(-xmax, xmax), rng.uniform(-ymax, ymax), rng.uniform(floor + r + gap, top)

    def inside(x, y, z, r):
        return abs(x) <= half_x - r - gap and abs(y) <= half_y - r - gap and z >= floor + r + gap
    return sample, inside
