// ParticleVtkWriter.hpp: the particles of a coupled run as a ParaView time
// series (VTK XML PolyData), written in parallel without a gather.
//
// Layout under the output directory, for output number k = 0, 1, ...:
//   particles_<k>/rank<r>.vtp   one piece per rank r: that rank's particles
//                               (written by rank r itself; may be empty)
//   particles_<k>.pvtp          the index of the pieces (rank 0)
//   particles.pvd               the collection: time -> particles_<k>.pvtp,
//                               rewritten by rank 0 after every output, so
//                               ParaView opens the whole series from it
// Every .vtp holds the points (positions [m]), one vertex cell per point (so
// ParaView draws them without a filter), and the point data
//   id          Int64    LIGGGHTS atom tag
//   radius      Float64  parcel radius [m]
//   velocity    Float64  x3, [m/s]
//   fluidForce  Float64  x3, the fluid force of the coupling step [N]
// as appended raw binary (each array: a UInt64 byte count, then the values
// in the machine's byte order, which the header names). Values are written
// bit for bit; nothing is converted or rounded.
//
// The .pvd is rebuilt from this writer's own outputs: a run that starts in an
// existing directory replaces particles.pvd and the particles_<k> it rewrites
// (older, higher-numbered outputs stay on disk but leave the collection).
#pragma once
#include <mpi.h>

#include <string>
#include <utility>
#include <vector>

#include "core/Particle.hpp"
#include "core/ParticleList.hpp"
#include "core/Vec3.hpp"

namespace granair {

class ParticleVtkWriter {
public:
    // Creates `directory` (rank 0, with parents) if missing. Collective:
    // InputError on every rank, naming the path, if it cannot be created.
    ParticleVtkWriter(MPI_Comm comm, std::string directory);
    ParticleVtkWriter(const ParticleVtkWriter&) = delete;
    ParticleVtkWriter& operator=(const ParticleVtkWriter&) = delete;

    // Writes output number outputs() at `time` [s]: this rank's particles
    // (any number, including none) with their fluid force [N], one per
    // particle in the same order. Collective. Throws CollectiveError on
    // every rank together (nothing is written) if forces and particles
    // differ in size on some rank, or the time is not finite or not later
    // than the last output's; and, naming the file, if one cannot be written.
    void write(double time, const std::vector<ParticleState>& particles,
               const std::vector<Vec3>& fluidForces);
    // The same with the forces as nForces x 3 contiguous doubles; nullptr
    // writes zero forces (no fluid force yet, or the air off).
    void write(double time, const std::vector<ParticleState>& particles, const double* fluidForces,
               std::size_t nForces);
    // The same from a list (the coupled run's view of the DEM's arrays).
    void write(double time, const ParticleList& particles, const double* fluidForces, std::size_t nForces);

    int outputs() const { return static_cast<int>(times_.size()); }
    const std::vector<double>& times() const { return times_; }
    // A restart: the outputs already on disk (their times, increasing), so
    // numbering and the collection continue after them.
    void resume(const std::vector<double>& times);
    const std::string& directory() const { return directory_; }
    std::string collectionPath() const { return directory_ + "/particles.pvd"; }

    // File names relative to the directory.
    static std::string indexName(int output);            // particles_<k>.pvtp
    static std::string pieceName(int output, int rank);  // particles_<k>/rank<r>.vtp

private:
    std::string writePiece(int output, const ParticleList& particles, const double* fluidForces) const;
    std::string writeIndex(int output) const;
    std::string writeCollection() const;

    MPI_Comm comm_;
    int rank_ = 0, size_ = 1;
    std::string directory_;
    std::vector<double> times_;  // of the outputs written so far (every rank)
};

}  // namespace granair
