// bench_cg: seconds per snapshot of the CG fields (coupling/cg) for a dense
// bed with its contacts on a 3-D grid. Not a test: bench/cg/run.sh sweeps
// particles, grid points and threads and writes bench/results/cg.{md,csv}.
//
//   bench_cg [--particles N] [--points G | --spacing H_OVER_D] [--width W_OVER_D] [--kernel gauss|lucy|heaviside]
//            [--coordinates XYZ|XZ|Z|RZ] [--threads T] [--repeat R] [--read]
//
// The bed: spheres of d = 1 mm on a jittered cubic lattice of spacing 0.95 d
// in a cube (volume fraction 0.61), every pair of lattice neighbours closer
// than d is a contact (about 2.9 per particle, coordination ~5.8), a floor
// contact under each bottom particle. Prints one CSV row (header with --header).
// --read also writes the bed as LIGGGHTS dumps and times reading them back.
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <random>
#include <string>

#include "cg/CgGrid.hpp"
#include "cg/CgKernel.hpp"
#include "cg/CgSnapshotReader.hpp"
#include "cg/CoarseGrainer.hpp"
#include "cg/GaussKernel.hpp"
#include "cg/HeavisideKernel.hpp"
#include "cg/LucyKernel.hpp"

using namespace granair;

namespace {

CgSnapshot bed(long n, double d, double& L) {
    const double a = 0.95 * d;
    const int m = int(std::lround(std::cbrt(double(n))));
    L = m * a;
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> U(-0.04 * d, 0.04 * d);
    CgSnapshot s;
    s.domain.box = Box{Vec3::Zero(), Vec3::Constant(L)};
    s.particles.resize(std::size_t(m) * m * m);
    auto id = [m](int i, int j, int k) { return (std::size_t(k) * m + j) * m + i; };
    for (int k = 0; k < m; ++k)
        for (int j = 0; j < m; ++j)
            for (int i = 0; i < m; ++i) {
                CgParticle& p = s.particles[id(i, j, k)];
                p.id = long(id(i, j, k)) + 1;
                p.x = Vec3((i + 0.5) * a + U(rng), (j + 0.5) * a + U(rng), (k + 0.5) * a + U(rng));
                p.v = Vec3(U(rng), U(rng), U(rng)) * 10.0;
                p.radius = 0.5 * d;
                p.mass = 2500 * M_PI / 6 * d * d * d;
            }
    for (int k = 0; k < m; ++k)
        for (int j = 0; j < m; ++j)
            for (int i = 0; i < m; ++i) {
                const CgParticle& p = s.particles[id(i, j, k)];
                const int nb[3][3] = {{i + 1, j, k}, {i, j + 1, k}, {i, j, k + 1}};
                for (const auto& q : nb) {
                    if (q[0] >= m || q[1] >= m || q[2] >= m) continue;
                    const CgParticle& o = s.particles[id(q[0], q[1], q[2])];
                    const Vec3 r = p.x - o.x;
                    if (r.norm() >= d) continue;
                    s.pairs.push_back(CgPairContact{p.x, o.x, 1e3 * (d - r.norm()) * r / r.norm()});
                }
                if (k == 0) s.walls.push_back(CgWallContact{p.x, Vec3(p.x[0], p.x[1], 0.0), Vec3(0, 0, 0.5)});
            }
    return s;
}

void writeDumps(const CgSnapshot& s, const std::string& dir) {
    std::filesystem::create_directories(dir);
    const Box& b = s.domain.box;
    auto head = [&](std::FILE* f, const char* what, std::size_t n) {
        std::fprintf(f, "ITEM: TIMESTEP\n0\nITEM: NUMBER OF %s\n%zu\nITEM: BOX BOUNDS ff ff ff\n", what, n);
        for (int a = 0; a < 3; ++a) std::fprintf(f, "%g %g\n", b.lo[a], b.hi[a]);
    };
    std::FILE* f = std::fopen((dir + "/particles_0.dump").c_str(), "w");
    head(f, "ATOMS", s.particles.size());
    std::fprintf(f, "ITEM: ATOMS id x y z vx vy vz radius mass\n");
    for (const auto& p : s.particles)
        std::fprintf(f, "%ld %g %g %g %g %g %g %g %g\n", p.id, p.x[0], p.x[1], p.x[2], p.v[0], p.v[1], p.v[2], p.radius, p.mass);
    std::fclose(f);
    f = std::fopen((dir + "/pairs_0.dump").c_str(), "w");
    head(f, "ENTRIES", s.pairs.size());
    std::fprintf(f, "ITEM: ENTRIES");
    for (int k = 1; k <= 12; ++k) std::fprintf(f, " c_p[%d]", k);
    std::fprintf(f, "\n");
    for (std::size_t i = 0; i < s.pairs.size(); ++i) {
        const auto& c = s.pairs[i];
        std::fprintf(f, "%g %g %g %g %g %g %zu %zu 0 %g %g %g\n", c.xi[0], c.xi[1], c.xi[2], c.xj[0], c.xj[1], c.xj[2],
                     2 * i + 1, 2 * i + 2, c.force[0], c.force[1], c.force[2]);
    }
    std::fclose(f);
}

}  // namespace

