"""A silo filled in layers (cases/corn-silo): LIGGGHTS `insert/pack` regions, each a
cylinder just above where the grains inserted before it come to rest, run one after
the other. Why here: pouring a tall fill at once from its top compacts it by the
impacts (the corn silo's first fill raised the shaft pressure at rest by a third);
layers each dropped a short way are how any cylindrical silo on a conical hopper
(or a flat floor, h = 0) is filled, whatever the grains.

    lines, top = cylinder(grains, grain_volume, D, d_outlet, h, r_insert, fraction,
                          layer_height, bulk_fraction, gap, seed, steps)
"""
import math

from . import dem


def cylinder(grains, grain_volume, D, d_outlet, h, r_insert, fraction, layer_height, bulk_fraction, gap, seed,
             steps, template="pdd"):
    """The insertion block of a fill of `grains` (mean volume grain_volume) into a silo
    of diameter D on a conical hopper of height h to an outlet d_outlet wide: layers about
    layer_height tall at solid fraction `fraction` in a cylinder of radius r_insert, each
    `gap` above the rest level of the grains below it (at bulk_fraction, the hopper filled
    first), inserted `steps` apart (the last followed by one step), seeds the primes
    after `seed`, the grains from the distribution `template`. Returns (the LIGGGHTS
    lines, the top of the last layer [m])."""
    area, a_ins = math.pi * D ** 2 / 4, math.pi * r_insert ** 2
    r_o, r = d_outlet / 2, D / 2
    v_hopper = math.pi * h / 3 * (r_o ** 2 + r_o * r + r ** 2)
    n_layers = max(1, math.ceil(grains * grain_volume / (fraction * a_ins) / layer_height))
    counts = [grains // n_layers + (1 if i < grains % n_layers else 0) for i in range(n_layers)]
    lines, below, p = [], 0, seed
    for i, n in enumerate(counts):
        rest = h + max(0.0, below * grain_volume / bulk_fraction - v_hopper) / area
        lo = rest + gap
        hi = lo + n * grain_volume / (fraction * a_ins)
        p = dem.next_prime(p + 1)
        lines += [f"region          layer{i + 1} cylinder z 0 0 {r_insert:.6g} {lo:.6g} {hi:.6g} units box",
                  f"fix ins{i + 1} all insert/pack seed {p} distributiontemplate {template} insert_every once "
                  f"overlapcheck yes all_in yes particles_in_region {n} region layer{i + 1}",
                  f"run             {steps if i < len(counts) - 1 else 1}",
                  f"unfix           ins{i + 1}"]
        below += n
    return "\n".join(lines), hi
