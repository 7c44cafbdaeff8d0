// shearRate(grad U) = sqrt(2 D:D) against closed forms: simple shear gives
// |G|, a rigid rotation gives 0, uniaxial extension gives sqrt(3)|e|
// (D = diag(e, -e/2, -e/2): 2 D:D = 2 (e^2 + e^2/4 + e^2/4) = 3 e^2).
// deviatoricShearRate: a pure dilation gives 0, shear plus dilation the
// shear's |G|, and a uniaxial compression D = diag(-e, 0, 0) (deviator
// diag(-2e/3, e/3, e/3)) sqrt(2 (4/9 + 1/9 + 1/9)) e = (2/sqrt(3)) e.
#include <catch2/catch.hpp>

#include <cmath>

#include "rheology/ShearRate.hpp"

TEST_CASE("shearRate: sqrt(2 D:D) of a velocity gradient", "[rheology][shearRate]") {
    SECTION("simple shear u = (G y, 0, 0) gives G, in either index convention") {
        Eigen::Matrix3d g = Eigen::Matrix3d::Zero();
        g(0, 1) = 3.5;  // du/dy
        CHECK(granair::shearRate(g) == Approx(3.5).epsilon(1e-15));
        CHECK(granair::shearRate(g.transpose()) == Approx(3.5).epsilon(1e-15));
        CHECK(granair::shearRate(-g) == Approx(3.5).epsilon(1e-15));
    }

    SECTION("a rigid rotation has no shear rate") {
        Eigen::Matrix3d w;
        w << 0, -2, 1, 2, 0, -4, -1, 4, 0;  // antisymmetric
        CHECK(granair::shearRate(w) == 0.0);
    }

    SECTION("uniaxial extension D = diag(e, -e/2, -e/2) gives sqrt(3) e") {
        const double e = 0.8;
        const Eigen::Matrix3d g = Eigen::Vector3d(e, -e / 2, -e / 2).asDiagonal();
        CHECK(granair::shearRate(g) == Approx(std::sqrt(3.0) * e).epsilon(1e-15));
    }

    SECTION("shear plus rotation: only the symmetric part counts") {
        Eigen::Matrix3d g = Eigen::Matrix3d::Zero();
        g(2, 0) = 1.2;  // du_x/dz = 1.2 (a shear of 1.2 = rotation + strain)
        Eigen::Matrix3d w;
        w << 0, 0.7, 0, -0.7, 0, 0, 0, 0, 0;
        CHECK(granair::shearRate(g + w) == Approx(1.2).epsilon(1e-15));
    }
}

TEST_CASE("deviatoricShearRate: sqrt(2 D':D') without the dilation", "[rheology][shearRate]") {
    SECTION("a pure dilation has no deviatoric shear rate") {
        const Eigen::Matrix3d g = 2.5 * Eigen::Matrix3d::Identity();
        CHECK(granair::deviatoricShearRate(g) == Approx(0.0).margin(1e-15));
    }

    SECTION("shear plus dilation gives the shear's G") {
        Eigen::Matrix3d g = 0.4 * Eigen::Matrix3d::Identity();
        g(0, 1) = 3.5;
        CHECK(granair::deviatoricShearRate(g) == Approx(3.5).epsilon(1e-15));
        CHECK(granair::shearRate(g) > 3.5);
    }

    SECTION("uniaxial compression diag(-e, 0, 0) gives 2 e / sqrt(3)") {
        const double e = 0.9;
        const Eigen::Matrix3d g = Eigen::Vector3d(-e, 0, 0).asDiagonal();
        CHECK(granair::deviatoricShearRate(g) == Approx(2.0 * e / std::sqrt(3.0)).epsilon(1e-15));
    }

    SECTION("incompressible: the same as shearRate") {
        const double e = 0.8;
        const Eigen::Matrix3d g = Eigen::Vector3d(e, -e / 2, -e / 2).asDiagonal();
        CHECK(granair::deviatoricShearRate(g) == Approx(granair::shearRate(g)).epsilon(1e-15));
    }
}
