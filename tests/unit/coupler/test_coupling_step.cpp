// CouplingStep: the particle -> cell -> particle path of one coupling step on
// a structured mesh. Asserts: void fraction from particle volumes; momentum
// given to the air equals the drag on the particles; the Ergun pressure drop
// carried by drag + pressure-gradient force in a uniform bed; coarse-grained
// parcels; the floor and its count.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "coupler/CouplingStep.hpp"
#include "voidfraction/GaussianVoidFraction.hpp"
#include "mapping/BoxMesh.hpp"

using namespace granair;

namespace {

CouplingSettings settings(const std::string& drag, const std::string& vf, double s = 1.0) {
    auto d = Dictionary::fromString("couplingInterval 1; coarseGrainingFactor " + std::to_string(s) +
                                        "; drag { type " + drag + "; } voidFraction { type " + vf +
                                        "; width 0.002; }",
                                    "test");
    return CouplingSettings::read(d);
}

OwnedParticles lattice(const BoxMesh& mesh, int perAxis, const Vec3& lo, const Vec3& hi, double radius,
                       const Vec3& v) {
    OwnedParticles out;
    long id = 1;
    for (int i = 0; i < perAxis; ++i)
        for (int j = 0; j < perAxis; ++j)
            for (int k = 0; k < perAxis; ++k) {
                ParticleState p;
                p.id = id++;
                p.x = lo + ((Vec3(i, j, k).array() + 0.5) / perAxis * (hi - lo).array()).matrix();
                p.v = v;
                p.radius = radius;
                out.add(p, mesh.findCell(p.x));
            }
    return out;
}

// n particles of one radius at random places in the 0.02 x 0.02 x 0.04 m
// box, random velocities up to 0.1 m/s per component.
OwnedParticles randomParticles(const BoxMesh& mesh, int n, unsigned seed, double radius) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> ux(0.0, 0.02), uz(0.0, 0.04), uv(-0.1, 0.1);
    OwnedParticles parts;
    for (int i = 0; i < n; ++i) {
        const ParticleState p{i + 1, Vec3(ux(rng), ux(rng), uz(rng)), Vec3(uv(rng), uv(rng), uv(rng)), radius};
        parts.add(p, mesh.findCell(p.x));
    }
    return parts;
}

}  // namespace

TEST_CASE("void fraction is one minus the particle volume per cell", "[coupler]") {
    // one cell, 4^3 particles of radius r: eps = 1 - 64 * 4/3 pi r^3 / V
    BoxMesh mesh(Vec3(0, 0, 0), Vec3(0.01, 0.01, 0.01), {1, 1, 1});
    auto cs = settings("ErgunGidaspow", "centre");
    CouplingStep step(cs, mesh, FluidProperties{1.2, 1.8e-5});
    const double r = 0.001;
    auto parts = lattice(mesh, 4, Vec3(0, 0, 0), Vec3(0.01, 0.01, 0.01), r, Vec3::Zero());
    std::vector<double> U(3, 0.0), eps(1), K(1), Us(3);
    step.particlesToCells(parts, U.data(), eps.data(), K.data(), Us.data());
    CHECK(eps[0] == Approx(1 - 64 * 4.0 / 3.0 * M_PI * r * r * r / 1e-6).epsilon(1e-14));
    CHECK(step.stats().floorHits == 0);
}

