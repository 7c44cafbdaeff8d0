// CouplingStep.cpp: see CouplingStep.hpp for the equations.
#include "coupler/CouplingStep.hpp"

#include <algorithm>
#include <cmath>

#include "core/CapacityBytes.hpp"
#include "core/Error.hpp"

namespace granair {

// Parcel volume [m3] from its radius.
static double volume(const ParticleState& p) {
    const double r = p.radius;
    return 4.0 / 3.0 * M_PI * r * r * r;
}

CouplingStep::CouplingStep(const CouplingSettings& settings, const CellLocator& mesh, FluidProperties fluid)
    : settings_(settings), mesh_(mesh), fluid_(fluid) {
    if (!settings_.voidFraction) fail("CouplingStep: a void-fraction model is required");
}

void CouplingStep::voidFraction(const OwnedParticles& owned, double* eps) {
    const int nCells = mesh_.nCells();
    const std::size_t np = owned.size();

    // Stencils and solid volume.
    offset_.assign(1, 0);
    offset_.reserve(np + 1);
    weights_.clear();
    solid_.assign(nCells, 0.0);
    for (std::size_t p = 0; p < np; ++p) {
        const ParticleState& ps = owned.state(p);
        const double vp = volume(ps);
        settings_.voidFraction->stencil(mesh_, ps, owned.cell(p), scratch_);
        for (const CellWeight& cw : scratch_) {
            solid_[cw.cell] += cw.weight * vp;
            weights_.push_back(cw);
        }
        offset_.push_back(static_cast<std::int64_t>(weights_.size()));
    }

    // Void fraction with its floor.
    stats_ = CouplingStepStats{};
    for (int c = 0; c < nCells; ++c) {
        const double raw = 1.0 - solid_[c] / mesh_.cellVolume(c);
        stats_.minRawVoidFraction = std::min(stats_.minRawVoidFraction, raw);
        if (raw < settings_.voidFractionFloor) {
            eps[c] = settings_.voidFractionFloor;
            ++stats_.floorHits;
        } else {
            eps[c] = raw;
        }
    }
}

void CouplingStep::particlesToCells(const OwnedParticles& owned, const double* Ucell,
                                    double* eps, double* K, double* Us) {
    if (!settings_.drag) fail("CouplingStep::particlesToCells: a drag law is required when the air is on");
    voidFraction(owned, eps);
    const int nCells = mesh_.nCells();
    const std::size_t np = owned.size();
    const double s = settings_.coarseGrainingFactor;

    // Drag coefficient per particle, then K and Us per cell.
    beta_.resize(np);
    sumBeta_.assign(nCells, 0.0);
    std::fill(Us, Us + 3 * static_cast<std::size_t>(nCells), 0.0);
    for (std::size_t p = 0; p < np; ++p) {
        Vec3 uf = Vec3::Zero();
        double epsP = 0.0;
        for (std::int64_t k = offset_[p]; k < offset_[p + 1]; ++k) {
            const CellWeight& cw = weights_[k];
            uf += cw.weight * Vec3(Ucell[3 * cw.cell], Ucell[3 * cw.cell + 1], Ucell[3 * cw.cell + 2]);
            epsP += cw.weight * eps[cw.cell];
        }
        const ParticleState& ps = owned.state(p);
        const double dParcel = 2.0 * ps.radius;
        double b = 0.0;
        if (settings_.dragForce) {
            try {
                b = parcelBeta(*settings_.drag, dParcel, s, epsP, (uf - ps.v).norm(), fluid_);
            } catch (const InputError& e) {
                fail<InputError>("particle ", ps.id, " at (", ps.x.transpose(),
                                 "): ", e.what());
            }
        }
        beta_[p] = b;
        for (std::int64_t k = offset_[p]; k < offset_[p + 1]; ++k) {
            const CellWeight& cw = weights_[k];
            const double wb = cw.weight * b;
            sumBeta_[cw.cell] += wb;
            for (int a = 0; a < 3; ++a) Us[3 * cw.cell + a] += wb * ps.v[a];
        }
    }
    for (int c = 0; c < nCells; ++c) {
        K[c] = sumBeta_[c] / mesh_.cellVolume(c);
        if (sumBeta_[c] > 0)
            for (int a = 0; a < 3; ++a) Us[3 * c + a] /= sumBeta_[c];
    }
}

void CouplingStep::cellsToParticles(const OwnedParticles& owned, const double* Ucell,
                                    const double* gradPcell, std::vector<double>& forces,
                                    std::vector<double>* drag) const {
    const std::size_t np = beta_.size();
    if (owned.size() != np)
        fail("CouplingStep::cellsToParticles: ", owned.size(), " particles given, ", np,
             " in the last particlesToCells");
    forces.assign(3 * np, 0.0);
    if (drag) drag->assign(3 * np, 0.0);
    const Vec3 buoyancyPerVolume = -fluid_.rho * settings_.gravity;
    for (std::size_t p = 0; p < np; ++p) {
        Vec3 uf = Vec3::Zero(), gp = Vec3::Zero();
        for (std::int64_t k = offset_[p]; k < offset_[p + 1]; ++k) {
            const CellWeight& cw = weights_[k];
            const int c = cw.cell;
            uf += cw.weight * Vec3(Ucell[3 * c], Ucell[3 * c + 1], Ucell[3 * c + 2]);
            gp += cw.weight * Vec3(gradPcell[3 * c], gradPcell[3 * c + 1], gradPcell[3 * c + 2]);
        }
        const ParticleState& ps = owned.state(p);
        const double vp = volume(ps);
        const Vec3 fd = beta_[p] * (uf - ps.v);
        Vec3 f = fd;
        if (settings_.pressureGradientForce) f -= vp * gp;
        if (settings_.buoyancyForce) f += vp * buoyancyPerVolume;
        for (int a = 0; a < 3; ++a) {
            forces[3 * p + a] = f[a];
            if (drag) (*drag)[3 * p + a] = fd[a];
        }
    }
}

std::size_t CouplingStep::particleBufferBytes() const {
    return capacityBytes(offset_) + capacityBytes(weights_) + capacityBytes(beta_) + capacityBytes(scratch_);
}

std::size_t CouplingStep::cellBufferBytes() const { return capacityBytes(solid_) + capacityBytes(sumBeta_); }

}  // namespace granair
