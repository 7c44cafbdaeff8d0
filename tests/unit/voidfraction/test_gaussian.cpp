// The gaussian model: kernel centroid, truncation on a decomposed mesh, the
// wall, and parameter errors.
#include <catch2/catch.hpp>
#include <cmath>

#include "VoidFractionTestSupport.hpp"
#include "mapping/BoxMesh.hpp"
#include "voidfraction/GaussianVoidFraction.hpp"

using granair::BoxMesh;
using granair::CellWeight;
using granair::GaussianVoidFraction;
using granair::ParticleState;
using granair::Vec3;

namespace {

ParticleState particleAt(const Vec3& x, double r) {
    ParticleState p;
    p.id = 1;
    p.x = x;
    p.radius = r;
    return p;
}

Vec3 centroid(const granair::CellLocator& mesh, const std::vector<CellWeight>& st) {
    Vec3 c = Vec3::Zero();
    for (const auto& cw : st) c += cw.weight * mesh.cellCentre(cw.cell);
    return c;
}

// First moment carried by the tail |x| > c w of a 3-D Gaussian of standard
// deviation w, in units of w: integral_c^inf r * r^2 exp(-r^2/2) dr * sqrt(2/pi)
// = sqrt(2/pi) (c^2 + 2) exp(-c^2/2). Cutting the tail off can shift the
// centroid by at most this much (divided by the kept mass, > 0.97 here).
double tailFirstMoment(double c) { return std::sqrt(2 / M_PI) * (c * c + 2) * std::exp(-c * c / 2); }

}  // namespace

