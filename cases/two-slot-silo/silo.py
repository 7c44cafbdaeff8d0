"""The two-slot silo's run folders: the derived numbers, the walls (STL) and
the LIGGGHTS stages (fill, discharge chunks with restarts, the CG chunk).
Used by study.py; every number comes from parameters.py (README "Parameters")."""
import json
import math
import os
import random

import granair_cases as gc
import parameters as P

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))


def geometry_name(L):
    return "single" if L == P.SINGLE else f"L{L}"


def numbers(size, friction):
    """Every placeholder of the templates for a size and a friction set."""
    s = P.SIZES[size]
    width, height = s["width"], s["height"]
    masses = [P.mass(d) for d in P.D_SIZES]
    m_mean = sum(masses) / len(masses)
    # the contact time of the lightest particle pair sets the step; the CG
    # snapshot interval a whole number of steps, so are the series and chunks
    t_c = gc.linear_contact.contact_time(min(masses) / 2, P.K_N, P.RESTITUTION)
    per_snapshot = math.ceil(P.CG_SPACING_T / (P.DT_FRACTION * t_c))
    dt = P.CG_SPACING_T / per_snapshot
    v_mean = sum(math.pi / 6 * d ** 3 for d in P.D_SIZES) / len(P.D_SIZES)
    n_fill = round(width * P.DEPTH * height * P.PHI_SETTLED / v_mean)
    r_max = max(P.D_SIZES) / 2
    fill_top = height * P.PHI_SETTLED / P.FILL_PHI_INSERT
    # the box holds the loose packing (which may grow by a few mm when crowded)
    z_top = max(1.25 * fill_top, height + P.FEED_HEIGHT) + P.BOX_TOP_MARGIN
    mu_pp, mu_pw = P.FRICTION[friction]
    gn_pp, gn_pw = (gc.linear_contact.gamma_per_mass(m, P.K_N, P.RESTITUTION) for m in (m_mean / 2, m_mean))
    snap_steps = per_snapshot
    return dict(
        SIZE=size, FRICTION=friction, WIDTH=width, HEIGHT=height, DEPTH=P.DEPTH, N_FILL=n_fill,
        XLO=-width / 2, XHI=width / 2, ZLO=P.SINK_Z - 0.005, ZHI=z_top, SINK_Z=P.SINK_Z,
        XLO_OUT=-width / 2 - 0.01, XHI_OUT=width / 2 + 0.01, YHI_OUT=P.DEPTH + 0.01, ZLO_OUT=P.SINK_Z - 0.05,
        XLO_IN=-width / 2 + r_max, XHI_IN=width / 2 - r_max, YLO_IN=r_max, YHI_IN=P.DEPTH - r_max,
        ZFILL_LO=r_max, ZFILL_HI=fill_top, ZFEED_LO=height, ZFEED_HI=height + P.FEED_HEIGHT,
        K_N=P.K_N, K_T=P.K_T, E=P.RESTITUTION, GN_PP=gn_pp, GN_PW=gn_pw,
        GT_PP=P.ETA_T_FACTOR * gn_pp, GT_PW=P.ETA_T_FACTOR * gn_pw, MU_PP=mu_pp, MU_PW=mu_pw,
        DEM_DT=dt, CONTACT_TIME=t_c, G=P.G, RHO_P=P.RHO_P, SKIN=0.5 * P.D_MEAN,
        R1=P.D_SIZES[0] / 2, R2=P.D_SIZES[1] / 2, R3=P.D_SIZES[2] / 2, F1=1 / 3, F2=1 / 3, F3=1 / 3,
        SETTLE_TIME=s["settle"], N_SETTLE=round(s["settle"] / dt), THERMO_EVERY=round(0.05 / dt),
        SEED=gc.dem.next_prime(12345701 if friction == "low" else 22345701), FEED_PHI=P.FEED_PHI, FEED_EVERY=P.FEED_EVERY,
        FEED_STEPS=round(P.FEED_EVERY / dt), SERIES_STEPS=round(P.SERIES_EVERY / dt), SNAP_STEPS=snap_steps,
        GRANAIR_ROOT=ROOT, T_DISCHARGE=s["t_discharge"], CHUNK_T=s["chunk"], STEADY_FROM=s["steady_from"],
        CG=int(s["cg"]), T_CG=(P.CG_SNAPSHOTS - 1) * P.CG_SPACING_T)


def chunks(v):
    """[(index, steps, cg)]: discharge chunks of about CHUNK_T s in whole snapshot
    intervals, then the CG chunk (gc.chunk_inputs.layout) if the size has one."""
    return gc.chunk_inputs.layout(v["T_DISCHARGE"], v["CHUNK_T"], P.CG_SPACING_T, v["SNAP_STEPS"],
                                  P.CG_SNAPSHOTS if v["CG"] else 0)


