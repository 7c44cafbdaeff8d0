// CgSnapshot.hpp: what the CG fields are computed from: one DEM snapshot.
//
// Particles (centre, velocity, radius, mass, optionally spin), pair contacts
// and wall contacts, read from LIGGGHTS dumps (LiggghtsDump.hpp,
// SnapshotReader.hpp) or filled by a program (tests, the benchmark, the
// shear-cell calibration). Conventions (docs/cg-fields.md):
//  - a pair contact is stored once: force f on particle i from particle j,
//    centres xi and xj, where xj is the periodic image nearest to xi, so
//    xi - xj is the branch vector r_ij even across a periodic boundary;
//  - a wall contact holds the force f the wall exerts on the particle, the
//    particle centre and the contact point.
#pragma once
#include <array>
#include <vector>

#include "core/Vec3.hpp"

namespace granair {

struct CgParticle {
    long id = 0;
    Vec3 x = Vec3::Zero();      // centre [m]
    Vec3 v = Vec3::Zero();      // velocity [m/s]
    Vec3 omega = Vec3::Zero();  // angular velocity [rad/s] (zero if not dumped)
    double radius = 0.0;        // [m]
    double mass = 0.0;          // [kg]
};

struct CgPairContact {
    Vec3 xi = Vec3::Zero();     // centre of i [m]
    Vec3 xj = Vec3::Zero();     // centre of j, the image nearest to xi [m]
    Vec3 force = Vec3::Zero();  // force on i from j [N]
};

struct CgWallContact {
    Vec3 x = Vec3::Zero();      // particle centre [m]
    Vec3 point = Vec3::Zero();  // contact point on the wall [m]
    Vec3 force = Vec3::Zero();  // force of the wall on the particle [N]
};

// The simulation box and which directions are periodic (from the dump).
struct CgDomain {
    Box box;
    std::array<bool, 3> periodic{{false, false, false}};
    double period(int axis) const { return box.hi[axis] - box.lo[axis]; }
};

struct CgSnapshot {
    long step = 0;      // DEM time step number
    double time = 0.0;  // [s] (step * dt when the dt is known, else the step)
    CgDomain domain;
    bool hasSpin = false;  // omega read from the dump
    std::vector<CgParticle> particles;
    std::vector<CgPairContact> pairs;
    std::vector<CgWallContact> walls;
};

}  // namespace granair
