"""The one template mechanism of the case layer.

A case's template/ folder holds ordinary OpenFOAM dictionaries and LIGGGHTS
scripts in which the numbers that change from run to run are placeholders:

    endTime         @T_END:.10g@;     // discharge time [s]
    drag            { type @DRAG_LAW@; }

`@KEY@` is replaced by str(value), `@KEY:spec@` by format(value, spec) (a
Python format spec, so the template says how a number is printed). Keys are
upper case. A placeholder with no value stops the render with the file and
the key named; values no file uses are allowed (one dictionary of numbers can
serve several templates).

    render(src, dst, values)            copy a template folder, fill every file
    render(src, dst, values, ["dem"])   only some of its files or folders
    fill(text, values, where)           one text
    constants(parameters)               the upper-case numbers of a case's parameters.py as values
    save_values(path, values)           the run's numbers as JSON beside it
    check_values(path, values, hint)    a resumed run must have been set up with the same numbers
    relocate(src, dst, values)          re-fill the files that name this checkout's folder (PLACES)
"""
import json
import os
import re
import shutil

from . import CaseError

PLACEHOLDER = re.compile(r"@([A-Z][A-Z0-9_]*)(?::([^@\s]*))?@")

# Values that say where this checkout is, not how the run is set up: a run
# folder packed on one machine and resumed on another (gc.chunks) holds the
# first one's paths, so check_values ignores them and relocate re-fills the
# files that use them.
PLACES = ("GRANAIR_ROOT",)


def constants(module):
    """The case's numbers as template values: every upper-case number or string of
    its parameters module (so a template names them as parameters.py does)."""
    return {k: v for k, v in vars(module).items() if k.isupper() and isinstance(v, (int, float, str))}


def fill(text, values, where="template"):
    """text with every @KEY@ / @KEY:spec@ replaced; CaseError names `where` and the key."""
    def one(m):
        key, spec = m.group(1), m.group(2)
        if key not in values:
            raise CaseError(f"{where}: placeholder @{key}@ has no value "
                            f"(given: {', '.join(sorted(values)) or 'none'})")
        try:
            return format(values[key], spec) if spec else str(values[key])
        except (TypeError, ValueError) as e:
            raise CaseError(f"{where}: placeholder @{key}:{spec}@ cannot format {values[key]!r} ({e})")
    return PLACEHOLDER.sub(one, text)


def render(src, dst, values, only=None):
    """Copy the template folder src to dst (created; existing files overwritten)
    with every text file filled from `values`. `only`: relative paths of the
    files or folders to take (default all). Returns the written paths."""
    if not os.path.isdir(src):
        raise CaseError(f"template folder {src} not found")
    written = []
    for root, _, files in os.walk(src):
        for name in sorted(files):
            path = os.path.join(root, name)
            rel = os.path.relpath(path, src)
            if only is not None and not any(rel == o or rel.startswith(o.rstrip("/") + "/") for o in only):
                continue
            out = os.path.join(dst, rel)
            os.makedirs(os.path.dirname(out), exist_ok=True)
            try:
                with open(path) as fh:
                    text = fh.read()
            except UnicodeDecodeError:
                shutil.copyfile(path, out)
            else:
                with open(out, "w") as fh:
                    fh.write(fill(text, values, path))
            written.append(out)
    if only is not None:
        missing = [o for o in only if not os.path.exists(os.path.join(src, o))]
        if missing:
            raise CaseError(f"template {src}: no {', '.join(missing)}")
    return written


def relocate(src, dst, values):
    """Re-fill, in the run folder dst, the files of the template folder src that
    use a PLACES value (an include of the checkout's dem-side/ scripts, say),
    so a folder set up elsewhere points at this checkout's files. The other
    values must be those the folder was set up with (check_values first).
    Returns the written paths."""
    uses = []
    for root, _, files in os.walk(src):
        for name in sorted(files):
            path = os.path.join(root, name)
            try:
                with open(path) as fh:
                    keys = {m.group(1) for m in PLACEHOLDER.finditer(fh.read())}
            except UnicodeDecodeError:
                continue
            if keys & set(PLACES) and os.path.exists(os.path.join(dst, os.path.relpath(path, src))):
                uses.append(os.path.relpath(path, src))
    return render(src, dst, values, only=uses) if uses else []


def write(path, text):
    """Write text to path, creating its folder (generated data: packings, STL walls)."""
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w") as fh:
        fh.write(text)
    return path


def save_values(path, values):
    """The numbers a run folder was set up with (JSON): a resumed run checks them (check_values)."""
    return write(path, json.dumps(values, indent=1))


def check_values(path, values, hint="remove the folder to start again", since=None, ignore=()):
    """A run resumed from path's folder must have been set up with these values
    (as JSON holds them); CaseError names up to four that differ, and the hint.
    since: the values a folder set up before those keys existed had implicitly
    (e.g. a case option added later, at its default), used where it lacks them.
    ignore: keys that do not change the run (e.g. where its probes are)."""
    with open(path) as fh:
        old = {**json.loads(json.dumps(since or {})), **json.load(fh)}
    new = json.loads(json.dumps(values))
    diff = [k for k in sorted(set(old) | set(new)) if old.get(k) != new.get(k) and k not in PLACES and k not in ignore]
    if diff:
        raise CaseError(f"{os.path.dirname(path)} was set up with other numbers ("
                        f"{', '.join(f'{k}: {old.get(k)} vs {new.get(k)}' for k in diff[:4])}); {hint}")