TEST_CASE("momentum given to the air equals the drag on the particles", "[coupler]") {
    // Random particles and a non-uniform air velocity: with K and Us per cell
    // the air loses sum_c K_c V_c (U_c - Us_c); the particles gain sum_p drag_p.
    BoxMesh mesh(Vec3(0, 0, 0), Vec3(0.02, 0.02, 0.04), {4, 4, 8});
    for (const std::string vf : {"centre", "divided", "gaussian"}) {
        auto cs = settings("DiFelice", vf);
        CouplingStep step(cs, mesh, FluidProperties{1.2, 1.8e-5});
        const OwnedParticles parts = randomParticles(mesh, 500, 42, 5e-4);
        const int n = mesh.nCells();
        std::vector<double> U(3 * n), eps(n), K(n), Us(3 * n), gradP(3 * n, 0.0), f;
        for (int c = 0; c < n; ++c) {
            const Vec3 x = mesh.cellCentre(c);
            U[3 * c] = 0.3 * x.z() / 0.04;
            U[3 * c + 1] = -0.1;
            U[3 * c + 2] = 0.5 + x.x() * 10;
        }
        step.particlesToCells(parts, U.data(), eps.data(), K.data(), Us.data());
        std::vector<double> drag;
        step.cellsToParticles(parts, U.data(), gradP.data(), f, &drag);
        Vec3 air = Vec3::Zero(), particles = Vec3::Zero();
        for (int c = 0; c < n; ++c)
            for (int a = 0; a < 3; ++a) air[a] += K[c] * mesh.cellVolume(c) * (U[3 * c + a] - Us[3 * c + a]);
        for (size_t p = 0; p < parts.size(); ++p)
            for (int a = 0; a < 3; ++a) particles[a] += drag[3 * p + a];
        INFO("void fraction model " << vf);
        CHECK((air - particles).norm() <= 1e-12 * particles.norm());
        CHECK(particles.norm() > 0);
    }
}

TEST_CASE("uniform bed: drag + pressure-gradient force per volume equals Ergun", "[coupler]") {
    // Particles at rest filling one cell uniformly, air at interstitial
    // velocity u = U_s/eps. In model A the air's steady momentum balance gives
    // grad p = -K u / eps; the total force on the particles per bed volume is
    // then the Ergun (1952) pressure drop per length.
    const double L = 0.01, r = 0.001, rho = 1.2, mu = 1.8e-5;
    BoxMesh mesh(Vec3(0, 0, 0), Vec3(L, L, L), {1, 1, 1});
    auto cs = settings("ErgunGidaspow", "centre");
    cs.buoyancyForce = false;
    CouplingStep step(cs, mesh, FluidProperties{rho, mu});
    auto parts = lattice(mesh, 4, Vec3(0, 0, 0), Vec3(L, L, L), r, Vec3::Zero());
    const double eps = 1 - 64 * 4.0 / 3.0 * M_PI * r * r * r / (L * L * L);
    const double d = 2 * r;
    for (double Us : {0.01, 0.1, 1.0}) {
        const double u = Us / eps;
        std::vector<double> U{0, 0, u}, epsC(1), K(1), UsC(3), f;
        step.particlesToCells(parts, U.data(), epsC.data(), K.data(), UsC.data());
        const std::vector<double> gradP{0, 0, -K[0] * u / eps};
        step.cellsToParticles(parts, U.data(), gradP.data(), f);
        double fz = 0;
        for (size_t p = 0; p < parts.size(); ++p) fz += f[3 * p + 2];
        const double ergun = 150 * mu * Us * (1 - eps) * (1 - eps) / (eps * eps * eps * d * d) +
                             1.75 * rho * Us * Us * (1 - eps) / (eps * eps * eps * d);
        CHECK(fz / (L * L * L) == Approx(ergun).epsilon(1e-12));
    }
}

TEST_CASE("coarse-grained parcel feels s^3 times the primary drag", "[coupler]") {
    // One parcel of factor 2 (radius 2 r) against eight primary particles of
    // radius r in the same cell volume fraction: same total drag.
    BoxMesh mesh(Vec3(0, 0, 0), Vec3(0.01, 0.01, 0.01), {1, 1, 1});
    const double r = 4e-4;
    auto one = settings("ErgunGidaspow", "centre", 2.0);
    auto prim = settings("ErgunGidaspow", "centre", 1.0);
    CouplingStep parcelStep(one, mesh, FluidProperties{});
    CouplingStep primaryStep(prim, mesh, FluidProperties{});
    OwnedParticles parcel;
    parcel.add({1, Vec3(0.005, 0.005, 0.005), Vec3::Zero(), 2 * r}, 0);
    const OwnedParticles primaries = lattice(mesh, 2, Vec3(0, 0, 0), Vec3(0.01, 0.01, 0.01), r, Vec3::Zero());
    std::vector<double> U{0, 0, 0.2}, e1(1), e2(1), K1(1), K2(1), Us(3), g(3, 0.0), f1, f2;
    parcelStep.particlesToCells(parcel, U.data(), e1.data(), K1.data(), Us.data());
    primaryStep.particlesToCells(primaries, U.data(), e2.data(), K2.data(), Us.data());
    CHECK(e1[0] == Approx(e2[0]).epsilon(1e-14));
    CHECK(K1[0] == Approx(K2[0]).epsilon(1e-12));
}

