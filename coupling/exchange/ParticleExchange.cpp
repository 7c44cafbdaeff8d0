// ParticleExchange.cpp: see ParticleExchange.hpp and docs/exchange.md.
#include "exchange/ParticleExchange.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "core/Collective.hpp"
#include "core/Error.hpp"
#include "exchange/RankBoxIndex.hpp"
#include "exchange/RecordMessage.hpp"
#include "exchange/SparseExchange.hpp"

namespace granair {

namespace {

// Tags on the exchange's private communicator. The records go by NBX, whose
// consecutive calls alternate between two tags (see SparseExchange.hpp); the
// other messages have a known pattern, at most one per (pair, tag, call), and
// MPI's non-overtaking rule keeps consecutive calls apart.
constexpr int kTagRecords[2] = {4101, 4102};
constexpr int kTagFound = 4103;   // candidate -> DEM owner: found flag per multi record
constexpr int kTagKeep = 4104;    // DEM owner -> finder: keep flag per multi record
constexpr int kTagValues = 4105;  // backward(): values, CFD owner -> DEM owner

std::string show(const Vec3& x) {
    std::ostringstream os;
    os.precision(10);
    os << '(' << x[0] << ' ' << x[1] << ' ' << x[2] << ')';
    return os.str();
}

// Keeps the first error message of this rank (raised collectively later).
struct FirstError {
    std::string message;
    template <class... Parts>
    void note(const Parts&... parts) {
        if (!message.empty()) return;
        std::ostringstream os;
        os.precision(10);
        (os << ... << parts);
        message = os.str();
    }
};

}  // namespace

struct ParticleExchange::Impl {
    MPI_Comm comm = MPI_COMM_NULL;  // private duplicate of the user's comm
    RankBoxIndex boxes;             // inflated CFD boxes of all ranks
    std::uint64_t forwardCalls = 0;
    bool routesValid = false;     // last forward() succeeded
    std::vector<int> candidates;  // scratch: candidate ranks of one particle

    // ---- DEM side: this rank's particles going out ----
    // Records for one remote candidate rank.
    struct Outbox {
        int rank = -1;
        std::vector<char> message;        // records + trailer (RecordMessage.hpp)
        std::vector<std::int64_t> multi;  // positions of multi records in message
        std::vector<int> dem;             // dem index of each record
        std::vector<char> found;          // reply: found flag per multi record
        std::vector<char> keep;           // decision: keep flag per multi record
        bool anyFound() const {
            for (char f : found)
                if (f) return true;
            return false;
        }
    };
    std::vector<Outbox> outboxes;  // the first nOutboxes are in use (reused storage)
    int nOutboxes = 0;
    std::vector<int> outboxOfRank;  // rank -> outbox or -1 (O(nRanks), like the bounds)
    // Records this rank is itself a candidate for (never go through MPI).
    std::vector<int> selfDem, selfCell;
    std::vector<char> selfMulti, selfKeep;
    // Particles with several candidates, and their candidates in rank order.
    struct Candidate {
        int rank;
        int outbox;  // -1: this rank
        int index;   // position in the outbox's multi list, or in the self lists
    };
    struct Multi {
        int dem, first, count;
    };
    std::vector<Multi> multis;
    std::vector<Candidate> multiCandidates;

    // ---- CFD side: records that came in ----
    SparseInbox inbox;
    struct Inbound {
        int rank = -1;
        const char* records = nullptr;
        record::Layout layout;
        std::size_t firstCell = 0;  // into cells
        int foundMulti = 0;         // multi records found here
        std::vector<char> found;    // reply sent to the DEM owner
        std::vector<char> keep;     // decision received from the DEM owner
    };
    std::vector<Inbound> inbound;  // first nInbound in use, ascending rank
    int nInbound = 0;
    std::vector<int> cells;  // findCell of every inbound record

    // ---- routes of the last forward(), for backward() ----
    struct Route {
        int rank;
        std::size_t first, count;
    };
    // DEM side: per CFD owner rank, the dem indices it kept (in dem order) are
    // routeDem[first .. first+count).
    std::vector<Route> sendRoutes;
    std::vector<int> routeDem;
    // CFD side: per source rank (ascending), owned[first .. first+count).
    std::vector<Route> recvRoutes;
    std::size_t nDem = 0, nOwned = 0;
    std::vector<double> values;  // backward(): received values
    std::vector<MPI_Request> requests;

