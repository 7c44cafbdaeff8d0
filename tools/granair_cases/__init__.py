"""granair_cases: the case layer, what every study under cases/ is built from
(docs/cases.md). Standard library, numpy and matplotlib (Debian packages).

    foam        OpenFOAM dictionaries and fields: read a field, set an entry, time folders
    template    the one template mechanism: a case's template/ with @KEY@ placeholders
    runner      run a step (log, mpirun, CPU time), a job pool, stop a run on a condition
    chunks      long runs of granairFoam or LIGGGHTS in chunks, each from the last restart, resumable
    dem         LIGGGHTS: loose packing, data files, STL walls, dumps, mesh VTK, the discharge balance
    series      time series: CSV in and out, window means, steady rates
    powder      the discharge of a silo or hopper: DEM and continuum runs to the level contract
    closed_forms  Beverloo, Hagen-Beverloo, Crewdson, Carleton, Ergun, Wen & Yu, Janssen
    gci         Roache's grid convergence index of a result on three meshes
    levels      level.json, the contract of `./granair compare` (docs/fidelity-levels.md)
    checks      a case's --check: named assertions with tolerances and reasons
    plots       matplotlib (Agg) helpers: figures, field panels, error bars, particles and force chains
    cli         the options every study takes (--out, --check, --np, --setup-only)
    calibration the DEM-calibrated mu(I) of a case material in place of a literature block
    cg          CG fields: granairCG run on a case's dumps, its CSV read back as grids, tensor invariants
    numerics    a root by bisection, a minimum by golden section
    cg_grids    2-D CG fields (RZ, XZ) on their grid: the committed CSV, the density's integral (mass check)
    outlet      particles leaving through an outlet: counter records, window rates, bulk density, Beverloo fit
    fits        least-squares fits the studies share: phi(I) = a1 / (1 + a2 I), y = alpha f, Beverloo's size term
    stl_walls   STL walls in pieces: strips between openings, tiled planes, surfaces of revolution, disks
    strain      the strain of the particles in a control volume: by their convex hull, from a CG field
    wall_rings  wall loads (LIGGGHTS mesh stress) per ring of elements, Janssen's slice balance
    field_maps  maps of 2-D fields, a row per run and a column per field on shared colour scales
    study       the driver of a study of many LIGGGHTS runs: fills once, resumable runs, a job pool, --setup-only, --post-only
    size_study  the DEM converged in parcel size: window rates, Beverloo's size fit over s and its pairs, its plot
    cg_slab     CG fields of a thin slab silo between four plane walls (XZ): granairCG, Fullard's shear rate, I, eta, the mass check
    phi_i       phi = a1 / (1 + a2 I) over CG points: the figure and the fits' text file
    chunk_inputs  a LIGGGHTS run as one input file per chunk, run in turn (resumable), and the fill it starts from
    linear_contact  the linear spring-dashpot: contact time, damping ratio, LIGGGHTS' gamman from a restitution, pairs and walls at once
    silo_walls  a silo's ring wall loads: profiles at rest and discharging, each wall's maximum, the shaft against Janssen, mean VTK, the outline
    layered_fill  a silo filled in layers: the LIGGGHTS insert/pack block, each layer just above the rest level of those below
    tables      text tables: markdown, right-aligned columns, the mean +- SD cell of repeated runs
    tally       the exact particle count of a chunked LIGGGHTS discharge with a feed, an outlet counter and a sink
    arch        the free-fall arch above an outlet from 2-D CG fields, three ways, and its paraboloid fit
    cg_runs     granairCG on 2-D grids: kernels, grid-aligned and enclosing windows, the kept fields, the mass record
    discharge_counts  a re-fed LIGGGHTS discharge in segments: counts with strays, window rates, the steady rate
    packing_regions  a loose packing's region: a cylinder, a box (sample and inside for dem.loose_packing)
    profile_plots  panels of a study's CG fields and rates: rates with bands, profiles at heights, maps, paraboloids
    two_fluid   the two-fluid level's chunked runs on a staircase mesh, their flow and probe series

Cases import it as `import granair_cases as gc`; tools/foam-env.sh puts tools/
on PYTHONPATH (every `./granair` command and every Allrun source it).
"""


class CaseError(Exception):
    """A case cannot go on: bad input, a failed step. The message names the
    file, the key or the command and what was expected."""


from . import foam, template, runner, chunks, dem, series, powder, closed_forms, gci, levels, checks, plots, cli, calibration, cg, numerics  # noqa: E402,F401,E501
from . import cg_grids, outlet, fits, stl_walls, field_maps, strain, wall_rings, study, size_study, dilatancy  # noqa: E402,F401
from . import tally, tables, cg_slab, phi_i, chunk_inputs, linear_contact, silo_walls, layered_fill  # noqa: E402,F401
from . import arch, cg_runs, discharge_counts, profile_plots, packing_regions, two_fluid  # noqa: E402,F401
