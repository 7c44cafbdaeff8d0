// Particle.hpp: what the coupling layer knows of a particle.
//
// ParticleState travels from the DEM owner rank to the CFD owner rank of the
// particle's cell; everything here is per parcel (a coarse-grained parcel of
// factor s stands for s^3 primary particles of diameter 2*radius/s).
#pragma once
#include <cstdint>

#include "core/Vec3.hpp"

namespace granair {

struct ParticleState {
    std::int64_t id = 0;  // LIGGGHTS atom tag, unique and stable
    Vec3 x{Vec3::Zero()};  // position [m]
    Vec3 v{Vec3::Zero()};  // velocity [m/s]
    double radius = 0;     // parcel (contact) radius [m]
};

// Fluid properties the drag laws need.
struct FluidProperties {
    double rho = 1.2;     // density [kg/m3]
    double mu = 1.8e-5;   // dynamic viscosity [Pa s]
};

}  // namespace granair
