// CG kernels (coupling/cg/*Kernel.hpp): standard deviations against closed
// forms, the exact line integrals against quadrature of the kernel, the
// registry and bad parameters.
#include <catch2/catch.hpp>

#include <random>

#include "CgTestSupport.hpp"
#include "core/Error.hpp"

using namespace granair;
using namespace granair::cgtest;

TEST_CASE("CG kernels: standard deviation per axis matches the closed forms", "[cg][kernel]") {
    const double w = 0.7e-3, k = 3.0, c = 2.1e-3;
    const double e = std::exp(-0.5 * k * k);
    const double J2 = std::sqrt(M_PI / 2) * std::erf(k / std::sqrt(2.0)) - k * e;  // int_0^k x^2 exp(-x^2/2)
    // Truncated Gaussian: sigma^2/w^2 = 1 - k^3 e / (3 J2) (3-D), 1 - k^2 e / (2 (1 - e)) (2-D),
    // J2 / (sqrt(pi/2) erf(k/sqrt 2)) (1-D).
    const double gauss[4] = {0, J2 / (std::sqrt(M_PI / 2) * std::erf(k / std::sqrt(2.0))),
                             1 - k * k * e / (2 * (1 - e)), 1 - k * k * k * e / (3 * J2)};
    for (int d = 1; d <= 3; ++d) {
        INFO(d << "-D");
        CHECK(CgKernel(shape("gauss", w, k), d).standardDeviation() == Approx(w * std::sqrt(gauss[d])).epsilon(1e-13));
        // Ball: c / sqrt(D + 2).
        CHECK(CgKernel(shape("heaviside", c), d).standardDeviation() == Approx(c / std::sqrt(d + 2.0)).epsilon(1e-13));
    }
    // Lucy in 3-D: sigma^2 = c^2 I_4 / (3 I_2), I_n = int_0^1 q^n (1 + 3q)(1 - q)^3 dq = 1/105 and 4/105.
    CHECK(CgKernel(shape("lucy", c), 3).standardDeviation() == Approx(c / std::sqrt(12.0)).epsilon(1e-13));
    // withStandardDeviation scales the width to hit the target.
    for (const char* n : {"gauss", "heaviside", "lucy"})
        for (int d = 1; d <= 3; ++d)
            CHECK(CgKernel::withStandardDeviation(*shape(n, 1.0), d, 0.4e-3).standardDeviation() ==
                  Approx(0.4e-3).epsilon(1e-13));
    // The normalisation constants of Lucy and the ball.
    CHECK(CgKernel(shape("lucy", c), 3).normalisation() == Approx(105.0 / (16 * M_PI * c * c * c)).epsilon(1e-14));
    CHECK(CgKernel(shape("lucy", c), 2).normalisation() == Approx(5.0 / (M_PI * c * c)).epsilon(1e-14));
    CHECK(CgKernel(shape("lucy", c), 1).normalisation() == Approx(5.0 / (4 * c)).epsilon(1e-14));
    CHECK(CgKernel(shape("heaviside", c), 3).normalisation() == Approx(3.0 / (4 * M_PI * c * c * c)).epsilon(1e-14));
}

TEST_CASE("CG kernels: exact line integrals equal quadrature of the kernel", "[cg][kernel]") {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> U(-1.2, 1.2);
    for (const auto& kc : kernelCases()) {
        const CgKernel k(shape(kc.name, kc.width, kc.k), 3);
        const double c = k.cutoff();
        for (int trial = 0; trial < 200; ++trial) {
            const double p2 = std::pow(std::abs(U(rng)) * c, 2);
            double a0 = U(rng) * c, a1 = U(rng) * c;
            if (trial % 5 == 0) a1 = a0 + 1e-7 * c;  // the short-interval branch
            if (a1 < a0) std::swap(a0, a1);
            // Reference: split at the support edges +-h and at 0, cosine-mapped Gauss-Legendre.
            const double h = chord(c, p2);
            std::vector<double> b{a0, a1};
            for (double x : {-h, 0.0, h})
                if (x > a0 && x < a1) b.push_back(x);
            const auto nodes = nestedRule(1, [&](int, const double*) { return b; }, 40);
            double ref = 0;
            for (const auto& nd : nodes) ref += nd.w * k.value(p2 + nd.u[0] * nd.u[0]);
            INFO(kc.name << " p2/c2 " << p2 / (c * c) << " a0/c " << a0 / c << " a1/c " << a1 / c);
            // Relative 1e-12, or 1e-14 of the kernel's scale psi(0) c where
            // the value itself is tiny (Lucy at the edge of its support).
            CHECK(std::abs(k.lineIntegral(p2, a0, a1) - ref) <= 1e-12 * ref + 1e-14 * k.value(0) * c);
        }
    }
}

TEST_CASE("CG kernels: the registry names every kernel; bad parameters are refused", "[cg][kernel]") {
    const auto names = cgKernelShapes().names();
    CHECK(names == std::vector<std::string>{"gauss", "heaviside", "lucy"});
    Dictionary d = Dictionary::fromString("type box; width 1e-3;", "cg.dict");
    CHECK_THROWS_WITH(cgKernelShapes().create(d), Catch::Contains("unknown CG kernel 'box'") &&
                                                     Catch::Contains("gauss") && Catch::Contains("lucy"));
    Dictionary g = Dictionary::fromString("type gauss; width -1e-3;", "cg.dict");
    CHECK_THROWS_AS(cgKernelShapes().create(g), InputError);
    Dictionary g2 = Dictionary::fromString("type gauss; width 1e-3; cutoff 20;", "cg.dict");
    CHECK_THROWS_WITH(cgKernelShapes().create(g2), Catch::Contains("cutoff") && Catch::Contains("cg.dict"));
    CHECK_THROWS_AS(LucyKernel(0.0), InputError);
    CHECK_THROWS_AS(HeavisideKernel(std::nan("")), InputError);
}
