// RZ coordinates (docs/cg-fields.md, "RZ"): the fields are the azimuthal
// averages of the 3-D (XYZ) fields, vectors and tensors in the local
// (r, theta, z) frame.
//  - every kernel integrates to 1 with the volume element 2 pi r dr dz, and
//    mass and axial momentum are conserved to 1e-10, also for particles
//    whose kernel crosses the axis;
//  - particle fields equal the azimuthal average of the XYZ fields to 1e-10
//    of the largest value (the library's 16-point rule over the kernel's
//    exact angular support; measured <= 6e-11, Lucy's |x|^3 term limits it);
//  - contact stress equals it to 1e-5 of the largest value (measured
//    <= 1.8e-6: the composite rule between the ring's crossings of the
//    capsule's edges, 8 points per piece of at most c/2 of arc).
#include <catch2/catch.hpp>

#include "CgTestSupport.hpp"

using namespace granair;
using namespace granair::cgtest;

namespace {

const Vec3 axisXY(0.5e-3, -0.3e-3, 0.0);

std::vector<CgParticle> ringParticles(double c) {
    std::vector<CgParticle> ps(4);
    // one on the axis, one whose kernel crosses the axis, two further out
    ps[0].x = axisXY + Vec3(0, 0, 0.2e-3);
    ps[1].x = axisXY + Vec3(0.35 * c, 0.2 * c, -0.4e-3);
    ps[2].x = axisXY + Vec3(-1.3 * c, 0.9 * c, 0.7e-3);
    ps[3].x = axisXY + Vec3(0.3 * c, -3.1 * c, -0.1e-3);
    const Vec3 v[4] = {Vec3(0.3, -1.2, 0.7), Vec3(-0.8, 0.1, 0.4), Vec3(0.05, 0.6, -1.5), Vec3(1.1, 0.4, 0.2)};
    for (int i = 0; i < 4; ++i) {
        ps[i].v = v[i];
        ps[i].mass = (1.0 + 0.3 * i) * 1e-6;
        ps[i].radius = 0.5e-3;
    }
    return ps;
}

CoarseGrainer rzCg(const KernelCase& kc, int nodes = 16) {
    const CgGrid g = CgGrid::cylindrical(axisXY[0], axisXY[1], 0.0, 0.02, -0.02, 0.02, 4, 4);
    return CoarseGrainer(g, CgKernel(shape(kc.name, kc.width, kc.k), 3), nodes);
}

CoarseGrainer xyzCg(const KernelCase& kc) {
    const CgGrid g(CgCoordinates::XYZ, Box{Vec3::Constant(-0.03), Vec3::Constant(0.03)}, {{4, 4, 4}});
    return CoarseGrainer(g, CgKernel(shape(kc.name, kc.width, kc.k), 3));
}

// The XYZ fields on the ring (r, z) averaged over theta, rotated into the
// local frame: each piece between breaks split in 16, n Gauss nodes in the
// cosine map on each (CgQuadrature.hpp).
std::vector<double> ringAverage(const CoarseGrainer& xyz, const CgSnapshot& snap, double r, double z,
                                const std::vector<double>& breaks, int n) {
    std::vector<double> fine;
    for (std::size_t p = 0; p + 1 < breaks.size(); ++p)
        for (int k = 0; k < 16; ++k) fine.push_back(breaks[p] + (breaks[p + 1] - breaks[p]) * k / 16.0);
    fine.push_back(breaks.back());
    const auto nodes = nestedRule(1, [&](int, const double*) { return fine; }, n);
    std::vector<Vec3> pts;
    std::vector<double> w, th;
    for (const auto& nd : nodes) {
        const double t = nd.u[0];
        pts.push_back(Vec3(axisXY[0] + r * std::cos(t), axisXY[1] + r * std::sin(t), z));
        w.push_back(nd.w / (2 * M_PI));
        th.push_back(t);
    }
    const CgRawFields f = xyz.evaluateAt(pts, snap);
    std::vector<double> out(cgraw::count, 0.0);
    for (std::size_t k = 0; k < pts.size(); ++k) {
        const double* x = f.at(k);
        Eigen::Matrix3d R;  // rows e_r, e_t, e_z
        R << std::cos(th[k]), std::sin(th[k]), 0, -std::sin(th[k]), std::cos(th[k]), 0, 0, 0, 1;
        for (int c : {cgraw::number, cgraw::volume, cgraw::density}) out[c] += w[k] * x[c];
        const Eigen::Vector3d j = R * Eigen::Vector3d(x[cgraw::momentum], x[cgraw::momentum + 1], x[cgraw::momentum + 2]);
        for (int a = 0; a < 3; ++a) out[cgraw::momentum + a] += w[k] * j[a];
        const double* K = x + cgraw::momentumFlux;
        Eigen::Matrix3d Kt;
        Kt << K[0], K[3], K[4], K[3], K[1], K[5], K[4], K[5], K[2];
        const Eigen::Matrix3d Kl = R * Kt * R.transpose();
        const double ks[6] = {Kl(0, 0), Kl(1, 1), Kl(2, 2), Kl(0, 1), Kl(0, 2), Kl(1, 2)};
        for (int a = 0; a < 6; ++a) out[cgraw::momentumFlux + a] += w[k] * ks[a];
        Eigen::Matrix3d S;
        for (int a = 0; a < 9; ++a) S(a / 3, a % 3) = x[cgraw::contactStress + a];
        const Eigen::Matrix3d Sl = R * S * R.transpose();
        for (int a = 0; a < 9; ++a) out[cgraw::contactStress + a] += w[k] * Sl(a / 3, a % 3);
    }
    return out;
}

}  // namespace

