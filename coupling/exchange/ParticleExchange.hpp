// ParticleExchange.hpp: many-to-many routing of particles between the DEM
// decomposition and the CFD decomposition.
//
// Every rank holds a DEM subdomain (its local particles) and a CFD subdomain
// (its CellLocator). The two decompositions need not match. forward() sends
// each local particle to the rank whose CFD cells contain it; backward()
// returns per-particle values (forces) from there to the particle's DEM
// owner. A rank only talks to the ranks whose (inflated) CFD bounding box
// contains one of its particles: no all-to-all of particle data, no arrays of
// global size, no gather to rank 0.
//
// Protocol of forward() (details and a picture in docs/exchange.md):
//   1. Candidates: ranks whose CFD box (inflated by `margin`, allgathered once)
//      contains x. Usually one; several within `margin` of a subdomain face.
//   2. Records {id, x, v, radius} go to every candidate by the NBX sparse
//      exchange (exchange/SparseExchange.hpp); each message says which of its
//      records were ALSO sent elsewhere ("multi" records).
//   3. Each candidate calls findCell. A record sent to one rank only is owned
//      there if found, an error if not. For multi records the candidate
//      replies found/not-found (point to point: both sides know the pattern),
//      the DEM owner picks the LOWEST rank that found it and tells every
//      finder keep/drop. Ranks with no multi records skip both rounds.
//   4. One raiseIfAny: any bad particle throws on all ranks together.
// The rank's own particles are never copied: `owned` refers to them by
// index. backward() sends the values back along the routes of the last
// forward() with plain point-to-point messages.
//
// Errors (non-finite position or velocity, radius <= 0, a particle in no
// rank's cells) are raised on ALL ranks together (see core/Collective.hpp),
// so a bad particle never leaves the other ranks waiting. forward() and
// backward() are collective over comm: every rank calls them in the same
// order. The exchange works on its own duplicate of comm, so its messages
// never meet other traffic on comm.
#pragma once
#include <mpi.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/Particle.hpp"
#include "core/ParticleList.hpp"
#include "mapping/CellLocator.hpp"

namespace granair {

// One particle as seen on the rank owning its cell (a copy).
struct OwnedParticle {
    ParticleState state;
    int cell = -1;  // local cell index on this rank
};

// The particles whose cells this rank owns, as forward() leaves them. This
// rank's own DEM particles are referred to by their index in the `dem` list
// given to forward(), never copied, and so are their cells: the list reads
// both from the exchange's own per-particle lists (ParticleExchange.cpp
// `selfDem`, `selfCell`), with no copy of its own. The `dem` list and the
// exchange must stay alive and unchanged while the owned list is used (until
// the next forward()). Records from other ranks are decoded once into a list
// of their own. add() appends a copy (for callers that build a list
// directly, e.g. tests).
class OwnedParticles {
public:
    std::size_t size() const { return selfCount_ + remoteCell_.size(); }
    bool empty() const { return size() == 0; }
    ParticleState state(std::size_t k) const {
        const std::size_t s = k - selfBegin_;  // wraps around for k < selfBegin_
        return s < selfCount_ ? (*local_)[demIndex(s)] : remote_[remoteIndex(k)];
    }
    // state(k)'s radius and velocity alone (ParticleList::radius, velocity).
    double radius(std::size_t k) const {
        const std::size_t s = k - selfBegin_;
        return s < selfCount_ ? local_->radius(demIndex(s)) : remote_[remoteIndex(k)].radius;
    }
    Vec3 velocity(std::size_t k) const {
        const std::size_t s = k - selfBegin_;
        return s < selfCount_ ? local_->velocity(demIndex(s)) : remote_[remoteIndex(k)].v;
    }
    int cell(std::size_t k) const {
        const std::size_t s = k - selfBegin_;
        return s < selfCount_ ? (*selfCell_)[s] : remoteCell_[remoteIndex(k)];
    }
    OwnedParticle operator[](std::size_t k) const { return {state(k), cell(k)}; }

    // Iteration yields copies (OwnedParticle values), for tests and checks;
    // hot loops use state(k) and cell(k).
    class const_iterator {
    public:
        const_iterator(const OwnedParticles* list, std::size_t k) : list_(list), k_(k) {}
        OwnedParticle operator*() const { return (*list_)[k_]; }
        const_iterator& operator++() {
            ++k_;
            return *this;
        }
        bool operator!=(const const_iterator& o) const { return k_ != o.k_; }

    private:
        const OwnedParticles* list_;
        std::size_t k_;
    };
    const_iterator begin() const { return {this, 0}; }
    const_iterator end() const { return {this, size()}; }

    void clear();
    void reserve(std::size_t n);  // room for n remote particles (exactly, not by doubling)
    void add(const ParticleState& p, int cell);
    std::size_t bufferBytes() const;  // its own lists (the remote particles)

private:
    friend class ParticleExchange;
    // Own particle s (0 <= s < selfCount_): its index in the dem list.
    std::size_t demIndex(std::size_t s) const { return selfDem_ ? static_cast<std::size_t>((*selfDem_)[s]) : s; }
    // Owned particle k, not an own one: its index in remote_ and remoteCell_.
    std::size_t remoteIndex(std::size_t k) const { return k < selfBegin_ ? k : k - selfCount_; }
    void addRemote(const ParticleState& p, int cell);
    // The own particles: owned[selfBegin_ .. selfBegin_ + selfCount_) are
    // (*local_)[(*selfDem_)[s]] (selfDem_ null: [s]) in cell (*selfCell_)[s];
    // the remote ones the others, in order.
    void setSelf(const ParticleList* local, const std::vector<int>* selfDem,
                 const std::vector<int>* selfCell, std::size_t count);

