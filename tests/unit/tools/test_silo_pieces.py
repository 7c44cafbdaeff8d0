#!/usr/bin/env python3
"""The pieces of the DEM-only silo studies (cases/two-slot-silo, cases/corn-silo) that
live in the case layer: the chunked particle balance (gc.tally), the text tables
(gc.tables), against hand-made logs and numbers. Fast (no simulation): label unit."""
import math
import os
import tempfile
import unittest

import granair_cases as gc
from granair_cases import CaseError


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as fh:
        fh.write(text)
    return path


def chunk_log(k, start, end):
    keys = ("atoms", "in_silo", "outlet", "sink", "feed")
    line = lambda s, t, v: (f"granair chunk {k} {s}: time {t} " + " ".join(f"{a} {b}" for a, b in zip(keys, v)))  # noqa: E731
    return f"LIGGGHTS\n{line('start', *start)}\nrun 100\ngranair chunk {k} pending: 1\n{line('end', *end)}\n"


class Tally(unittest.TestCase):
    def test_log_values_reads_labelled_key_value_lines(self):
        with tempfile.TemporaryDirectory() as d:
            p = write(os.path.join(d, "log"), "granair chunk 1 start: time 0.1 atoms 5 note x\n"
                                              "granair chunk 10 start: time 9 atoms 9\n"
                                              "granair chunk 1 start: time 0.2 atoms 6\n")
            # chunk 10's line is not chunk 1's; the last line of a label wins; words stay strings
            self.assertEqual(gc.tally.log_values(p, "granair chunk 1"), {"start": {"time": 0.2, "atoms": 6.0}})
            self.assertEqual(gc.tally.log_values(p, "granair chunk 10")["start"]["atoms"], 9.0)

    def test_balance_of_two_chunks_closes_and_names_a_gap(self):
        # fill 100; chunk 0: feed 10, 30 cross the outlet, 20 reach the sink; chunk 1: feed 5, 10 cross, 15 removed
        with tempfile.TemporaryDirectory() as d:
            logs = [write(os.path.join(d, f"chunk_{k}.liggghts"), chunk_log(k, s, e)) for k, (s, e) in enumerate([
                ((0.0, (100, 100, 0, 0, 0)), (0.1, (90, 80, 30, 20, 10))),
                ((0.1, (90, 80, 30, 20, 10)), (0.2, (80, 75, 40, 35, 15)))])]
            states = [gc.tally.chunk_states(p, k) for k, p in enumerate(logs)]
            self.assertEqual(states[1][1], dict(t=0.2, atoms=80, in_silo=75, outlet=40, sink=35, feed=15))
            acc = gc.tally.balance(100, 100, states, list(range(40)), list(range(35)), [3, 4], lost=2)
            # inserted 115 = 75 in the silo + 5 below the outlet + 35 removed; 40 crossings = 5 + 35
            self.assertEqual((acc["inserted"], acc["in_silo"], acc["below_outlet"], acc["removed"], acc["discharged"]),
                             (115, 75, 5, 35, 40))
            self.assertTrue(acc["closes"] and acc["chunks_consistent"] and acc["pending_all_removed"])
            self.assertEqual((acc["t_end"], acc["lost_atom_warnings"], acc["pending_deleted"]), (0.2, 2, 2))
            # a particle crossing without its record, a pending id the sink never counted: not closed
            self.assertFalse(gc.tally.balance(100, 100, states, list(range(39)), list(range(35)))["closes"])
            self.assertFalse(gc.tally.balance(100, 100, states, list(range(40)), list(range(35)), [99])["closes"])
            # a chunk that does not start where the one before ended
            bad = [states[0], (dict(states[1][0], atoms=91), states[1][1])]
            self.assertFalse(gc.tally.balance(100, 100, bad, list(range(40)), list(range(35)))["chunks_consistent"])
            c = gc.checks.Checks("t")
            gc.tally.check(c, "run", acc, 2)
            self.assertEqual((len(c.lines), c.failed), (6, []))
            with self.assertRaisesRegex(CaseError, r"no 'granair chunk 2 start/end' lines"):
                gc.tally.chunk_states(logs[0], 2)

    def test_lost_atoms_counts_the_warnings(self):
        with tempfile.TemporaryDirectory() as d:
            p = write(os.path.join(d, "s"), "WARNING: Lost atoms: original 5 current 5\nx\nWARNING: Lost atoms: ...\n")
            self.assertEqual(gc.tally.lost_atoms(p), 2)


class Tables(unittest.TestCase):
    def test_pm_markdown_and_aligned(self):
        self.assertEqual(gc.tables.pm(dict(w=0.123456, w_sd=0.00123), "w"), "0.123 ± 0.0012")
        self.assertEqual(gc.tables.pm(dict(w=0.01234, w_sd=math.nan), "w", 100, 2), "1.2")     # one run: no SD
        self.assertEqual(gc.tables.markdown(["a", "b"], [[1, "x"]]), ["| a | b |", "|---|---|", "| 1 | x |"])
        self.assertEqual(gc.tables.aligned([["n", "value"], [10, 2.5]]), [" n  value", "10    2.5"])


if __name__ == "__main__":
    unittest.main()
