// bench_exchange.cpp: time the particle exchange of one coupling step.
//
// Every rank holds N/nRanks particles of its DEM slab; the CFD mesh is a
// BoxMesh of 40^3 cells in slabs. Two layouts: DEM slabs along x vs CFD
// slabs along z (decompositions that differ: almost every particle changes
// rank) and both along z (matched: only face particles cross). Particles move
// a little between steps. Per step, each phase is timed between barriers and
// the slowest rank counts; the median over the steps is printed (and the
// fastest step's total: on a shared, loaded machine the median includes
// scheduler preemptions of a few ms, the minimum is closer to the cost):
//   findCell   a bare findCell loop over the owned particles (the mapping cost)
//   forward    ParticleExchange::forward (includes its own findCell calls)
//   backward   ParticleExchange::backward with 3 doubles (a force) per particle
//   total      forward + backward (median, and min over the steps)
// in microseconds of wall time per particle (N = all particles), plus the
// bytes sent to other ranks per particle (forward + backward, all ranks).
//
// Usage: bench_exchange [steps=20] [N ...=10000 100000]
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "exchange/ParticleExchange.hpp"
#include "mapping/BoxMesh.hpp"

using namespace granair;

namespace {

const Vec3 kLo(0, 0, 0), kHi(1, 1, 1);
const BoxMesh::Index3 kCells{40, 40, 40};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// Wall time of the slowest rank since t0.
double slowest(double t0) {
    double mine = MPI_Wtime() - t0, worst = 0;
    MPI_Allreduce(&mine, &worst, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    return worst;
}

void run(long nGlobal, int demAxis, int steps, int rank, int size) {
    const BoxMesh mesh = BoxMesh::slab(kLo, kHi, kCells, size, rank, 2);
    ParticleExchange ex(MPI_COMM_WORLD, mesh);

    const long nLocal = nGlobal / size + (rank < nGlobal % size ? 1 : 0);
    std::mt19937_64 rng(77 + rank);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<ParticleState> dem(nLocal);
    for (long i = 0; i < nLocal; ++i) {
        ParticleState& p = dem[i];
        p.id = rank * 100000000L + i;
        for (int a = 0; a < 3; ++a) {
            p.x[a] = u(rng);
            p.v[a] = 0.2 * (u(rng) - 0.5);
        }
        p.x[demAxis] = (rank + u(rng)) / size;  // this rank's DEM slab
        p.radius = 1e-4;
    }

    OwnedParticles owned;
    std::vector<double> forces, out;
    std::vector<double> tFind, tForward, tBackward, tTotal, bytes;
    const double dt = 1e-3;
    for (int step = -2; step < steps; ++step) {  // two warm-up steps
        for (auto& p : dem)
            for (int a = 0; a < 3; ++a) {
                p.x[a] += p.v[a] * dt;
                if (p.x[a] < 0 || p.x[a] > 1) {
                    p.v[a] = -p.v[a];
                    p.x[a] = std::clamp(p.x[a], 0.0, 1.0);
                }
            }

        MPI_Barrier(MPI_COMM_WORLD);
        double t0 = MPI_Wtime();
        ex.forward(dem, owned);
        const double forward = slowest(t0);

        forces.resize(3 * owned.size());
        for (std::size_t i = 0; i < owned.size(); ++i)
            for (int a = 0; a < 3; ++a) forces[3 * i + a] = owned.state(i).v[a];
        MPI_Barrier(MPI_COMM_WORLD);
        t0 = MPI_Wtime();
        ex.backward(forces, 3, out);
        const double backward = slowest(t0);

        MPI_Barrier(MPI_COMM_WORLD);
        t0 = MPI_Wtime();
        long found = 0;
        for (std::size_t i = 0; i < owned.size(); ++i) found += mesh.findCell(owned.state(i).x) >= 0;
        const double find = slowest(t0);
        if (found != static_cast<long>(owned.size())) std::fprintf(stderr, "findCell mismatch\n");

        long sent = ex.stats().bytesSent, sentAll = 0;
        MPI_Allreduce(&sent, &sentAll, 1, MPI_LONG, MPI_SUM, MPI_COMM_WORLD);
        if (step < 0) continue;
        const double perParticle = 1e6 / nGlobal;
        tFind.push_back(find * perParticle);
        tForward.push_back(forward * perParticle);
        tBackward.push_back(backward * perParticle);
        tTotal.push_back((forward + backward) * perParticle);
        bytes.push_back(static_cast<double>(sentAll) / nGlobal);
    }
    int partners = ex.stats().partners, maxPartners = 0;
    MPI_Allreduce(&partners, &maxPartners, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    if (rank == 0)
        std::printf("%8ld  %5d  %-9s  %8.3f  %8.3f  %8.3f  %8.3f  %8.3f  %8.1f  %8d\n", nGlobal, size,
                    demAxis == 0 ? "x vs z" : "z vs z", median(tFind), median(tForward), median(tBackward),
                    median(tTotal), *std::min_element(tTotal.begin(), tTotal.end()), median(bytes),
                    maxPartners);
}

}  // namespace

int main(int argc, char** argv) {
    MPI_Init(&argc, &argv);
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    // Every rank parses the same argv, so a bad argument stops all ranks alike.
    const auto usage = [&](const char* why) {
        if (rank == 0)
            std::fprintf(stderr, "bench_exchange: %s\nusage: bench_exchange [steps>=1, default 20] "
                                 "[N>=1 ... particles, default 10000 100000]\n", why);
        MPI_Finalize();
        return 2;
    };
    const int steps = argc > 1 ? std::atoi(argv[1]) : 20;
    if (steps < 1) return usage("the number of steps must be a positive integer");
    std::vector<long> sizes;
    for (int i = 2; i < argc; ++i) {
        sizes.push_back(std::atol(argv[i]));
        if (sizes.back() < 1) return usage("particle counts must be positive integers");
    }
    if (sizes.empty()) sizes = {10000, 100000};
    if (rank == 0) {
        std::printf("# mesh 40^3 cells, CFD slabs along z; DEM slabs along x (differ) or z (match)\n");
        std::printf("# median of %d steps, slowest rank; times in us of wall time per particle per step\n",
                    steps);
        std::printf("# %6s  %5s  %-9s  %8s  %8s  %8s  %8s  %8s  %8s  %8s\n", "N", "ranks", "DEM/CFD",
                    "findCell", "forward", "backward", "total", "min tot", "bytes/p", "partners");
    }
    for (long n : sizes)
        for (int demAxis : {0, 2}) run(n, demAxis, steps, rank, size);
    MPI_Finalize();
    return 0;
}