TEST_CASE("void fraction floor is applied and counted", "[coupler]") {
    // A particle larger than its cell with the centre model: raw eps < 0.
    BoxMesh mesh(Vec3(0, 0, 0), Vec3(0.004, 0.001, 0.001), {4, 1, 1});
    auto cs = settings("ErgunGidaspow", "centre");
    CouplingStep step(cs, mesh, FluidProperties{});
    OwnedParticles p;
    p.add({7, Vec3(0.0005, 0.0005, 0.0005), Vec3::Zero(), 0.0008}, 0);
    std::vector<double> U(12, 0.0), eps(4), K(4), Us(12);
    step.particlesToCells(p, U.data(), eps.data(), K.data(), Us.data());
    CHECK(eps[0] == cs.voidFractionFloor);
    CHECK(step.stats().floorHits == 1);
    CHECK(step.stats().minRawVoidFraction == Approx(1 - 4.0 / 3.0 * M_PI * 0.0008 * 0.0008 * 0.0008 / 1e-9));
    CHECK(eps[1] == 1.0);
}

namespace {
// `centre` with its fast path switched off: the coupling step stores and
// walks its one-cell stencils like any other model's.
struct CentreViaStencils : VoidFractionModel {
    std::string name() const override { return "centre (stencils kept)"; }
    void stencil(const CellLocator&, const ParticleState&, int centreCell,
                 std::vector<CellWeight>& out) const override {
        out.assign(1, {centreCell, 1.0});
    }
};
}  // namespace

TEST_CASE("centre: no stored stencils, the same numbers bit for bit", "[coupler]") {
    // The coupling step keeps no stencils for a model whose stencil is always
    // the centre cell (24 bytes per particle less); eps, K, Us and the forces
    // must be exactly those of the stored one-cell stencils.
    BoxMesh mesh(Vec3(0, 0, 0), Vec3(0.02, 0.02, 0.04), {4, 4, 8});
    auto fast = settings("WenYu", "centre");
    auto slow = fast;
    slow.voidFraction = std::make_shared<CentreViaStencils>();
    REQUIRE(fast.voidFraction->centreCellOnly());
    REQUIRE_FALSE(slow.voidFraction->centreCellOnly());
    CouplingStep a(fast, mesh, FluidProperties{1.2, 1.8e-5}), b(slow, mesh, FluidProperties{1.2, 1.8e-5});
    const OwnedParticles parts = randomParticles(mesh, 300, 7, 4e-4);
    const int n = mesh.nCells();
    std::vector<double> U(3 * n), gradP(3 * n);
    for (int c = 0; c < 3 * n; ++c) {
        U[c] = 0.01 * (c % 7) - 0.02;
        gradP[c] = 30.0 * (c % 5) - 50.0;
    }
    std::vector<double> eps[2], K[2], Us[2], f[2];
    CouplingStep* steps[2] = {&a, &b};
    for (int k = 0; k < 2; ++k) {
        eps[k].resize(n);
        K[k].resize(n);
        Us[k].resize(3 * n);
        steps[k]->particlesToCells(parts, U.data(), eps[k].data(), K[k].data(), Us[k].data());
        steps[k]->cellsToParticles(parts, U.data(), gradP.data(), f[k]);
    }
    CHECK(eps[0] == eps[1]);
    CHECK(K[0] == K[1]);
    CHECK(Us[0] == Us[1]);
    CHECK(f[0] == f[1]);
    CHECK(a.particleBufferBytes() < b.particleBufferBytes());
    // One particle at a time (what the coupled run hands the exchange) gives
    // the same forces.
    const CouplingStep::Forces force = a.forces(parts, U.data(), gradP.data());
    std::vector<double> one(3 * parts.size());
    for (std::size_t p = 0; p < parts.size(); ++p) force(p, one.data() + 3 * p);
    CHECK(one == f[0]);
}