    int outboxFor(int rank) {
        int& b = outboxOfRank[rank];
        if (b >= 0) return b;
        b = nOutboxes++;
        if (static_cast<int>(outboxes.size()) < nOutboxes) outboxes.emplace_back();
        Outbox& o = outboxes[b];
        o.rank = rank;
        o.message.clear();
        o.multi.clear();
        o.dem.clear();
        o.found.clear();
        o.keep.clear();
        return b;
    }
};

ParticleExchange::ParticleExchange(MPI_Comm comm, const CellLocator& mesh, double margin)
    : comm_(comm), mesh_(mesh), margin_(margin), impl_(std::make_unique<Impl>()) {
    MPI_Comm_rank(comm, &rank_);
    MPI_Comm_size(comm, &size_);
    std::string bad;
    if (!(margin >= 0) || !std::isfinite(margin)) {
        std::ostringstream os;
        os << "ParticleExchange: margin = " << margin << " m; expected a finite value >= 0";
        bad = os.str();
    }
    raiseIfAny(comm, bad);
    MPI_Comm_dup(comm, &impl_->comm);
    impl_->outboxOfRank.assign(size_, -1);
    updateBounds();
}

ParticleExchange::~ParticleExchange() {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (impl_ && impl_->comm != MPI_COMM_NULL && !finalized) MPI_Comm_free(&impl_->comm);
}

void ParticleExchange::updateBounds() {
    const Box mine = mesh_.bounds();
    double local[6] = {mine.lo[0], mine.lo[1], mine.lo[2], mine.hi[0], mine.hi[1], mine.hi[2]};
    std::vector<double> all(6 * static_cast<std::size_t>(size_));
    MPI_Allgather(local, 6, MPI_DOUBLE, all.data(), 6, MPI_DOUBLE, impl_->comm);
    cfdBounds_.resize(size_);
    std::vector<Box> inflated(size_);
    for (int r = 0; r < size_; ++r) {
        cfdBounds_[r].lo = Vec3(all[6 * r], all[6 * r + 1], all[6 * r + 2]);
        cfdBounds_[r].hi = Vec3(all[6 * r + 3], all[6 * r + 4], all[6 * r + 5]);
        // An empty box (a rank with no cells) stays empty when inflated.
        inflated[r] = cfdBounds_[r].empty() ? Box{} : cfdBounds_[r].inflated(margin_);
    }
    impl_->boxes.build(inflated);
}

void ParticleExchange::forward(const std::vector<ParticleState>& dem, std::vector<OwnedParticle>& owned,
                               Outside outsidePolicy) {
    Impl& m = *impl_;
    m.routesValid = false;
    stats_ = ExchangeStats{};
    owned.clear();
    FirstError error;
    // A particle in no rank's cells: an error, or (Outside::skip) counted.
    auto outside = [&](const auto&... parts) {
        if (outsidePolicy == Outside::skip)
            ++stats_.outside;
        else
            error.note(parts...);
    };

    // ---- 1. candidates, records packed per destination ----
    for (int b = 0; b < m.nOutboxes; ++b) m.outboxOfRank[m.outboxes[b].rank] = -1;
    m.nOutboxes = 0;
    m.selfDem.clear();
    // m.selfCell keeps the last step's cells: they are the first hints in 3.
    m.selfMulti.clear();
    m.multis.clear();
    m.multiCandidates.clear();
    for (int i = 0; i < static_cast<int>(dem.size()); ++i) {
        const ParticleState& p = dem[i];
        if (!p.x.allFinite()) {
            error.note("particle ", p.id, " has a non-finite position ", show(p.x),
                       "; expected finite coordinates [m]");
            continue;
        }
        if (!p.v.allFinite()) {
            error.note("particle ", p.id, " at ", show(p.x), " has a non-finite velocity ", show(p.v),
                       "; expected finite components [m/s]");
            continue;
        }
        if (!(p.radius > 0) || !std::isfinite(p.radius)) {
            error.note("particle ", p.id, " at ", show(p.x), " has radius ", p.radius,
                       " m; expected a finite radius > 0");
            continue;
        }
        m.boxes.find(p.x, m.candidates);
        if (m.candidates.empty()) {
            outside("particle ", p.id, " at ", show(p.x),
                    " is outside the CFD mesh (in no rank's CFD subdomain box)");
            continue;
        }
        const bool multi = m.candidates.size() > 1;
        if (multi)
            m.multis.push_back(
                {i, static_cast<int>(m.multiCandidates.size()), static_cast<int>(m.candidates.size())});
        for (int r : m.candidates) {
            ++stats_.particlesSent;
            if (r == rank_) {
                if (multi) m.multiCandidates.push_back({r, -1, static_cast<int>(m.selfDem.size())});
                m.selfDem.push_back(i);
                m.selfMulti.push_back(multi);
                continue;
            }
            const int b = m.outboxFor(r);
            Impl::Outbox& o = m.outboxes[b];
            if (multi) {
                m.multiCandidates.push_back({r, b, static_cast<int>(o.multi.size())});
                o.multi.push_back(static_cast<std::int64_t>(o.dem.size()));
            }
            o.dem.push_back(i);
            record::append(o.message, p);
        }
    }

    // ---- 2. records to the remote candidates (NBX) ----
    std::vector<SparseSend> sends;
    sends.reserve(m.nOutboxes);
    for (int b = 0; b < m.nOutboxes; ++b) {
        Impl::Outbox& o = m.outboxes[b];
        record::appendTrailer(o.message, o.multi);
        sends.push_back({o.rank, o.message.data(), o.message.size()});
        stats_.bytesSent += static_cast<std::int64_t>(o.message.size());
    }
    stats_.partners = m.nOutboxes;
    sparseExchange(m.comm, kTagRecords[m.forwardCalls++ % 2], sends, m.inbox);

    // ---- 3. locate: own records, then inbound ones ----
    // Two hints before the locator's global search (which costs tens of
    // microseconds per particle on thin or skewed meshes):
    // - own particles: the cell found at the same position of the list in the
    //   last forward(). The DEM keeps its local order between re-sorts, and a
    //   particle moves less than a cell per coupling step, so this is mostly
    //   the particle's own last cell (no per-particle storage beyond the
    //   selfCell list this class keeps anyway);
    // - then the previous record's cell: DEM codes sort their particles in
    //   space, so neighbours in the list are mostly in the same or an
    //   adjacent cell (this also covers the steps right after a re-sort).
    // Hints only choose where to look first; a wrong one never gives a wrong cell.
    int hint = -1;
    const std::size_t previous = m.selfCell.size();
    m.selfCell.resize(m.selfDem.size());
    for (std::size_t j = 0; j < m.selfDem.size(); ++j) {
        const ParticleState& p = dem[m.selfDem[j]];
        const int near = j < previous ? mesh_.findCellNear(p.x, m.selfCell[j]) : -1;
        m.selfCell[j] = near >= 0 ? near : mesh_.findCell(p.x, hint);
        if (m.selfCell[j] >= 0) hint = m.selfCell[j];
        if (m.selfCell[j] < 0 && !m.selfMulti[j])
            outside("particle ", p.id, " at ", show(p.x), " is outside the CFD mesh (in rank ", rank_,
                    "'s CFD box but in none of its cells)");
    }
    m.nInbound = static_cast<int>(m.inbox.messages.size());
    if (static_cast<int>(m.inbound.size()) < m.nInbound) m.inbound.resize(m.nInbound);
    m.cells.clear();
    for (int n = 0; n < m.nInbound; ++n) {
        const SparseMessage& msg = m.inbox.messages[n];
        Impl::Inbound& in = m.inbound[n];
        in.rank = msg.rank;
        in.records = m.inbox.bytes.data() + msg.offset;
        in.firstCell = m.cells.size();
        in.foundMulti = 0;
        if (!record::parse(in.records, msg.bytes, in.layout)) {
            // Cannot happen with messages written by this class; reported, not trusted.
            error.note("ParticleExchange: malformed record message of ", msg.bytes, " bytes from rank ",
                       msg.rank);
            in.layout = record::Layout{};
        }
        in.found.assign(in.layout.nMulti, 0);
        std::size_t mi = 0;
        for (std::size_t k = 0; k < in.layout.nRecords; ++k) {
            const ParticleState p = record::read(in.records, k);
            const int cell = mesh_.findCell(p.x, hint);
            if (cell >= 0) hint = cell;
            m.cells.push_back(cell);
            if (mi < in.layout.nMulti && record::multiAt(in.layout, mi) == static_cast<std::int64_t>(k)) {
                in.found[mi++] = cell >= 0;
                in.foundMulti += cell >= 0;
            } else if (cell < 0) {
                outside("particle ", p.id, " at ", show(p.x), " is outside the CFD mesh (in rank ", rank_,
                        "'s CFD box but in none of its cells)");
            }
        }
    }

    // ---- 4. found flags of the multi records back to their DEM owners ----
    // Pattern known on both sides: an outbox with multi records expects one
    // reply; an inbound message with multi records sends one.
    m.requests.clear();
    for (int b = 0; b < m.nOutboxes; ++b) {
        Impl::Outbox& o = m.outboxes[b];
        if (o.multi.empty()) continue;
        o.found.assign(o.multi.size(), 0);
        m.requests.emplace_back();
        MPI_Irecv(o.found.data(), static_cast<int>(o.found.size()), MPI_BYTE, o.rank, kTagFound, m.comm,
                  &m.requests.back());
    }
    for (int n = 0; n < m.nInbound; ++n) {
        Impl::Inbound& in = m.inbound[n];
        if (in.layout.nMulti == 0) continue;
        m.requests.emplace_back();
        MPI_Isend(in.found.data(), static_cast<int>(in.found.size()), MPI_BYTE, in.rank, kTagFound, m.comm,
                  &m.requests.back());
        stats_.bytesSent += static_cast<std::int64_t>(in.found.size());
    }
    MPI_Waitall(static_cast<int>(m.requests.size()), m.requests.data(), MPI_STATUSES_IGNORE);

    // ---- 5. owner of each multi particle: the lowest rank that found it ----
    for (int b = 0; b < m.nOutboxes; ++b) m.outboxes[b].keep.assign(m.outboxes[b].multi.size(), 0);
    m.selfKeep.assign(m.selfDem.size(), 0);
    for (const Impl::Multi& mp : m.multis) {
        int owner = -1;
        for (int c = mp.first; c < mp.first + mp.count && owner < 0; ++c) {
            const Impl::Candidate& cand = m.multiCandidates[c];
            const bool found =
                cand.outbox < 0 ? m.selfCell[cand.index] >= 0 : m.outboxes[cand.outbox].found[cand.index];
            if (found) owner = cand.rank;  // candidates are in ascending rank order
        }
        if (owner < 0) {
            const ParticleState& p = dem[mp.dem];
            outside("particle ", p.id, " at ", show(p.x), " is outside the CFD mesh (none of the ",
                    mp.count, " ranks whose CFD box contains it has a cell containing it)");
            continue;
        }
        for (int c = mp.first; c < mp.first + mp.count; ++c) {
            const Impl::Candidate& cand = m.multiCandidates[c];
            if (cand.rank != owner) continue;
            (cand.outbox < 0 ? m.selfKeep[cand.index] : m.outboxes[cand.outbox].keep[cand.index]) = 1;
        }
    }

    // ---- 6. keep/drop to every rank that found a multi record ----
    // Pattern known on both sides: a finder of >= 1 multi record expects one
    // decision, and its DEM owner knows it from the found flags.
    m.requests.clear();
    for (int n = 0; n < m.nInbound; ++n) {
        Impl::Inbound& in = m.inbound[n];
        in.keep.assign(in.layout.nMulti, 0);
        if (in.foundMulti == 0) continue;
        m.requests.emplace_back();
        MPI_Irecv(in.keep.data(), static_cast<int>(in.keep.size()), MPI_BYTE, in.rank, kTagKeep, m.comm,
                  &m.requests.back());
    }
    for (int b = 0; b < m.nOutboxes; ++b) {
        Impl::Outbox& o = m.outboxes[b];
        if (!o.anyFound()) continue;
        m.requests.emplace_back();
        MPI_Isend(o.keep.data(), static_cast<int>(o.keep.size()), MPI_BYTE, o.rank, kTagKeep, m.comm,
                  &m.requests.back());
        stats_.bytesSent += static_cast<std::int64_t>(o.keep.size());
    }
    MPI_Waitall(static_cast<int>(m.requests.size()), m.requests.data(), MPI_STATUSES_IGNORE);

    // ---- 7. routes (DEM side) and the owned list (CFD side) ----
    m.sendRoutes.clear();
    m.routeDem.clear();
    for (int b = 0; b < m.nOutboxes; ++b) {
        const Impl::Outbox& o = m.outboxes[b];
        const std::size_t first = m.routeDem.size();
        std::size_t mi = 0;
        for (std::size_t k = 0; k < o.dem.size(); ++k) {
            const bool isMulti = mi < o.multi.size() && o.multi[mi] == static_cast<std::int64_t>(k);
            if (!isMulti || o.keep[mi]) m.routeDem.push_back(o.dem[k]);
            mi += isMulti;
        }
        if (m.routeDem.size() > first) m.sendRoutes.push_back({o.rank, first, m.routeDem.size() - first});
    }
    {
        const std::size_t first = m.routeDem.size();
        for (std::size_t j = 0; j < m.selfDem.size(); ++j)
            if (m.selfMulti[j] ? m.selfKeep[j] : m.selfCell[j] >= 0) m.routeDem.push_back(m.selfDem[j]);
        if (m.routeDem.size() > first) m.sendRoutes.push_back({rank_, first, m.routeDem.size() - first});
    }

    m.recvRoutes.clear();
    auto takeSelf = [&] {
        const std::size_t first = owned.size();
        for (std::size_t j = 0; j < m.selfDem.size(); ++j)
            if (m.selfMulti[j] ? m.selfKeep[j] : m.selfCell[j] >= 0)
                owned.push_back({dem[m.selfDem[j]], m.selfCell[j]});
        if (owned.size() > first) m.recvRoutes.push_back({rank_, first, owned.size() - first});
    };
    bool selfTaken = false;
    for (int n = 0; n < m.nInbound; ++n) {
        const Impl::Inbound& in = m.inbound[n];
        if (!selfTaken && rank_ < in.rank) {
            takeSelf();
            selfTaken = true;
        }
        const std::size_t first = owned.size();
        std::size_t mi = 0;
        for (std::size_t k = 0; k < in.layout.nRecords; ++k) {
            const int cell = m.cells[in.firstCell + k];
            const bool isMulti =
                mi < in.layout.nMulti && record::multiAt(in.layout, mi) == static_cast<std::int64_t>(k);
            const bool keep = isMulti ? (cell >= 0 && in.keep[mi]) : cell >= 0;
            mi += isMulti;
            if (keep) owned.push_back({record::read(in.records, k), cell});
        }
        if (owned.size() > first) m.recvRoutes.push_back({in.rank, first, owned.size() - first});
    }
    if (!selfTaken) takeSelf();

    m.nDem = dem.size();
    m.nOwned = owned.size();
    // ---- 8. any bad particle anywhere: every rank throws the same error ----
    raiseIfAny(m.comm, error.message);
    m.routesValid = true;
}

void ParticleExchange::backward(const std::vector<double>& ownedValues, int width, std::vector<double>& out) {
    Impl& m = *impl_;
    // Checked collectively: a rank throwing alone would leave its partners
    // waiting for its values. One allreduce carries the local verdict and the
    // width range (a width mismatch would garble every message).
    std::string bad;
    if (!m.routesValid) {
        bad = "ParticleExchange::backward(): the last forward() did not succeed (or was never called)";
    } else if (width < 1) {
        bad = "ParticleExchange::backward(): width = " + std::to_string(width) + "; expected >= 1";
    } else if (ownedValues.size() != m.nOwned * static_cast<std::size_t>(width)) {
        bad = "ParticleExchange::backward(): got " + std::to_string(ownedValues.size()) + " values for " +
              std::to_string(m.nOwned) + " owned particles of width " + std::to_string(width) +
              "; expected owned.size() * width";
    }
    int check[3] = {bad.empty() ? 0 : 1, width, -width}, global[3];
    MPI_Allreduce(check, global, 3, MPI_INT, MPI_MAX, m.comm);
    if (global[0] != 0 || global[1] != -global[2]) {
        if (bad.empty() && global[1] != -global[2])
            bad = "ParticleExchange::backward(): width differs between ranks (" + std::to_string(-global[2]) +
                  " to " + std::to_string(global[1]) + "); expected the same width on every rank";
        raiseIfAny(m.comm, bad);
    }

    const std::size_t w = static_cast<std::size_t>(width);
    out.assign(m.nDem * w, std::numeric_limits<double>::quiet_NaN());
    std::size_t total = 0;
    for (const Impl::Route& r : m.sendRoutes)
        if (r.rank != rank_) total += r.count * w;
    m.values.resize(total);

    m.requests.clear();
    std::size_t at = 0;
    for (const Impl::Route& r : m.sendRoutes) {
        if (r.rank == rank_) continue;
        m.requests.emplace_back();
        MPI_Irecv(m.values.data() + at, static_cast<int>(r.count * w), MPI_DOUBLE, r.rank, kTagValues, m.comm,
                  &m.requests.back());
        at += r.count * w;
    }
    for (const Impl::Route& r : m.recvRoutes) {
        const double* src = ownedValues.data() + r.first * w;
        if (r.rank == rank_) {
            // Own particles: the self route lists their dem indices in the
            // same order as they were appended to `owned`.
            for (const Impl::Route& s : m.sendRoutes)
                if (s.rank == rank_)
                    for (std::size_t k = 0; k < s.count; ++k)
                        for (std::size_t j = 0; j < w; ++j)
                            out[m.routeDem[s.first + k] * w + j] = src[k * w + j];
            continue;
        }
        m.requests.emplace_back();
        MPI_Isend(src, static_cast<int>(r.count * w), MPI_DOUBLE, r.rank, kTagValues, m.comm,
                  &m.requests.back());
        stats_.bytesSent += static_cast<std::int64_t>(r.count * w * sizeof(double));
    }
    MPI_Waitall(static_cast<int>(m.requests.size()), m.requests.data(), MPI_STATUSES_IGNORE);

    at = 0;
    for (const Impl::Route& r : m.sendRoutes) {
        if (r.rank == rank_) continue;
        for (std::size_t k = 0; k < r.count; ++k)
            for (std::size_t j = 0; j < w; ++j)
                out[m.routeDem[r.first + k] * w + j] = m.values[at + k * w + j];
        at += r.count * w;
    }
}

namespace {
template <class T>
std::size_t capacityBytes(const std::vector<T>& v) {
    return v.capacity() * sizeof(T);
}
}  // namespace

std::size_t ParticleExchange::bufferBytes() const {
    const Impl& m = *impl_;
    std::size_t n = capacityBytes(m.candidates) + capacityBytes(m.outboxes) + capacityBytes(m.outboxOfRank) +
                    capacityBytes(m.selfDem) + capacityBytes(m.selfCell) + capacityBytes(m.selfMulti) +
                    capacityBytes(m.selfKeep) + capacityBytes(m.multis) + capacityBytes(m.multiCandidates) +
                    capacityBytes(m.inbox.bytes) + capacityBytes(m.inbox.messages) +
                    capacityBytes(m.inbound) + capacityBytes(m.cells) + capacityBytes(m.sendRoutes) +
                    capacityBytes(m.routeDem) + capacityBytes(m.recvRoutes) + capacityBytes(m.values) +
                    capacityBytes(m.requests) + capacityBytes(cfdBounds_);
    for (const Impl::Outbox& o : m.outboxes)
        n += capacityBytes(o.message) + capacityBytes(o.multi) + capacityBytes(o.dem) +
             capacityBytes(o.found) + capacityBytes(o.keep);
    for (const Impl::Inbound& in : m.inbound) n += capacityBytes(in.found) + capacityBytes(in.keep);
    return n;
}

}  // namespace granair
