// Collective.cpp: see Collective.hpp.
#include "core/Collective.hpp"

#include <climits>
#include <vector>

#include "core/Error.hpp"

namespace granair {

void raiseIfAny(MPI_Comm comm, const std::string& localMessage) {
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    int mine = localMessage.empty() ? INT_MAX : rank;
    int first = INT_MAX;
    MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm);
    if (first == INT_MAX) return;
    int len = rank == first ? static_cast<int>(localMessage.size()) : 0;
    MPI_Bcast(&len, 1, MPI_INT, first, comm);
    std::vector<char> buf(localMessage.begin(), localMessage.end());
    buf.resize(len);
    MPI_Bcast(buf.data(), len, MPI_CHAR, first, comm);
    int size = 1;
    MPI_Comm_size(comm, &size);
    std::string msg(buf.begin(), buf.end());
    if (size > 1) msg = "(rank " + std::to_string(first) + ") " + msg;
    throw CollectiveError(msg);
}

}  // namespace granair
