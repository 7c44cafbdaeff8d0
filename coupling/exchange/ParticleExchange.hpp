// ParticleExchange.hpp: many-to-many routing of particles between the DEM
// decomposition and the CFD decomposition.
//
// Every rank holds a DEM subdomain (its local particles) and a CFD subdomain
// (its CellLocator). The two decompositions need not match. forward() sends
// each local particle to the rank whose CFD cells contain it; backward()
// returns per-particle values (forces) from there to the particle's DEM
// owner. A rank only talks to the ranks whose (inflated) CFD bounding box
// contains one of its particles: no all-to-all of particle data, no arrays of
// global size, no gather to rank 0. See docs/architecture.md for the protocol.
//
// Errors (a particle in no rank's mesh, NaN position) are raised on ALL ranks
// together (see core/Collective.hpp), so a bad particle never leaves the
// other ranks waiting.
#pragma once
#include <mpi.h>

#include <cstdint>
#include <vector>

#include "core/Particle.hpp"
#include "mapping/CellLocator.hpp"

namespace granair {

// A particle as seen on the rank owning its cell.
struct OwnedParticle {
    ParticleState state;
    int cell = -1;  // local cell index on this rank
};

struct ExchangeStats {
    std::int64_t particlesSent = 0;    // particle records sent in forward() (incl. to self)
    std::int64_t bytesSent = 0;        // bytes sent to other ranks
    int partners = 0;                  // distinct ranks sent to (excluding self)
};

class ParticleExchange {
public:
    // margin [m]: how much each rank's CFD bounding box is inflated when
    // choosing candidate ranks (covers round-off at subdomain faces).
    ParticleExchange(MPI_Comm comm, const CellLocator& mesh, double margin = 1e-9);

    // Re-read every rank's CFD bounding box (O(nRanks) allgather). Called by
    // the constructor; call again only if the mesh moves.
    void updateBounds();

    // Route `dem` (this rank's DEM particles) to their cell owners. On return
    // `owned` holds the particles whose cell this rank owns, ordered by source
    // rank then by position in the source's `dem` (deterministic).
    void forward(const std::vector<ParticleState>& dem, std::vector<OwnedParticle>& owned);

    // Send `width` doubles per owned particle (ordered as `owned` of the last
    // forward()) back to the DEM owners; `out` receives width doubles per
    // `dem` particle of the last forward(), in that order.
    void backward(const std::vector<double>& ownedValues, int width, std::vector<double>& out);

    const ExchangeStats& stats() const { return stats_; }
    MPI_Comm comm() const { return comm_; }

private:
    struct Impl;
    MPI_Comm comm_;
    const CellLocator& mesh_;
    double margin_;
    int rank_ = 0, size_ = 1;
    std::vector<Box> cfdBounds_;  // one per rank
    // Routing of the last forward(): for each destination rank, the indices
    // into `dem` sent there (only those accepted as owned), and for each
    // source rank how many owned particles came from it.
    std::vector<int> sendRanks_;
    std::vector<std::vector<int>> sendIndex_;
    std::vector<int> recvRanks_;
    std::vector<int> recvCount_;
    std::size_t nDem_ = 0, nOwned_ = 0;
    ExchangeStats stats_;
};

}  // namespace granair
