// Collective.hpp: raise an error on all ranks together.
//
// An error found on one rank (bad particle, NaN) must end the job on every
// rank, never leave the others blocked in the next message. At a check point
// every rank calls raiseIfAny(comm, localMessage): if any rank has a message,
// the lowest such rank's message is broadcast and every rank throws a
// CollectiveError (an InputError) with it (prefixed by the rank it came from).
#pragma once
#include <mpi.h>

#include <string>

namespace granair {

// localMessage empty == no error on this rank. Collective over comm.
void raiseIfAny(MPI_Comm comm, const std::string& localMessage);

}  // namespace granair
