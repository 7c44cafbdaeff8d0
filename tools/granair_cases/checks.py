"""A case's --check: named assertions, each with its tolerance and the reason for it.

    c = Checks("wedge-silo b10_air")
    c.close("steady mass flow", w, 0.1063, 0.10, "the demo run's rate; 10 %: ...")
    c.exact("accounting", inserted, present + removed, "integer counts")
    c.report(enforce=args.check)        # prints every line; exits 1 on a failure if enforce

Every line says what was compared, the two numbers, the tolerance and why
(tests assert physics against a reference, never a sign alone).
"""
import math
import sys


class Checks:
    def __init__(self, name):
        self.name = name
        self.lines, self.failed = [], []

    def _add(self, ok, what, detail, why):
        line = f"{'PASS' if ok else 'FAIL'} {what}: {detail}" + (f" ({why})" if why else "")
        self.lines.append(line)
        if not ok:
            self.failed.append(line)
        return ok

    def close(self, what, value, ref, rel, why=""):
        """|value / ref - 1| <= rel."""
        err = value / ref - 1 if ref else float("inf")
        ok = math.isfinite(value) and abs(err) <= rel
        return self._add(ok, what, f"{value:.6g} vs {ref:.6g}: {100 * err:+.3g} %, tolerance {100 * rel:.3g} %", why)

    def near(self, what, value, ref, tol, why="", unit=""):
        """|value - ref| <= tol (absolute)."""
        ok = math.isfinite(value) and abs(value - ref) <= tol
        return self._add(ok, what, f"{value:.6g} vs {ref:.6g}{unit}: difference {value - ref:+.3g}, "
                         f"tolerance {tol:.3g}{unit}", why)

    def within(self, what, value, lo, hi, why="", unit=""):
        """lo <= value <= hi."""
        ok = math.isfinite(value) and lo <= value <= hi
        return self._add(ok, what, f"{value:.6g}{unit} in [{lo:.6g}, {hi:.6g}]{unit}", why)

    def exact(self, what, value, ref, why=""):
        """value == ref (counts)."""
        return self._add(value == ref, what, f"{value} vs {ref}", why)

    def true(self, what, ok, detail, why=""):
        """Anything else (an output exists, every value is finite)."""
        return self._add(bool(ok), what, detail, why)

    def report(self, enforce=True):
        for line in self.lines:
            print(f"{self.name}: {line}")
        if self.failed:
            print(f"{self.name}: CHECK FAILED ({len(self.failed)} of {len(self.lines)})", flush=True)
            if enforce:
                sys.exit(1)
        elif self.lines:
            print(f"{self.name}: all {len(self.lines)} checks passed", flush=True)
        return not self.failed
