"""dem_io.py: what the DEM-based cases share (cases/wedge-silo, cases/mcc-hopper):
reading LIGGGHTS dumps and granairFoam's discharge balance, and the LIGGGHTS
script block that settles a fill on a closed shutter and writes the restart
the discharge starts from.
"""
import re


def read_dump(path):
    """LIGGGHTS `custom` dump: list of dicts per atom (columns from the ITEM: ATOMS line)."""
    with open(path) as fh:
        lines = fh.read().splitlines()
    i = next(k for k, line in enumerate(lines) if line.startswith("ITEM: ATOMS"))
    cols = lines[i].split()[2:]
    return [dict(zip(cols, map(float, line.split()))) for line in lines[i + 1:] if line.strip()]


def read_discharge_balance(log_path, who="post"):
    """The DEM discharge balance granairFoam prints at the end (DischargeCounter::report):
    counts and masses of inserted, present, removed, lost and discharged particles,
    the run's wall time, and whether inserted = present + removed with none lost."""
    with open(log_path) as fh:
        text = fh.read()
    i = text.rfind("DEM discharge balance")
    if i < 0:
        raise SystemExit(f"{who}: no discharge balance in {log_path} (did the run finish?)")
    bal = {}
    for key, label in (("inserted", "inserted"), ("present", "present"),
                       ("removed", "removed at the sink"), ("lost", "lost (inserted - present - removed)"),
                       ("discharged", "discharged (crossed the outlet)")):
        m = re.search(r"^\s+" + re.escape(label) + r"\s+(-?\d+)\s+(\S+) kg", text[i:], re.M)
        if not m:
            raise SystemExit(f"{who}: '{label}' missing from the discharge balance in {log_path}")
        bal[key] = int(m.group(1))
        bal[key + "_kg"] = float(m.group(2))
    m = re.search(r"total wall time\s+([\d.]+) s", text[i:])
    bal["wall_time_s"] = float(m.group(1)) if m else float("nan")
    bal["closes"] = bal["lost"] == 0 and bal["inserted"] == bal["present"] + bal["removed"]
    return bal


def settle_on_shutter(shutter_fix, chunk, n_min, n_max, settle_min, settle_max, track_top=False):
    """LIGGGHTS script lines: the shutter wall, then runs of `chunk` steps until at
    least n_min chunks (settle_min s) have passed and the rms speed is below
    5 mm/s (at most n_max chunks, settle_max s); then the shutter goes, the step
    counter restarts at 0 (the discharge starts there) and the restart and a dump
    are written. track_top adds the highest particle to thermo and the message."""
    top_var = "variable        ztop equal bound(all,zmax)\n" if track_top else ""
    top_col = " v_ztop" if track_top else ""
    top_msg = ", top ${ztop} m" if track_top else ""
    return f"""# The shutter: the plane z = 0 under the orifice (absent in the discharge runs)
fix shutter all {shutter_fix}

compute         rke all erotate/sphere
variable        vrms equal sqrt(2*ke/mass(all))
{top_var}thermo_style    custom step atoms ke c_rke v_vrms{top_col}
thermo          {chunk}
thermo_modify   norm no

# Settle: at least {settle_min} s, then until the rms speed is below 5 mm/s (at most {settle_max} s)
variable        n loop {n_max}
label           settle
run             {chunk}
if              "$n >= {n_min} && ${{vrms}} < 0.005" then "jump SELF settled"
next            n
jump            SELF settle
label           settled
print           "granair fill: settled after $n x {chunk} steps, rms speed ${{vrms}} m/s{top_msg}"
unfix           shutter
reset_timestep  0               # discharge step 0 = the shutter opens
write_restart   dem/fill.restart
write_dump      all custom dem/fill.dump id x y z radius mass
"""
