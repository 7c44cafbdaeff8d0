// SparseExchange.cpp: see SparseExchange.hpp.
#include "exchange/SparseExchange.hpp"

#include <algorithm>
#include <climits>

#include "core/Error.hpp"

namespace granair {

void sparseExchange(MPI_Comm comm, int tag, const std::vector<SparseSend>& sends, SparseInbox& inbox) {
    inbox.bytes.clear();
    inbox.messages.clear();

    // Checked before anything is posted: a throw after the first Issend would
    // leave the other ranks waiting for a barrier this rank never enters.
    for (std::size_t i = 0; i < sends.size(); ++i) {
        if (sends[i].bytes > static_cast<std::size_t>(INT_MAX))
            fail<Error>("sparseExchange: a buffer of ", sends[i].bytes, " bytes to rank ", sends[i].rank,
                        " exceeds the 2^31-1 byte limit of one MPI message");
        for (std::size_t j = 0; j < i; ++j)
            if (sends[j].rank == sends[i].rank)
                fail<Error>("sparseExchange: two buffers for rank ", sends[i].rank, " (send at most one)");
    }

    std::vector<MPI_Request> sendRequests(sends.size(), MPI_REQUEST_NULL);
    for (std::size_t i = 0; i < sends.size(); ++i)
        MPI_Issend(sends[i].data, static_cast<int>(sends[i].bytes), MPI_BYTE, sends[i].rank, tag, comm,
                   &sendRequests[i]);

    MPI_Request barrier = MPI_REQUEST_NULL;
    bool inBarrier = false;
    for (;;) {
        int arrived = 0;
        MPI_Message message;
        MPI_Status status;
        // Matched probe + receive: the message probed is the one received,
        // even if another thread were probing the same communicator.
        MPI_Improbe(MPI_ANY_SOURCE, tag, comm, &arrived, &message, &status);
        if (arrived) {
            int count = 0;
            MPI_Get_count(&status, MPI_BYTE, &count);
            const std::size_t offset = (inbox.bytes.size() + 7) / 8 * 8;
            inbox.bytes.resize(offset + static_cast<std::size_t>(count));
            MPI_Mrecv(inbox.bytes.data() + offset, count, MPI_BYTE, &message, MPI_STATUS_IGNORE);
            inbox.messages.push_back({status.MPI_SOURCE, offset, static_cast<std::size_t>(count)});
            continue;  // drain what has arrived before testing for completion
        }
        int done = 0;
        if (inBarrier) {
            MPI_Test(&barrier, &done, MPI_STATUS_IGNORE);
            if (done) break;
        } else {
            MPI_Testall(static_cast<int>(sendRequests.size()), sendRequests.data(), &done,
                        MPI_STATUSES_IGNORE);
            if (done) {
                MPI_Ibarrier(comm, &barrier);
                inBarrier = true;
            }
        }
    }

    std::sort(inbox.messages.begin(), inbox.messages.end(),
              [](const SparseMessage& a, const SparseMessage& b) { return a.rank < b.rank; });
}

}  // namespace granair
