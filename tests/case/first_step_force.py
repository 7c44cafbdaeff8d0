"""first_step_force.py CASE: checks the fluid force on the particles of the
packed column (tests/data/packed-column) at the first coupling step, read
from the particle output (postProcessing/particles/particles_1.pvtp).

Reference: Ergun (1952), Chem. Eng. Prog. 48(2) 89-94, pressure gradient of
a packed bed,
    -dp/dz = 150 mu Us (1-eps)^2 / (eps^3 d^2) + 1.75 rho Us^2 (1-eps) / (eps^3 d),
which the ErgunGidaspow drag law reproduces for eps < 0.8. In the steady,
uniform bed the fluid force on the particles per bed volume (drag + pressure
gradient) equals -dp/dz; each sphere of the simple cubic lattice stands for
d^3 of bed, so F_z = -dp/dz d^3 + rho g V_p (buoyancy). Here eps = 1 - pi/6,
d = 1 mm, rho = 1.2, mu = 1.8e-5, and the superficial velocity
Us = eps U_in = eps 0.2 m/s (flux eps U through the inlet face, whose void
fraction is the bed's). Particles in the bottom and top cell rows (z < 3 mm,
z > 9 mm) see one-sided gradients and are left out.

Tolerances: mean F_z of the inner particles within 5 % of the reference
(the bed is still settling in the first step, falling at up to g t = 5 mm/s,
which raises the slip velocity by up to 2.5 %); and no particle anywhere with
|F| above 20 % of its weight (a particle-free start would kick the bed with
~15 weights: the regression this guards against).
"""

import glob
import math
import os
import re
import sys

import numpy as np


def read_vtp(path):
    """Point data and points of a .vtp with appended raw data, UInt64 headers."""
    data = open(path, "rb").read()
    head_end = data.index(b'<AppendedData encoding="raw">')
    base = data.index(b"_", head_end) + 1
    head = data[:head_end].decode()
    assert 'header_type="UInt64"' in head and 'byte_order="LittleEndian"' in head, path
    arrays = {}
    for tag in re.findall(r"<DataArray [^>]*/>", head):
        attrs = dict(re.findall(r'(\w+)="([^"]*)"', tag))
        offset = base + int(attrs["offset"])
        nbytes = int(np.frombuffer(data, "<u8", 1, offset)[0])
        dtype = {"Float64": "<f8", "Int64": "<i8"}[attrs["type"]]
        values = np.frombuffer(data, dtype, nbytes // 8, offset + 8)
        arrays[attrs.get("Name", "Points")] = values.reshape(-1, int(attrs["NumberOfComponents"]))
    return arrays


def main():
    case = sys.argv[1]
    pieces = sorted(glob.glob(os.path.join(case, "postProcessing/particles/particles_1/rank*.vtp")))
    if not pieces:
        sys.exit(f"first_step_force: no particle output of the first coupling step in {case}")
    parts = [read_vtp(p) for p in pieces]
    x = np.concatenate([a["Points"] for a in parts])
    f = np.concatenate([a["fluidForce"] for a in parts])
    ids = np.concatenate([a["id"] for a in parts]).ravel()
    d, rho_p, rho, mu, g, u_in = 1e-3, 2500.0, 1.2, 1.8e-5, 9.81, 0.2
    eps = 1 - math.pi / 6
    us = eps * u_in
    dpdz = 150 * mu * us * (1 - eps) ** 2 / (eps ** 3 * d ** 2) + 1.75 * rho * us ** 2 * (1 - eps) / (eps ** 3 * d)
    vp = math.pi / 6 * d ** 3
    ref = dpdz * d ** 3 + rho * g * vp
    weight = rho_p * vp * g
    inner = (x[:, 2] > 3e-3) & (x[:, 2] < 9e-3)
    mean_inner = f[inner, 2].mean()
    worst = np.linalg.norm(f, axis=1).max()
    print(f"first_step_force: {len(ids)} particles ({len(np.unique(ids))} distinct) in {len(pieces)} piece(s)")
    print(f"  Ergun + buoyancy: F_z = {ref:.4e} N per particle (-dp/dz = {dpdz:.1f} Pa/m)")
    print(f"  measured, inner {inner.sum()} particles: mean F_z = {mean_inner:.4e} N "
          f"({100 * (mean_inner / ref - 1):+.2f} %)")
    print(f"  largest |F| of any particle: {worst:.3e} N = {worst / weight:.3f} x its weight")
    ok = True
    if len(ids) != 972 or len(np.unique(ids)) != 972:
        print("FAILED: expected the 972 particles once each")
        ok = False
    if abs(mean_inner / ref - 1) > 0.05:
        print("FAILED: inner mean F_z differs from Ergun + buoyancy by more than 5 %")
        ok = False
    if worst > 0.2 * weight:
        print("FAILED: a fluid force above 20 % of the particle weight at the first step")
        ok = False
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