// Sections of one test case: each ctest test pays ~0.5 s of MPI start-up.
TEST_CASE("gaussian void-fraction model", "[voidfraction][gaussian]") {
    SECTION("the distributed volume's centroid is the particle centre away from boundaries") {
        // Uniform 30^3 mesh of the unit cube, h = 1/30, kernel width w = 2h (the
        // lattice error of the discrete first moment is then ~exp(-2 pi^2 w^2/h^2),
        // negligible); particles at random points at least 0.35 m (> 5w) from walls.
        const BoxMesh mesh(Vec3(0, 0, 0), Vec3(1, 1, 1), {30, 30, 30});
        const double h = 1.0 / 30, w = 2 * h;
        for (double c : {3.0, 5.0}) {
            const GaussianVoidFraction m(w, c);
            // Tolerance: the truncated tail's first moment (0.097 w for c = 3,
            // 8e-5 w for c = 5) divided by the kept mass (0.97 for c = 3). A bound,
            // not an estimate: measured worst errors are 1.8e-3 w and 2.4e-6 w.
            const double tol = tailFirstMoment(c) / 0.97 * w;
            vftest::Random rnd(42);
            std::vector<CellWeight> st;
            double worst = 0;
            for (int i = 0; i < 20; ++i) {
                const Vec3 x(rnd.uniform(0.35, 0.65), rnd.uniform(0.35, 0.65), rnd.uniform(0.35, 0.65));
                m.stencil(mesh, particleAt(x, 0.01), mesh.findCell(x), st);
                vftest::checkStencil(mesh, st);
                worst = std::max(worst, (centroid(mesh, st) - x).norm());
            }
            INFO("cutoff " << c << ": worst centroid error " << worst / w << " w, tolerance " << tol / w
                           << " w");
            CHECK(worst <= tol);
        }
        // At a cell centre the stencil is symmetric, so the centroid is exact to
        // round-off. (A cutoff of 6.1 h passes through no cell centre: with one at
        // exactly the cutoff, round-off alone would decide which side keeps it.)
        const GaussianVoidFraction m(w, 3.05);
        const int cell = mesh.findCell(Vec3(0.5, 0.5, 0.5));
        std::vector<CellWeight> st;
        m.stencil(mesh, particleAt(mesh.cellCentre(cell), 0.01), cell, st);
        CHECK((centroid(mesh, st) - mesh.cellCentre(cell)).norm() < 1e-14);
    }

    SECTION("the kernel reaches every cell centre within the cutoff and no other") {
        // Brute force over all cells of a 20^3 mesh: the breadth-first search must
        // find exactly the cells with |x_c - x_p| <= cutoff * width (plus the centre).
        const BoxMesh mesh(Vec3(0, 0, 0), Vec3(1, 2, 1), {20, 20, 20});  // cells 0.05 x 0.1 x 0.05
        const GaussianVoidFraction m(0.04, 3);
        vftest::Random rnd(9);
        std::vector<CellWeight> st;
        for (int i = 0; i < 20; ++i) {
            const Vec3 x(rnd.uniform(0, 1), rnd.uniform(0, 2), rnd.uniform(0, 1));
            const int centre = mesh.findCell(x);
            m.stencil(mesh, particleAt(x, 0.01), centre, st);
            int expected = 0;
            for (int c = 0; c < mesh.nCells(); ++c)
                if (c == centre || (mesh.cellCentre(c) - x).norm() <= 0.12) {
                    ++expected;
                    CHECK(vftest::weightOf(st, c) > 0);
                }
            CHECK(static_cast<int>(st.size()) == expected);
        }
    }

    SECTION("gaussian on a decomposed mesh: kernel cut at the rank boundary and renormalised") {
        // On a slab, each owned cell gets its whole-mesh weight divided by the
        // whole-mesh weight of the owned cells (round-off 1e-12): volume stays on
        // the rank and is conserved, but the split differs from the serial one.
        const Vec3 lo(0, 0, 0), hi(1, 1, 1);
        const BoxMesh::Index3 n{20, 20, 20};
        const BoxMesh whole(lo, hi, n);
        const GaussianVoidFraction m(0.05, 3);
        vftest::Random rnd(21);
        std::vector<CellWeight> full, part;
        for (int k = 0; k < 2; ++k) {
            const BoxMesh slab = BoxMesh::slab(lo, hi, n, 2, k, 0);
            for (int i = 0; i < 30; ++i) {
                // Within 0.1 m (2 widths) of the slab face x = 0.5.
                const Vec3 x(k == 0 ? rnd.uniform(0.4, 0.5) : rnd.uniform(0.5, 0.6), rnd.uniform(0.2, 0.8),
                             rnd.uniform(0.2, 0.8));
                m.stencil(whole, particleAt(x, 0.01), whole.findCell(x), full);
                m.stencil(slab, particleAt(x, 0.01), slab.findCell(x), part);
                vftest::checkStencil(slab, part);
                double kept = 0;
                for (const auto& cw : full)
                    if (slab.localCell(whole.globalIjk(cw.cell)) >= 0) kept += cw.weight;
                REQUIRE(kept < 1);  // the kernel does cross the slab face
                std::size_t owned = 0;
                for (const auto& cw : full) {
                    const int local = slab.localCell(whole.globalIjk(cw.cell));
                    if (local < 0) continue;
                    ++owned;
                    CHECK(vftest::weightOf(part, local) == Approx(cw.weight / kept).margin(1e-12));
                }
                CHECK(part.size() == owned);
            }
        }
    }

    SECTION("near a wall the truncated kernel keeps the volume and moves it inwards") {
        const BoxMesh mesh(Vec3(0, 0, 0), Vec3(1, 1, 1), {25, 25, 25});
        const GaussianVoidFraction m(0.04);
        std::vector<CellWeight> st;
        const Vec3 x(0.01, 0.5, 0.5);  // 0.25 widths from the wall x = 0
        m.stencil(mesh, particleAt(x, 0.005), mesh.findCell(x), st);
        vftest::checkStencil(mesh, st);
        const Vec3 c = centroid(mesh, st);
        CHECK(c.x() > x.x());
        // Only the wall-normal direction is cut (up to the lattice offset: the
        // particle sits at a cell centre in y and z), so no sideways drift.
        CHECK(std::abs(c.y() - 0.5) < 1e-12);
        CHECK(std::abs(c.z() - 0.5) < 1e-12);
    }

    SECTION("with cells much larger than the kernel the stencil is the centre cell") {
        const BoxMesh mesh(Vec3(0, 0, 0), Vec3(1, 1, 1), {2, 2, 2});
        const GaussianVoidFraction m(1e-3);
        std::vector<CellWeight> st;
        for (const Vec3& x : {Vec3(0.1, 0.1, 0.1), Vec3(0.5, 0.5, 0.5), Vec3(0.999, 0.2, 0.7)}) {
            const int c = mesh.findCell(x);
            m.stencil(mesh, particleAt(x, 1e-3), c, st);
            REQUIRE(st.size() == 1);
            CHECK(st[0].cell == c);
            CHECK(st[0].weight == 1.0);
        }
    }

    SECTION("gaussian parameters: width > 0 required, cutoff in [1, 10], errors name the file and key") {
        const auto& reg = granair::voidFractionModels();
        auto make = [&](const std::string& text) {
            return reg.create(granair::Dictionary::fromString(text, "constant/couplingProperties"));
        };
        const auto model = make("type gaussian; width 2e-3;");
        const auto& g = dynamic_cast<const GaussianVoidFraction&>(*model);
        CHECK(g.width() == 2e-3);
        CHECK(g.cutoff() == GaussianVoidFraction::defaultCutoff);
        CHECK(dynamic_cast<const GaussianVoidFraction&>(*make("type gaussian; width 1; cutoff 4.5;"))
                  .cutoff() == 4.5);
        const std::vector<std::pair<std::string, std::string>> bad{
            {"type gaussian;", "width"},
            {"type gaussian; width 0;", "width"},
            {"type gaussian; width -1e-3;", "width"},
            {"type gaussian; width nan;", "width"},
            {"type gaussian; width inf;", "width"},
            {"type gaussian; width 1e-3 2e-3;", "width"},
            {"type gaussian; width 1e-3; cutoff 0.5;", "cutoff"},
            {"type gaussian; width 1e-3; cutoff 11;", "cutoff"},
            {"type gaussian; width 1e-3; cutoff nan;", "cutoff"},
        };
        for (const auto& [text, key] : bad) {
            INFO(text);
            CHECK_THROWS_AS(make(text), granair::InputError);
            CHECK_THROWS_WITH(make(text), Catch::Matchers::Contains("constant/couplingProperties") &&
                                              Catch::Matchers::Contains(key));
        }
    }
}