TEST_CASE("CG RZ: every kernel integrates to 1; mass and axial momentum are conserved", "[cg][rz]") {
    for (const auto& kc : kernelCases()) {
        INFO(kc.name << " width " << kc.width);
        const auto cg = rzCg(kc);
        const double c = cg.kernel().cutoff();
        const auto ps = ringParticles(c);
        for (std::size_t count : {std::size_t(1), std::size_t(2), ps.size()}) {
            CgSnapshot snap;
            snap.particles.assign(ps.begin(), ps.begin() + count);
            double M = 0, Pz = 0, scale = 0;
            for (const auto& p : snap.particles) M += p.mass, Pz += p.mass * p.v[2], scale += p.mass * p.v.norm();
            // Levels: z (outer), r (inner); breaks at the support edges of
            // every particle, at the axis crossing and where the whole ring
            // enters the ball (theta support = pi).
            Breaks breaks = [&](int level, const double* u) {
                std::vector<double> b;
                for (const auto& p : snap.particles) {
                    const double ri = std::hypot(p.x[0] - axisXY[0], p.x[1] - axisXY[1]);
                    if (level == 0) {
                        b.insert(b.end(), {p.x[2] - c, p.x[2], p.x[2] + c});
                        if (ri < c) {
                            const double s = std::sqrt(c * c - ri * ri);
                            b.insert(b.end(), {p.x[2] - s, p.x[2] + s});
                        }
                    } else {
                        const double dz = u[0] - p.x[2];
                        const double h = chord(c, dz * dz);
                        if (h <= 0) continue;
                        b.insert(b.end(), {std::max(0.0, ri - h), ri, ri + h});
                        if (h > ri) b.push_back(h - ri);
                    }
                }
                return b;
            };
            const auto nodes = nestedRule(2, breaks, 24);
            std::vector<Vec3> pts;
            for (const auto& nd : nodes) pts.push_back(Vec3(nd.u[1], 0.0, nd.u[0]));
            const CgRawFields f = cg.evaluateAt(pts, snap);
            double m = 0, pz = 0, n = 0;
            for (std::size_t k = 0; k < nodes.size(); ++k) {
                const double dv = nodes[k].w * 2 * M_PI * nodes[k].u[1];
                n += dv * f.at(k)[cgraw::number];
                m += dv * f.at(k)[cgraw::density];
                pz += dv * f.at(k)[cgraw::momentum + 2];
            }
            CHECK(std::abs(n / count - 1.0) < 1e-10);
            CHECK(std::abs(m / M - 1.0) < 1e-10);
            CHECK(std::abs(pz - Pz) < 1e-10 * scale);
        }
    }
}

