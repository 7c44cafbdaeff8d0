// CgPointTerms.hpp: what one particle or contact adds to the raw fields at
// one point, given its kernel weight (internal to CoarseGrainer).
#pragma once
#include <array>

#include "cg/CgKernel.hpp"
#include "cg/CgRawFields.hpp"
#include "cg/CgSnapshot.hpp"

namespace granair::cgterms {

// A particle's additive quantities (vectors in the frame of the caller).
struct Particle {
    double volume = 0, mass = 0, diameterVolume = 0, inertia = 0;
    Vec3 momentum = Vec3::Zero(), angularMomentum = Vec3::Zero();
    std::array<double, 6> flux{};  // m v v: xx yy zz xy xz yz
};

// v and omega given in the frame wanted (global, or the particle's local r, t, z).
Particle particle(const CgParticle& p, const Vec3& v, const Vec3& omega);

inline void addParticle(double* rec, const Particle& t, double psi) {
    rec[cgraw::number] += psi;
    rec[cgraw::volume] += t.volume * psi;
    rec[cgraw::density] += t.mass * psi;
    for (int a = 0; a < 3; ++a) rec[cgraw::momentum + a] += t.momentum[a] * psi;
    for (int a = 0; a < 6; ++a) rec[cgraw::momentumFlux + a] += t.flux[a] * psi;
    rec[cgraw::diameter] += t.diameterVolume * psi;
    rec[cgraw::inertia] += t.inertia * psi;
    for (int a = 0; a < 3; ++a) rec[cgraw::angularMomentum + a] += t.angularMomentum[a] * psi;
}

// Azimuthal averages over a ring (RZ) of the kernel and of its products with
// cos(alpha) and cos^2(alpha), alpha the angle from the particle's meridian.
struct RingWeights {
    double w0 = 0, w1 = 0, w2 = 0;
    bool zero() const { return w0 == 0.0; }
};

// For a ring of radius r at height z and a point at distance ri from the
// axis and dz below the ring: A = r^2 + ri^2 + dz^2, B = 2 r ri.
RingWeights ringWeights(const CgKernel& k3, double A, double B, int nodes);

// Particle terms given in its local (r, t, z) frame, averaged over the ring.
void addParticleRing(double* rec, const Particle& local, const RingWeights& w);

// A vector at a point (wall force at a contact point), local frame, averaged over the ring.
inline void addVectorRing(double* rec, int offset, const Vec3& local, const RingWeights& w) {
    rec[offset + 0] += local[0] * w.w1;
    rec[offset + 1] += local[1] * w.w1;
    rec[offset + 2] += local[2] * w.w0;
}

// A segment from A to B in the resolved space of a Cartesian system (averaged
// components zeroed), with its parameter range [s0, s1] inside the window.
struct Segment {
    Vec3 a = Vec3::Zero(), u = Vec3::Zero();
    double length = 0, s0 = 0, s1 = 1;
};

// int_s0^s1 psi(g - a - s (b - a)) ds at point g (averaged components zeroed).
inline double segmentWeight(const CgKernel& k, const Segment& s, const Vec3& g) {
    const Vec3 d = g - s.a;
    if (s.length <= 1e-12 * k.cutoff() || k.dims() == 0) {
        // Perpendicular to the resolved space: the midpoint value is exact to O(length^2).
        const Vec3 m = d - 0.5 * (s.s0 + s.s1) * s.length * s.u;
        return (s.s1 - s.s0) * k.value(m.squaredNorm());
    }
    const double t = d.dot(s.u);
    const double p2 = std::max(0.0, d.squaredNorm() - t * t);
    return k.lineIntegral(p2, t - s.s1 * s.length, t - s.s0 * s.length) / s.length;
}

inline void addTensor(double* rec, const std::array<double, 9>& T, double lambda) {
    for (int a = 0; a < 9; ++a) rec[cgraw::contactStress + a] += T[a] * lambda;
}

// Outer product f (x) b, row-major, scaled.
std::array<double, 9> outer(const Vec3& f, const Vec3& b, double scale);

}  // namespace granair::cgterms