int main(int argc, char** argv) {
    long n = 100000, points = 100000;
    double wOverD = 0.5, spacing = 0.0;
    int threads = 1, repeat = 3;
    bool read = false, header = false;
    std::string kernelName = "gauss", coords = "XYZ";
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&]() { return std::string(i + 1 < argc ? argv[++i] : ""); };
        if (a == "--particles") n = std::stol(next());
        else if (a == "--points") points = std::stol(next());
        else if (a == "--width") wOverD = std::stod(next());
        else if (a == "--spacing") spacing = std::stod(next());
        else if (a == "--kernel") kernelName = next();
        else if (a == "--coordinates") coords = next();
        else if (a == "--threads") threads = std::stoi(next());
        else if (a == "--repeat") repeat = std::stoi(next());
        else if (a == "--read") read = true;
        else if (a == "--header") header = true;
        else {
            std::fprintf(stderr, "bench_cg: unknown argument %s\n", a.c_str());
            return 2;
        }
    }
    if (header) {
        std::printf("coordinates,kernel,w_over_d,particles,pairs,grid_points,threads,seconds,cpu_seconds,ns_per_object_point,read_seconds\n");
        return 0;
    }
    const double d = 1e-3;
    double L = 0;
    const CgSnapshot s = bed(n, d, L);
    const Box box{Vec3::Zero(), Vec3::Constant(L)};
    const double w = wOverD * d;
    std::shared_ptr<const CgKernelShape> shape;
    if (kernelName == "gauss") shape = std::make_shared<GaussKernel>(w);
    else if (kernelName == "lucy") shape = std::make_shared<LucyKernel>(w);
    else shape = std::make_shared<HeavisideKernel>(w);
    const CgCoordinates cc = parseCgCoordinates(coords, "--coordinates");
    CgGrid grid = [&] {
        if (cc == CgCoordinates::RZ) {
            const int nn = spacing > 0 ? int(std::lround(L / (spacing * d)))
                                       : int(std::lround(std::sqrt(double(points) * 2.0)));
            return CgGrid::cylindrical(L / 2, L / 2, 0.0, L / 2, 0.0, L, nn / 2, nn);
        }
        const auto res = cgResolvedAxes(cc);
        int dims = 0;
        for (bool r : res) dims += r;
        const int per = spacing > 0 ? int(std::lround(L / (spacing * d)))
                        : dims      ? int(std::lround(std::pow(double(points), 1.0 / dims)))
                                    : 1;
        return CgGrid(cc, box, {{res[0] ? per : 1, res[1] ? per : 1, res[2] ? per : 1}});
    }();
    const CoarseGrainer cg(grid, CgKernel(shape, grid.kernelDims()));
    // Wall time (fastest repeat) and the process's CPU time (all threads) of
    // that repeat: on a shared machine the CPU time is the steadier figure.
    double best = 1e300, bestCpu = 0;
    CgCounts counts;
    for (int r = 0; r < repeat; ++r) {
        const std::clock_t c0 = std::clock();
        const auto t0 = std::chrono::steady_clock::now();
        const CgRawFields f = cg.compute(s, threads, &counts);
        const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
        if (t < best) best = t, bestCpu = cpu;
        if (f.data.empty()) return 1;
    }
    // object-point evaluations: the points within the cutoff ball of each particle, scaled
    const double c = cg.kernel().cutoff();
    double cellVol = 1.0;
    int dims = 0;
    for (int a = 0; a < 3; ++a)
        if (grid.resolved(a)) cellVol *= grid.spacing(a), ++dims;
    const double ball = dims == 3 ? 4.0 / 3.0 * M_PI * c * c * c : dims == 2 ? M_PI * c * c : 2 * c;
    const double evals = double(s.particles.size() + s.pairs.size()) * std::max(1.0, ball / cellVol);
    double readSeconds = 0;
    if (read) {
        const std::string dir = (std::filesystem::temp_directory_path() / "granair_bench_cg").string();
        writeDumps(s, dir);
        CgReadOptions o;
        o.particles = dir + "/particles_0.dump";
        o.pairs = dir + "/pairs_0.dump";
        const auto t0 = std::chrono::steady_clock::now();
        const CgSnapshotReader reader(o);
        const CgSnapshot back = reader.read(0);
        readSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::filesystem::remove_all(dir);
        if (back.pairs.size() != s.pairs.size()) return 1;
    }
    std::printf("%s,%s,%g,%zu,%zu,%zu,%d,%.4g,%.4g,%.4g,%.4g\n", coords.c_str(), kernelName.c_str(), wOverD,
                s.particles.size(), s.pairs.size(), grid.size(), threads, best, bestCpu, bestCpu / evals * 1e9,
                readSeconds);
    return 0;
}
