// DragLaw.hpp: the interface every gas-solid drag law implements.
//
// Convention (unresolved CFD-DEM, "model A" of Zhou et al. 2010): the drag on
// ONE primary particle of diameter d is
//     F_d = beta * (U_f - U_p)
// with beta [kg/s] the per-particle momentum exchange coefficient. The air
// solver treats drag implicitly through K = sum_p beta_p / V_cell [kg/(m3 s)].
// The pressure-gradient force -V_p grad(p) is NOT part of beta; the coupling
// step adds it separately (so for model A the Ergun pressure drop is carried
// by drag + pressure-gradient force together).
//
// Inputs: d the primary-particle diameter [m], eps the local air volume
// fraction (void fraction) in (0, 1], slip = |U_f - U_p| [m/s] (interstitial
// velocities), fluid density and viscosity.
#pragma once
#include <memory>
#include <string>

#include "core/Particle.hpp"
#include "core/Registry.hpp"

namespace granair {

class DragLaw {
public:
    virtual ~DragLaw() = default;
    virtual std::string name() const = 0;

    // beta [kg/s] for one primary particle.
    virtual double beta(double d, double eps, double slip, const FluidProperties& f) const = 0;

    // Force [N] on one primary particle: beta * (Uf - Up).
    Vec3 force(double d, double eps, const Vec3& Uf, const Vec3& Up, const FluidProperties& f) const {
        const Vec3 u = Uf - Up;
        return beta(d, eps, u.norm(), f) * u;
    }
};

// Coarse graining (Radl et al. 2011): a parcel of factor s holds s^3 primary
// particles, each of diameter dParcel/s and feeling the primary drag, so the
// parcel coefficient is s^3 times the primary one. Re and Cd inside the law use
// the primary diameter.
double parcelBeta(const DragLaw& law, double dParcel, double s, double eps, double slip,
                  const FluidProperties& f);

// The registry of drag laws (registerDragLaws.cpp), filled on first use from
// the list in drag/sources.cmake.
const Registry<DragLaw>& dragLaws();

}  // namespace granair
