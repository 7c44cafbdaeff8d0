// SolidVolume.hpp: solid volume per cell from particles and a void-fraction model.
//
// The one place where particle volumes meet the stencils, shared by the
// coupling step and the tests:  Vs_c += w_pc * V_p  for every particle p and
// every (c, w_pc) of p's stencil. Because each stencil sums to 1, the total of
// Vs over the local cells equals the total volume of the particles given, to
// round-off. No flooring of eps happens here: the raw Vs may exceed V_c.
#pragma once
#include <vector>

#include "core/Particle.hpp"
#include "mapping/CellLocator.hpp"
#include "voidfraction/VoidFractionModel.hpp"

namespace granair {

// Volume [m3] of a sphere of radius r [m].
inline double sphereVolume(double r) { return 4.0 / 3.0 * 3.14159265358979323846 * r * r * r; }

// Add each particle's volume to solidVolume over its stencil.
//   particles[i] has its centre in local cell cells[i] (located by the caller).
//   solidVolume: if empty it is set to mesh.nCells() zeros; otherwise it must
//   already have mesh.nCells() entries and is added to (zero it per step).
// Throws InputError naming the particle id for a centre cell that is not a
// local cell (e.g. -1: the particle is not on this rank) or a radius that is
// negative or NaN; throws Error if the array sizes disagree.
void accumulateSolidVolume(const CellLocator& mesh, const VoidFractionModel& model,
                           const std::vector<ParticleState>& particles, const std::vector<int>& cells,
                           std::vector<double>& solidVolume);

}  // namespace granair
