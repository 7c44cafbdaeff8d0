"""particle_in_stream.py CASE: one glass sphere released at rest in a uniform
upward air stream (tests/data/particle-in-stream, one-way coupling), against
an RK4 solution of the same equation of motion:

    m dv/dt = beta(|U - v|) (U - v) - m g + rho_f V g,
    beta = (pi/8) mu d Cd Re,  Cd Re = 24 (1 + 0.15 Re^0.687),  Re = rho_f d |U - v| / mu

(Schiller & Naumann 1933, granair's SchillerNaumann law; buoyancy from the
coupling step, no pressure gradient in the uniform stream). d = 200 um,
rho_p = 2500 kg/m3, air rho_f = 1.2 kg/m3, mu = 1.8e-5 Pa s, U = 2 m/s,
g = 9.81 m/s2. The particle's relaxation time at the start is 0.09 s, 90 CFD
steps of 1 ms.

Checks:
  1. the velocity at every coupling step (dem/history.txt, from the first
     output at t = 1 ms on) within 1 % of RK4 (step 1e-6 s). The force held
     over a coupling interval costs dt/(2 tau) = 0.55 % at the first output,
     less later; a first interval without fluid force (free fall, before
     the fix) is off by -266 % there and still -1.2 % at t = 0.1 s (printed
     for reference).
  2. one-way coupling: the air at the end (0.1/U, 0.1/p) is the inflow field,
     U = (0 0 2) m/s and p = 0 to 1e-12 (relative to U, and in Pa).
"""

import math
import os
import re
import sys

D, RHO_P, RHO_F, MU, U, G = 2e-4, 2500.0, 1.2, 1.8e-5, 2.0, 9.81
V = math.pi / 6 * D ** 3
M = RHO_P * V


def accel(v):
    slip = U - v
    re = RHO_F * D * abs(slip) / MU
    beta = math.pi / 8 * MU * D * 24 * (1 + 0.15 * re ** 0.687)
    return beta * slip / M - G + RHO_F * V * G / M


def rk4(t_end, h=1e-6):
    """v(t) on the grid of h."""
    n = int(round(t_end / h))
    v, out = 0.0, [0.0]
    for _ in range(n):
        k1 = accel(v)
        k2 = accel(v + h / 2 * k1)
        k3 = accel(v + h / 2 * k2)
        k4 = accel(v + h * k3)
        v += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        out.append(v)
    return out


def held_force(times, dt, first_free):
    """The coupled scheme as an ODE map: force from v at the start of each
    interval, held over it (first_free: no fluid force in the first one)."""
    v, out = 0.0, []
    for k in range(len(times)):
        a = -G if (first_free and k == 0) else accel(v)
        v += a * dt
        out.append(v)
    return out


def read_history(path):
    steps, vz = [], []
    lines = open(path).read().split("\n")
    for i, line in enumerate(lines):
        if line.startswith("ITEM: TIMESTEP"):
            steps.append(int(lines[i + 1]))
        if line.startswith("ITEM: ATOMS"):
            vz.append(float(lines[i + 1].split()[2]))
    return steps, vz


def vector_field(path):
    text = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<vector>\s*\d+\s*\((.*?)\)\s*;", text, re.S)
    if m:
        return [tuple(float(c) for c in t.split()) for t in re.findall(r"\(([^()]*)\)", m.group(1))]
    m = re.search(r"internalField\s+uniform\s+\(([^)]*)\)", text)
    return [tuple(float(c) for c in m.group(1).split())]


def scalar_field(path):
    text = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*\d+\s*\((.*?)\)", text, re.S)
    if m:
        return [float(v) for v in m.group(1).split()]
    return [float(re.search(r"internalField\s+uniform\s+(\S+);", text).group(1))]


def main():
    case = sys.argv[1]
    steps, vz = read_history(os.path.join(case, "dem", "history.txt"))
    dem_dt, n = 2e-5, 50
    times = [s * dem_dt for s in steps]
    exact = rk4(times[-1])
    ok = True
    worst, worst_t = 0.0, 0.0
    for t, v in zip(times[1:], vz[1:]):
        ref = exact[int(round(t / 1e-6))]
        err = abs(v - ref) / abs(ref)
        if err > worst:
            worst, worst_t = err, t
    print(f"particle_in_stream: {len(times) - 1} outputs to t = {times[-1]:.3f} s, "
          f"v = {vz[-1]:.6f} m/s (RK4 {exact[-1]:.6f})")
    print(f"  largest |v - v_RK4| / |v_RK4| = {100 * worst:.3f} % at t = {worst_t * 1e3:.0f} ms (limit 1 %)")
    first = exact[int(round(times[1] / 1e-6))]
    print(f"  first output t = 1 ms: v = {vz[1]:.6e}, RK4 {first:.6e} ({100 * (vz[1] / first - 1):+.3f} %)")
    free = held_force(times[1:], n * dem_dt, True)
    print(f"  for reference, a first interval in free fall: {100 * (free[0] / first - 1):+.0f} % at 1 ms, "
          f"{100 * (free[-1] / exact[-1] - 1):+.1f} % at {times[-1]:.2f} s")
    if len(times) != 101 or worst > 0.01:
        print("FAILED: velocity history off the RK4 solution by more than 1 % (or outputs missing)")
        ok = False

    tdir = os.path.join(case, "0.1")
    u = vector_field(os.path.join(tdir, "U"))
    p = scalar_field(os.path.join(tdir, "p"))
    du = max(max(abs(a - b) for a, b in zip(c, (0.0, 0.0, U))) for c in u)
    dp = max(abs(x) for x in p)
    print(f"  one-way coupling: air at t = 0.1 s: max |U - (0 0 2)| = {du:.2e} m/s, max |p| = {dp:.2e} Pa "
          f"({len(u)} cells)")
    if du > 1e-12 * U or dp > 1e-12:
        print("FAILED: with one-way coupling the air must stay the inflow field")
        ok = False
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
