// CgPointTerms.cpp: see CgPointTerms.hpp.
#include "cg/CgPointTerms.hpp"

#include <cmath>

#include "cg/GaussLegendre.hpp"

namespace granair::cgterms {

Particle particle(const CgParticle& p, const Vec3& v, const Vec3& omega) {
    Particle t;
    const double d = 2.0 * p.radius;
    t.volume = M_PI / 6.0 * d * d * d;
    t.mass = p.mass;
    t.diameterVolume = t.volume * d;
    t.inertia = 0.4 * p.mass * p.radius * p.radius;
    t.momentum = p.mass * v;
    t.angularMomentum = t.inertia * omega;
    t.flux = {p.mass * v[0] * v[0], p.mass * v[1] * v[1], p.mass * v[2] * v[2],
              p.mass * v[0] * v[1], p.mass * v[0] * v[2], p.mass * v[1] * v[2]};
    return t;
}

RingWeights ringWeights(const CgKernel& k3, double A, double B, int nodes) {
    RingWeights w;
    const double c2 = k3.cutoff2();
    if (A - B >= c2) return w;  // the ring's nearest point is beyond the cutoff
    if (B <= 0.0) {             // ring on the axis or point on the axis: constant distance
        w.w0 = k3.value(A);
        w.w2 = 0.5 * w.w0;
        return w;
    }
    const double cosT = (A - c2) / B;
    const double theta = cosT <= -1.0 ? M_PI : std::acos(cosT);
    const auto& gl = gaussLegendre(nodes);
    double s0 = 0, s1 = 0, s2 = 0;
    for (int q = 0; q < nodes; ++q) {
        // alpha = theta (1 - cos(tau/2)): nodes gather at alpha = 0, where a
        // ring passing near the particle's centre sees the kernel least
        // smooth (Lucy's |x|^3 term); dalpha = theta/2 sin(tau/2) dtau.
        const double tau = 0.5 * M_PI * (gl.x[q] + 1.0);
        const double alpha = theta * (1.0 - std::cos(0.5 * tau));
        const double ca = std::cos(alpha);
        const double f = gl.w[q] * std::sin(0.5 * tau) * k3.value(std::max(0.0, A - B * ca));
        s0 += f;
        s1 += f * ca;
        s2 += f * ca * ca;
    }
    // (1/2pi) int_{-theta}^{theta} = (1/pi) int_0^theta; the map's factor theta pi/4.
    const double scale = 0.25 * theta;
    w.w0 = s0 * scale;
    w.w1 = s1 * scale;
    w.w2 = s2 * scale;
    return w;
}

void addParticleRing(double* rec, const Particle& t, const RingWeights& w) {
    const double w0 = w.w0, w1 = w.w1, w2 = w.w2;
    rec[cgraw::number] += w0;
    rec[cgraw::volume] += t.volume * w0;
    rec[cgraw::density] += t.mass * w0;
    addVectorRing(rec, cgraw::momentum, t.momentum, w);
    // m v v in the ring's frame, averaged over +-alpha (docs/cg-fields.md, RZ).
    const auto& K = t.flux;  // rr tt zz rt rz tz
    double* o = rec + cgraw::momentumFlux;
    o[0] += w2 * K[0] + (w0 - w2) * K[1];
    o[1] += w2 * K[1] + (w0 - w2) * K[0];
    o[2] += w0 * K[2];
    o[3] += (2.0 * w2 - w0) * K[3];
    o[4] += w1 * K[4];
    o[5] += w1 * K[5];
    rec[cgraw::diameter] += t.diameterVolume * w0;
    rec[cgraw::inertia] += t.inertia * w0;
    addVectorRing(rec, cgraw::angularMomentum, t.angularMomentum, w);
}

std::array<double, 9> outer(const Vec3& f, const Vec3& b, double scale) {
    std::array<double, 9> T;
    for (int a = 0; a < 3; ++a)
        for (int c = 0; c < 3; ++c) T[3 * a + c] = f[a] * b[c] * scale;
    return T;
}

}  // namespace granair::cgterms