def floor_quads(L, width, depth, piece=0.01):
    """The floor z = 0 without the openings, in strips of at most `piece` along x."""
    edges = [-width / 2] + [x for ab in P.openings(L) for x in ab] + [width / 2]
    return gc.stl_walls.strips(0.0, list(zip(edges[::2], edges[1::2])), 0.0, depth, piece)


def plane_quads(z, width, depth, margin=0.001, piece=0.01):
    """A horizontal plane at z over the whole silo (the outlet and sink counters)."""
    return gc.stl_walls.strips(z, [(-width / 2 - margin, width / 2 + margin)], -margin, depth + margin, piece)


def packing(v):
    """Random sequential addition of N_FILL spheres (the three sizes in equal
    numbers, shuffled) in the closed silo at about FILL_PHI_INSERT: [(x, y, z, d)]."""
    rng = random.Random(v["SEED"])
    sizes = [P.D_SIZES[k % len(P.D_SIZES)] for k in range(v["N_FILL"])]
    rng.shuffle(sizes)
    gap = 0.02 * P.D_MEAN

    def sample(rng, r, top):
        return (rng.uniform(v["XLO"] + r + gap, v["XHI"] - r - gap), rng.uniform(r + gap, v["DEPTH"] - r - gap),
                rng.uniform(r + gap, top - r))
    return gc.dem.loose_packing(sizes, rng, sample, lambda x, y, z, r: True, lambda t: t + 0.002,
                                v["ZFILL_HI"], max(P.D_SIZES) * 1.0001, gap)


def setup_fill(v, fill):
    gc.template.render(os.path.join(HERE, "template"), fill, v, only=["dem/in.fill", "dem/in.materials"])
    atoms = packing(v)
    top = max(a[2] for a in atoms) + max(P.D_SIZES)
    if top > v["ZHI"]:
        raise gc.CaseError(f"the loose packing reaches z = {top:.4g} m, above the DEM box (ZHI = {v['ZHI']:.4g} m)")
    gc.dem.write_data(os.path.join(fill, "dem", "packing.data"), atoms,
                      (v["XLO"], v["XHI"], 0.0, v["DEPTH"], v["ZLO"], v["ZHI"]), P.RHO_P,
                      f"two-slot silo loose packing: {len(atoms)} spheres of {', '.join('%g' % (d * 1e3) for d in P.D_SIZES)} mm")


def setup_run(v, L, run, fill):
    """The discharge folder of one geometry: materials, walls, one input per chunk."""
    gc.template.render(os.path.join(HERE, "template"), run, v, only=["dem/in.materials"])
    dem = os.path.join(run, "dem")
    gc.template.write(os.path.join(dem, "floor.stl"), gc.dem.stl("floor", floor_quads(L, v["WIDTH"], v["DEPTH"])))
    gc.template.write(os.path.join(dem, "outlet.stl"), gc.dem.stl("outlet", plane_quads(0.0, v["WIDTH"], v["DEPTH"])))
    gc.template.write(os.path.join(dem, "sink.stl"), gc.dem.stl("sink", plane_quads(P.SINK_Z, v["WIDTH"], v["DEPTH"])))
    with open(os.path.join(HERE, "template", "dem", "in.chunk")) as fh:
        gc.chunk_inputs.write(run, fh.read(), chunks(v), v, os.path.join(fill, "dem", "fill.restart"),
                              "template/dem/in.chunk", lambda k: dict(FEED_SEED=gc.dem.next_prime(v["SEED"] + 1000 * (k + 1))))
    with open(os.path.join(run, "numbers.json"), "w") as fh:
        json.dump(dict(v, L=L, OPENINGS=P.openings(L), CHUNKS=chunks(v)), fh, indent=1)


def fill_stage(v, fill):
    """(setup, simulate) of a friction set's fill (gc.study.drive), run once (gc.chunk_inputs.once)."""
    return gc.chunk_inputs.once(fill, lambda d: setup_fill(v, d))


def fill_cost(fill):
    """The fill's {cpu_s, wall_s} (cost.json; {"fill": ...} in one of an older study.py), or None."""
    path = os.path.join(fill, "cost.json")
    if not os.path.exists(path):
        return None
    with open(path) as fh:
        rec = json.load(fh)
    return rec.get("fill", rec)


def run_stage(v, L, run, fill, progress=print):
    """(setup, simulate) of one geometry's discharge (gc.study.drive): the chunks in turn
    (gc.chunk_inputs.stage: a stopped study resumes at the chunk it was in)."""
    return gc.chunk_inputs.stage(run, chunks(v), lambda d: setup_run(v, L, d, fill), progress)
