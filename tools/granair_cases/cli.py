"""The command line every study takes, and how it ends.

    ap = cli.parser(__doc__, out="results beside the study")
    ap.add_argument(...)                     # the case's own options
    a = cli.parse(ap, here)                  # a.out absolute, created
    cli.main(fn)                             # CaseError -> message and exit 2
"""
import argparse
import os
import sys

from . import CaseError


def parser(doc, np=1, out_help="results folder"):
    ap = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", default=None, help=f"{out_help} (the runs go to OUT/runs)")
    ap.add_argument("--check", action="store_true",
                    help="exit 1 unless every check of the case holds (they are printed either way)")
    ap.add_argument("--np", type=int, default=np, help=f"MPI ranks per run (default {np})")
    ap.add_argument("--setup-only", action="store_true",
                    help="write the run folders from the template and stop (nothing is run)")
    return ap


def parse(ap, default_out, argv=None):
    """The options; a.out absolute and created (default_out: a path, or a function of the options)."""
    a = ap.parse_args(argv)
    if a.np < 1:
        ap.error(f"--np {a.np}: expected a whole number >= 1")
    a.out = os.path.abspath(a.out or (default_out(a) if callable(default_out) else default_out))
    os.makedirs(a.out, exist_ok=True)
    return a


def main(fn):
    """Run fn(); a CaseError ends the study with its message (exit 2)."""
    try:
        sys.exit(fn())
    except CaseError as e:
        print(f"{os.path.basename(sys.argv[0])}: {e}", file=sys.stderr)
        sys.exit(2)