    const ParticleList* local_ = nullptr;  // the dem list of the last forward()
    const std::vector<int>* selfDem_ = nullptr;
    const std::vector<int>* selfCell_ = nullptr;
    std::size_t selfBegin_ = 0, selfCount_ = 0;
    std::vector<int> remoteCell_;
    std::vector<ParticleState> remote_;
};

// Counts of this rank for the last forward() and the backward() calls after
// it (forward() resets them).
struct ExchangeStats {
    std::int64_t particlesSent = 0;  // particle records sent in forward() (incl. to self)
    std::int64_t bytesSent = 0;      // bytes sent to other ranks (forward + backward)
    int partners = 0;                // distinct ranks sent to (excluding self)
    std::int64_t outside = 0;        // particles in no rank's cells (Outside::skip), counted once
                                     // over all ranks (sum them for the total)
    // Cell search (locate): own particles not in their last cell (nor its face
    // neighbours; new particles included), own particles of the last forward()
    // now at another list position (a DEM re-sort; their hint found by tag),
    // and searches of the whole local mesh (all hints missed; own and inbound
    // records).
    std::int64_t hintMisses = 0;
    std::int64_t reordered = 0;
    std::int64_t tagSearches = 0;  // of the reordered: found by binary search (TagCellHints)
    std::int64_t globalSearches = 0;
};

class ParticleExchange {
public:
    // margin [m]: how much each rank's CFD bounding box is inflated when
    // choosing candidate ranks (covers round-off at subdomain faces).
    ParticleExchange(MPI_Comm comm, const CellLocator& mesh, double margin = 1e-9);
    ~ParticleExchange();
    ParticleExchange(const ParticleExchange&) = delete;
    ParticleExchange& operator=(const ParticleExchange&) = delete;

    // Re-read every rank's CFD bounding box (O(nRanks) allgather). Called by
    // the constructor; call again only if the mesh moves.
    void updateBounds();

    // What forward() does with a particle that lies in no rank's cells.
    enum class Outside { error, skip };

    // Route `dem` (this rank's DEM particles) to their cell owners. On return
    // `owned` holds the particles whose cell this rank owns, ordered by source
    // rank then by position in the source's `dem` (deterministic). Throws
    // InputError on all ranks, naming the first bad particle, when a particle
    // has a non-finite position or velocity, a radius that is not > 0, or
    // (Outside::error) lies in no rank's cells. With Outside::skip such a
    // particle is owned by no rank, counted in stats().outside, and gets NaN
    // values from backward() (a DEM-only run maps only what is in the mesh).
    void forward(const ParticleList& dem, OwnedParticles& owned, Outside outside = Outside::error);
    // The same for a vector (kept as the list: it must outlive the owned list's use).
    void forward(const std::vector<ParticleState>& dem, OwnedParticles& owned,
                 Outside outside = Outside::error);

    // Send `width` doubles per owned particle (ordered as `owned` of the last
    // forward()) back to the DEM owners; `out` receives width doubles per
    // `dem` particle of the last forward(), in that order. Throws InputError
    // on all ranks when ownedValues.size() != owned.size() * width, when
    // width < 1 or differs between ranks, or when the last forward() failed.
    void backward(const std::vector<double>& ownedValues, int width, std::vector<double>& out);

    // backward() in two halves, with no per-particle array of values in
    // between: backwardFill() calls fill(k, dst) for every owned particle k
    // of the last forward(), which writes its `width` doubles to dst (the DEM
    // owner's slot in `out` for this rank's own particles, the message to
    // their owner for the others; no messages yet, no MPI call);
    // backwardSend() sends those messages and fills the rest of `out` (which
    // must stay alive in between). Both collective in effect: every rank calls
    // backwardSend() after its backwardFill(); the checks of backward() are
    // raised there, on all ranks together (nothing is filled on a rank whose
    // check failed).
    using ValueFill = std::function<void(std::size_t k, double* dst)>;
    void backwardFill(int width, const ValueFill& fill, std::vector<double>& out);
    void backwardSend();
    // backwardFill() with no array for the output either: sink(i, v) gets the
    // `width` values v of dem particle i of the last forward(), once for each
    // dem particle some rank owns (this rank's own during backwardFill(), the
    // others' in backwardSend(); a particle no rank owns, Outside::skip, gets
    // no call). The coupled run puts each force straight into LIGGGHTS.
    using ValueSink = std::function<void(std::size_t demIndex, const double* v)>;
    void backwardFill(int width, const ValueFill& fill, const ValueSink& sink);

    const ExchangeStats& stats() const { return stats_; }
    // Bytes held by the exchange's buffers on this rank (vector capacities,
    // i.e. their high-water mark; the O(nRanks) box index is not counted),
    // for the memory report.
    std::size_t bufferBytes() const;
    MPI_Comm comm() const { return comm_; }

private:
    // Buffers and routes of the last forward(), and the phases of forward()
    // as its member functions; defined in ParticleExchange.cpp.
    struct Impl;
    // Exactly one of out and sink is given.
    void fillBackward(int width, const ValueFill& fill, std::vector<double>* out, const ValueSink* sink,
                      std::string problem);
    MPI_Comm comm_;
    const CellLocator& mesh_;
    double margin_;
    int rank_ = 0, size_ = 1;
    std::vector<Box> cfdBounds_;  // one per rank, not inflated
    ParticleVector vectorList_;   // the list of forward(vector)
    std::unique_ptr<Impl> impl_;
    ExchangeStats stats_;
};

}  // namespace granair
