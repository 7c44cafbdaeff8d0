"""The continuum's opt-in dilatancy (cfd-side/continuum/Dilatancy.H) on a study's
command line: its three options, their checks, and the granularProperties lines
they render (@DILATANCY@ in a case's template). One place for the continuum
drivers that offer it (mcc-hopper/study.py, wedge-silo/continuum.py).

    gc.dilatancy.options(ap, P.DILATANCY_RATE, P.DILATANCY_RELAXATION)
    a = gc.cli.parse(ap, ...)
    gc.dilatancy.check(ap, a, P.DILATANCY_RATE, P.DILATANCY_RELAXATION)
    values["DILATANCY"] = gc.dilatancy.block(a, "study.py")
"""


def options(ap, rate, relaxation):
    """--dilatancy, --dilatancy-rate, --dilatancy-relaxation (the case's defaults)."""
    ap.add_argument("--dilatancy", action="store_true",
                    help="muI: the solid fraction phi(I) fed back into the powder's volume (Dilatancy.H; default off)")
    ap.add_argument("--dilatancy-rate", type=float, default=rate,
                    help=f"with --dilatancy: the rate k of d(phi)/dt = -k phi gammaDot (phi - phi(I)) (default {rate:g})")
    ap.add_argument("--dilatancy-relaxation", type=float, default=relaxation,
                    help=f"with --dilatancy: the under-relaxation of its volume source (default {relaxation:g})")


def check(ap, a, rate, relaxation):
    """A rate or relaxation given only with --dilatancy, and in range (else ap.error names the option)."""
    if a.dilatancy_rate != rate and not (a.dilatancy and a.dilatancy_rate > 0):
        ap.error(f"--dilatancy-rate {a.dilatancy_rate:g}: expected a rate > 0, with --dilatancy")
    if a.dilatancy_relaxation != relaxation and not (a.dilatancy and 0 < a.dilatancy_relaxation <= 1):
        ap.error(f"--dilatancy-relaxation {a.dilatancy_relaxation:g}: expected a factor in (0, 1], with --dilatancy")


def block(a, script, off=""):
    """The granularProperties lines: on with its rate and relaxation, or `off` (a comment or nothing)."""
    if not a.dilatancy:
        return off
    return (f"dilatancy       on;             // {script} --dilatancy: phi(I) in the powder's volume (Dilatancy.H)\n"
            f"dilatancyRate   {a.dilatancy_rate:g};\ndilatancyRelaxation {a.dilatancy_relaxation:g};")