TEST_CASE("CG RZ: particle fields are the azimuthal average of the XYZ fields", "[cg][rz]") {
    for (const auto& kc : kernelCases()) {
        INFO(kc.name << " width " << kc.width);
        const auto rz = rzCg(kc);
        const auto xyz = xyzCg(kc);
        const double c = rz.kernel().cutoff();
        CgSnapshot snap;
        snap.particles = ringParticles(c);
        std::vector<Vec3> ring;
        for (double r : {0.05 * c, 0.4 * c, 1.1 * c, 2.3 * c, 3.0 * c})
            for (double z : {-0.3e-3, 0.1e-3, 0.6e-3}) ring.push_back(Vec3(r, 0, z));
        const CgRawFields lib = rz.evaluateAt(ring, snap);
        for (std::size_t k = 0; k < ring.size(); ++k) {
            // Reference: each particle's own angular support, split at its
            // meridian, 48 Gauss points per piece; sum over particles.
            std::vector<double> ref(cgraw::count, 0.0);
            for (const auto& p : snap.particles) {
                CgSnapshot one;
                one.particles = {p};
                const double ri = std::hypot(p.x[0] - axisXY[0], p.x[1] - axisXY[1]);
                const double thi = std::atan2(p.x[1] - axisXY[1], p.x[0] - axisXY[0]);
                const double r = ring[k][0], dz = ring[k][2] - p.x[2];
                const double A = r * r + ri * ri + dz * dz, B = 2 * r * ri;
                if (A - B >= c * c) continue;
                double T = M_PI;
                if (B > 0 && (A - c * c) / B > -1) T = std::acos((A - c * c) / B);
                const auto part = ringAverage(xyz, one, r, ring[k][2], {thi - T, thi, thi + T}, 24);
                for (int a = 0; a < cgraw::count; ++a) ref[a] += part[a];
            }
            double scale = 0;
            for (int a = 0; a < cgraw::momentumFlux + 6; ++a) scale = std::max(scale, std::abs(ref[a]));
            const double* got = lib.at(k);
            for (int a = 0; a < cgraw::momentumFlux + 6; ++a) {
                INFO("ring r " << ring[k][0] << " z " << ring[k][2] << " raw field " << a);
                CHECK(std::abs(got[a] - ref[a]) <= 1e-10 * std::max(scale, 1e-300));
            }
        }
    }
}

TEST_CASE("CG RZ: contact stress is the azimuthal average of the XYZ stress (stated tolerance)", "[cg][rz]") {
    for (const auto& kc : kernelCases()) {
        INFO(kc.name << " width " << kc.width);
        const auto rz = rzCg(kc);
        const auto xyz = xyzCg(kc);
        const double c = rz.kernel().cutoff();
        CgSnapshot snap;
        CgPairContact pc;
        pc.xi = axisXY + Vec3(0.9 * c, 0.4 * c, 0.1e-3);
        pc.xj = pc.xi - Vec3(0.62e-3, 0.41e-3, 0.65e-3);
        pc.force = Vec3(1.7, 0.9, 2.3);
        snap.pairs.push_back(pc);
        double worst = 0, largest = 0;
        for (double r : {0.1 * c, 0.6 * c, 1.2 * c, 1.9 * c, 2.6 * c})
            for (double z : {-0.6e-3, -0.2e-3, 0.2e-3}) {
                // Reference: break the circle where the ring meets the balls
                // about both ends and the cylinder about the segment (found
                // by sampling and bisection), 32 Gauss points per piece.
                const Vec3 A = pc.xi, B = pc.xj, e = (B - A).normalized();
                const double L = (B - A).norm();
                auto edges = [&](double t) {
                    const Vec3 X(axisXY[0] + r * std::cos(t), axisXY[1] + r * std::sin(t), z);
                    const double a = (X - A).dot(e);
                    const double p2 = (X - A).squaredNorm() - a * a;
                    return std::array<double, 3>{(X - A).squaredNorm() - c * c, (X - B).squaredNorm() - c * c,
                                                 (a > 0 && a < L) ? p2 - c * c : 1.0};
                };
                std::vector<double> br{-M_PI, M_PI};
                const int samples = 4000;
                for (int s = 0; s < samples; ++s) {
                    double t0 = -M_PI + 2 * M_PI * s / samples, t1 = t0 + 2 * M_PI / samples;
                    for (int f = 0; f < 3; ++f) {
                        if ((edges(t0)[f] > 0) == (edges(t1)[f] > 0)) continue;
                        double lo = t0, hi = t1;
                        for (int it = 0; it < 60; ++it) {
                            const double m = 0.5 * (lo + hi);
                            ((edges(m)[f] > 0) == (edges(lo)[f] > 0) ? lo : hi) = m;
                        }
                        br.push_back(0.5 * (lo + hi));
                    }
                }
                std::sort(br.begin(), br.end());
                const auto ref = ringAverage(xyz, snap, r, z, br, 24);
                const CgRawFields lib = rz.evaluateAt({Vec3(r, 0, z)}, snap);
                for (int a = 0; a < 9; ++a) {
                    largest = std::max(largest, std::abs(ref[cgraw::contactStress + a]));
                    worst = std::max(worst, std::abs(lib.at(0)[cgraw::contactStress + a] - ref[cgraw::contactStress + a]));
                }
            }
        INFO("largest deviation " << worst << " Pa of the largest stress " << largest << " Pa");
        CHECK(worst <= 1e-5 * largest);
    }
}
