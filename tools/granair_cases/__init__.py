"""granair_cases: the case layer, what every study under cases/ is built from
(docs/cases.md). Standard library, numpy and matplotlib (Debian packages).

    foam        OpenFOAM dictionaries and fields: read a field, set an entry, time folders
    template    the one template mechanism: a case's template/ with @KEY@ placeholders
    runner      run a step (log, mpirun, CPU time), a job pool, stop a run on a condition
    dem         LIGGGHTS: loose packing, data files, STL walls, dumps, mesh VTK, the discharge balance
    series      time series: CSV in and out, window means, steady rates
    powder      the discharge of a silo or hopper: DEM and continuum runs to the level contract
    closed_forms  Beverloo, Hagen-Beverloo, Crewdson, Carleton, Ergun, Wen & Yu, Janssen
    levels      level.json, the contract of `./granair compare` (docs/fidelity-levels.md)
    checks      a case's --check: named assertions with tolerances and reasons
    plots       matplotlib (Agg) helpers: figures, Beverloo bands, field panels
    cli         the options every study takes (--out, --check, --np, --setup-only)

Cases import it as `import granair_cases as gc`; tools/foam-env.sh puts tools/
on PYTHONPATH (every `./granair` command and every Allrun source it).
"""


class CaseError(Exception):
    """A case cannot go on: bad input, a failed step. The message names the
    file, the key or the command and what was expected."""


from . import foam, template, runner, dem, series, powder, closed_forms, levels, checks, plots, cli  # noqa: E402,F401
