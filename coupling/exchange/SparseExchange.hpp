// SparseExchange.hpp: dynamic sparse data exchange (the NBX algorithm).
//
// Every rank sends one byte buffer to each of a few ranks; no rank knows in
// advance who will send to it. NBX (Hoefler, Siebert & Lumsdaine, "Scalable
// communication protocols for dynamic sparse data exchange", PPoPP 2010,
// doi:10.1145/1693453.1693476) solves this without any O(nRanks) step:
//   1. MPI_Issend every buffer (a synchronous send completes only once the
//      receiver has MATCHED it);
//   2. loop: MPI_Improbe for any message with `tag`, receive it;
//      once all own sends have completed, enter an MPI_Ibarrier;
//      when the barrier completes, stop.
// The barrier completes only after every rank has entered it, i.e. after every
// message of this exchange has been matched, so on return nothing of this
// exchange is left in flight.
//
// Message matching between consecutive exchanges on the same communicator:
// a rank that leaves exchange n early may already send its messages of
// exchange n+1 while a slower rank is still probing in exchange n. If both
// used the same tag the slow rank would take them as messages of exchange n.
// It cannot get further ahead than that (it cannot complete the barrier of
// n+1 until everybody has entered it), so alternating between TWO tags for
// consecutive calls from one call site is enough (see ParticleExchange, which
// also runs on its own duplicated communicator so no other code shares them).
// A collective between two calls (e.g. an MPI_Allreduce) makes one tag safe
// too, but the two-tag rule does not depend on it.
#pragma once
#include <mpi.h>

#include <cstddef>
#include <vector>

namespace granair {

// One outgoing buffer. The data must stay valid until sparseExchange returns.
struct SparseSend {
    int rank = 0;
    const void* data = nullptr;
    std::size_t bytes = 0;
};

// One received message: its payload is inbox.bytes[offset, offset + bytes).
struct SparseMessage {
    int rank = 0;
    std::size_t offset = 0;  // multiple of 8, so 8-byte words stay aligned
    std::size_t bytes = 0;
};

// Everything received by one call; reuse it across calls to keep its memory.
struct SparseInbox {
    std::vector<char> bytes;              // all payloads back to back
    std::vector<SparseMessage> messages;  // sorted by source rank
};

// Send sends[i] to sends[i].rank (at most one buffer per destination; sending
// to oneself works but costs an MPI round trip) and receive everything sent
// to this rank with `tag`. Collective over comm: every rank must call it,
// with the same tag, even with nothing to send. Each buffer must be below
// 2^31 bytes. Fills `inbox` (cleared first), messages sorted by source rank.
void sparseExchange(MPI_Comm comm, int tag, const std::vector<SparseSend>& sends, SparseInbox& inbox);

}  // namespace granair
