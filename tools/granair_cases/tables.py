"""Text tables of a study's results: markdown for a README, right-aligned columns for a
summary.txt, and the `mean ± SD` cell of repeated runs. Why here: every case writes
such tables (cases/corn-silo, two-slot-silo, mcc-hopper, wedge-silo), and the cell of
a mean over runs should read the same in all of them.

    cell = pm(row, key, scale=1.0, digits=3)   row[key] ± row[key + "_sd"] (gc.series.mean_sd_columns' names)
    lines = markdown(head, rows)               "| a | b |", "|---|---|", ...
    lines = aligned(rows)                      columns right-aligned to their widest cell, two spaces apart
"""
import math


def pm(row, key, scale=1.0, digits=3):
    """`mean ± sd` of row[key] and row[key + "_sd"] times scale, the mean to `digits`
    significant digits, the SD to 2; the mean alone where the SD is not finite (one run)."""
    m, s = row[key] * scale, row[key + "_sd"] * scale
    return f"{m:.{digits}g}" + (f" ± {s:.2g}" if math.isfinite(s) else "")


def markdown(head, rows):
    """A markdown table: the header, the rule, a line per row (cells as str)."""
    return ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)] + \
        ["| " + " | ".join(str(x) for x in row) + " |" for row in rows]


def aligned(rows, sep="  "):
    """Lines of the rows (the first may be the header), each column right-aligned to
    its widest cell."""
    w = [max(len(str(x)) for x in col) for col in zip(*rows)]
    return [sep.join(str(x).rjust(n) for x, n in zip(row, w)) for row in rows]
