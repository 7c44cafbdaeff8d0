// CouplingStep.cpp: see CouplingStep.hpp for the equations.
#include "coupler/CouplingStep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/CapacityBytes.hpp"
#include "core/Error.hpp"

namespace granair {

// Parcel volume [m3] from its radius.
static double volume(double r) { return 4.0 / 3.0 * M_PI * r * r * r; }

CouplingStep::CouplingStep(const CouplingSettings& settings, const CellLocator& mesh, FluidProperties fluid)
    : settings_(settings), mesh_(mesh), fluid_(fluid) {
    if (!settings_.voidFraction) fail("CouplingStep: a void-fraction model is required");
    centreOnly_ = settings_.voidFraction->centreCellOnly();
}

void CouplingStep::voidFraction(const OwnedParticles& owned, double* eps) {
    const int nCells = mesh_.nCells();
    const std::size_t np = owned.size();

    // Stencils and solid volume.
    if (centreOnly_) {
        offset_.clear();
        solid_.assign(nCells, 0.0);
        for (std::size_t p = 0; p < np; ++p) solid_[owned.cell(p)] += 1.0 * volume(owned.radius(p));
    } else if (!buildStencils(owned)) {
        // A stencil spans more than 16 bits of cell numbers: plain indices
        // from now on on this rank (the step's stencils built again).
        wideCells_ = true;
        std::vector<std::int16_t>().swap(stencilDelta_);
        buildStencils(owned);
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
    reserveAtLeast(beta_, np);
    beta_.resize(np);
    sumBeta_.assign(nCells, 0.0);
    std::fill(Us, Us + 3 * static_cast<std::size_t>(nCells), 0.0);
    for (std::size_t p = 0; p < np; ++p) {
        Vec3 uf = Vec3::Zero();
        double epsP = 0.0;
        forEachWeight(owned, p, [&](int c, double w) {
            uf += w * Vec3(Ucell[3 * c], Ucell[3 * c + 1], Ucell[3 * c + 2]);
            epsP += w * eps[c];
        });
        // Radius and velocity only (the whole state for an error message).
        const Vec3 v = owned.velocity(p);
        const double dParcel = 2.0 * owned.radius(p);
        double b = 0.0;
        if (settings_.dragForce) {
            try {
                b = parcelBeta(*settings_.drag, dParcel, s, epsP, (uf - v).norm(), fluid_);
            } catch (const InputError& e) {
                const ParticleState ps = owned.state(p);
                fail<InputError>("particle ", ps.id, " at (", ps.x.transpose(),
                                 "): ", e.what());
            }
        }
        beta_[p] = b;
        forEachWeight(owned, p, [&](int c, double w) {
            const double wb = w * b;
            sumBeta_[c] += wb;
            for (int a = 0; a < 3; ++a) Us[3 * c + a] += wb * v[a];
        });
    }
    for (int c = 0; c < nCells; ++c) {
        K[c] = sumBeta_[c] / mesh_.cellVolume(c);
        if (sumBeta_[c] > 0)
            for (int a = 0; a < 3; ++a) Us[3 * c + a] /= sumBeta_[c];
    }
}

bool CouplingStep::buildStencils(const OwnedParticles& owned) {
    const std::size_t np = owned.size();
    offset_.clear();
    stencilDelta_.clear();
    stencilCell_.clear();
    stencilWeight_.clear();
    if (np > 0 && stencilWeight_.capacity() == 0) {
        // The first step (usually the most particles a run has): the
        // stencils counted first, so the arrays are sized exactly (one extra
        // stencil evaluation per particle, once per run).
        std::size_t total = 0;
        for (std::size_t p = 0; p < np; ++p) {
            settings_.voidFraction->stencil(mesh_, owned.state(p), owned.cell(p), scratch_);
            total += scratch_.size();
        }
        stencilWeight_.reserve(total);
        if (wideCells_)
            stencilCell_.reserve(total - np);  // total >= np: every stencil has its centre
        else
            stencilDelta_.reserve(total - np);
    } else if (wideCells_ && stencilCell_.capacity() == 0 && np > 0) {
        // Just switched to plain cell indices: as many as the weights.
        stencilCell_.reserve(stencilWeight_.capacity() > np ? stencilWeight_.capacity() - np : 0);
    }
    solid_.assign(mesh_.nCells(), 0.0);
    reserveAtLeast(offset_, np + 1);
    offset_.push_back(0);
    constexpr int maxDelta = std::numeric_limits<std::int16_t>::max();
    for (std::size_t p = 0; p < np; ++p) {
        const ParticleState& ps = owned.state(p);
        const double vp = volume(ps.radius);
        const int centre = owned.cell(p);
        settings_.voidFraction->stencil(mesh_, ps, centre, scratch_);
        if (scratch_.empty() || scratch_.front().cell != centre)
            fail("CouplingStep: the ", settings_.voidFraction->name(), " stencil of particle ", ps.id,
                 " does not start with its centre cell ", centre);
        if (stencilWeight_.size() + scratch_.size() > std::numeric_limits<std::uint32_t>::max())
            fail("CouplingStep: more than 2^32 stencil entries on one rank (", np, " particles)");
        // Beyond the first step's size grown by an eighth, not doubled
        // (CapacityBytes.hpp): the largest per-particle buffers.
        const std::size_t others = stencilWeight_.size() - p + scratch_.size() - 1;
        reserveGrowing(stencilWeight_, stencilWeight_.size() + scratch_.size());
        if (wideCells_)
            reserveGrowing(stencilCell_, others);
        else
            reserveGrowing(stencilDelta_, others);
        solid_[centre] += scratch_.front().weight * vp;
        stencilWeight_.push_back(scratch_.front().weight);
        const CellWeight* const end = scratch_.data() + scratch_.size();
        if (wideCells_) {
            for (const CellWeight* cw = scratch_.data() + 1; cw != end; ++cw) {
                solid_[cw->cell] += cw->weight * vp;
                stencilCell_.push_back(cw->cell);
                stencilWeight_.push_back(cw->weight);
            }
        } else {
            for (const CellWeight* cw = scratch_.data() + 1; cw != end; ++cw) {
                const int d = cw->cell - centre;
                if (d < -maxDelta || d > maxDelta) return false;  // solid_ is rebuilt then
                solid_[cw->cell] += cw->weight * vp;
                stencilDelta_.push_back(static_cast<std::int16_t>(d));
                stencilWeight_.push_back(cw->weight);
            }
        }
        offset_.push_back(static_cast<std::uint32_t>(stencilWeight_.size()));
    }
    return true;
}

CouplingStep::Forces CouplingStep::forces(const OwnedParticles& owned, const double* Ucell,
                                          const double* gradPcell) const {
    if (owned.size() != beta_.size())
        fail("CouplingStep::cellsToParticles: ", owned.size(), " particles given, ", beta_.size(),
             " in the last particlesToCells");
    return Forces(*this, owned, Ucell, gradPcell);
}

void CouplingStep::Forces::operator()(std::size_t p, double* f, double* drag) const {
    const CouplingStep& st = step_;
    Vec3 uf = Vec3::Zero(), gp = Vec3::Zero();
    st.forEachWeight(owned_, p, [&](int c, double w) {
        uf += w * Vec3(U_[3 * c], U_[3 * c + 1], U_[3 * c + 2]);
        gp += w * Vec3(gradP_[3 * c], gradP_[3 * c + 1], gradP_[3 * c + 2]);
    });
    const double vp = volume(owned_.radius(p));
    const Vec3 fd = st.beta_[p] * (uf - owned_.velocity(p));
    Vec3 force = fd;
    if (st.settings_.pressureGradientForce) force -= vp * gp;
    if (st.settings_.buoyancyForce) force += vp * buoyancyPerVolume_;
    for (int a = 0; a < 3; ++a) {
        f[a] = force[a];
        if (drag) drag[a] = fd[a];
    }
}

void CouplingStep::cellsToParticles(const OwnedParticles& owned, const double* Ucell,
                                    const double* gradPcell, std::vector<double>& forces,
                                    std::vector<double>* drag) const {
    const Forces force = this->forces(owned, Ucell, gradPcell);
    const std::size_t np = owned.size();
    forces.assign(3 * np, 0.0);
    if (drag) drag->assign(3 * np, 0.0);
    for (std::size_t p = 0; p < np; ++p) force(p, forces.data() + 3 * p, drag ? drag->data() + 3 * p : nullptr);
}

std::size_t CouplingStep::particleBufferBytes() const {
    return capacityBytes(offset_) + capacityBytes(stencilDelta_) + capacityBytes(stencilCell_) +
           capacityBytes(stencilWeight_) +
           capacityBytes(beta_) + capacityBytes(scratch_);
}

std::size_t CouplingStep::cellBufferBytes() const { return capacityBytes(solid_) + capacityBytes(sumBeta_); }

}  // namespace granair