TEST_CASE("gaussian: stencil cells in 16 bits, or plain indices where they span more", "[coupler]") {
    // The coupling step stores a stencil's cells as differences from the
    // centre cell in 16 bits, and falls back to plain indices on a rank where
    // a stencil spans more. On 200 x 200 x 3 cells the z neighbours are 40000
    // cell numbers apart: particles in the middle layer need the fallback,
    // particles in a 4 x 4 x 8 mesh do not. Either way eps and the
    // pressure-gradient force are those of the model's own stencils (the same
    // arithmetic in the same order: bit for bit).
    struct Case {
        BoxMesh mesh;
        bool wide;
    };
    const double h = 0.002;  // cell size = the kernel width of settings()
    Case cases[] = {{BoxMesh(Vec3(0, 0, 0), Vec3(4 * h, 4 * h, 8 * h), {4, 4, 8}), false},
                    {BoxMesh(Vec3(0, 0, 0), Vec3(200 * h, 200 * h, 3 * h), {200, 200, 3}), true}};
    for (const Case& c : cases) {
        const BoxMesh& mesh = c.mesh;
        auto cs = settings("DiFelice", "gaussian");
        const GaussianVoidFraction model(h);
        CouplingStep step(cs, mesh, FluidProperties{1.2, 1.8e-5});
        std::mt19937 rng(3);
        std::uniform_real_distribution<double> u(0.3, 0.7);
        OwnedParticles parts;
        for (int i = 0; i < 40; ++i) {
            const Vec3 x(u(rng) * 4 * h, u(rng) * 4 * h, 1.5 * h);
            const ParticleState p{i + 1, x, Vec3(0, 0, -0.05), 4e-4};
            parts.add(p, mesh.findCell(p.x));
        }
        const int n = mesh.nCells();
        std::vector<double> U(3 * n, 0.0), eps(n), K(n), Us(3 * n), gradP(3 * n), zero(3 * n, 0.0), f, f0;
        for (int k = 0; k < n; ++k) gradP[3 * k + 2] = 10.0 * k;  // a different value in every cell
        step.particlesToCells(parts, U.data(), eps.data(), K.data(), Us.data());
        step.cellsToParticles(parts, U.data(), gradP.data(), f);
        step.cellsToParticles(parts, U.data(), zero.data(), f0);
        INFO(n << " cells");
        CHECK(step.wideStencilCells() == c.wide);
        // The model's own stencils, summed as the coupling step sums them.
        std::vector<double> solid(n, 0.0);
        std::vector<CellWeight> st;
        std::vector<double> gpz(parts.size(), 0.0);
        for (std::size_t p = 0; p < parts.size(); ++p) {
            const ParticleState& ps = parts.state(p);
            const double vp = 4.0 / 3.0 * M_PI * ps.radius * ps.radius * ps.radius;
            model.stencil(mesh, ps, parts.cell(p), st);
            for (const CellWeight& cw : st) {
                solid[cw.cell] += cw.weight * vp;
                gpz[p] += cw.weight * gradP[3 * cw.cell + 2];
            }
            if (c.wide) REQUIRE(st.size() > 9);  // the layers above and below are in it
            // -V_p grad(p): the force with the gradient less the force without it.
            CHECK(f[3 * p + 2] - f0[3 * p + 2] == Approx(-vp * gpz[p]).epsilon(1e-12));
        }
        bool same = true;
        for (int k = 0; k < n; ++k) same = same && eps[k] == 1.0 - solid[k] / mesh.cellVolume(k);
        CHECK(same);
    }
}
