// CoarseGrainer.cpp: see CoarseGrainer.hpp.
#include "cg/CoarseGrainer.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "cg/CgPointTerms.hpp"
#include "cg/GaussLegendre.hpp"
#include "core/Error.hpp"

namespace granair {

struct CoarseGrainer::Copy {
    enum Kind { particle, pair, wall } kind = particle;
    int index = 0;
    Vec3 shift = Vec3::Zero();
    double s0 = 0.0, s1 = 1.0;  // segment parameter range inside the window (averaged axes)
    bool pointInside = true;    // wall: contact point inside the window (averaged axes)
    int lo[3] = {0, 0, 0}, hi[3] = {-1, -1, -1};  // inclusive grid index ranges
};

namespace {

// Gauss nodes per piece of the azimuthal rule for contact segments (RZ).
constexpr int segmentPieceNodes = 8;
// Largest arc of one sub-panel, in cutoffs (the Gaussian varies on c/3).
constexpr double segmentPanelArc = 0.5;

// Clip the segment a + s (b - a), s in [s0, s1], to lo <= x < hi along one axis.
bool clipToSlab(double a, double b, double lo, double hi, double& s0, double& s1) {
    const double d = b - a;
    if (d == 0.0) return a >= lo && a < hi;
    double t0 = (lo - a) / d, t1 = (hi - a) / d;
    if (t0 > t1) std::swap(t0, t1);
    s0 = std::max(s0, t0);
    s1 = std::min(s1, t1);
    return s1 > s0;
}

// Grid index range of the coordinates [xmin, xmax] along an axis.
void indexRange(const CgGrid& g, int axis, double xmin, double xmax, int& lo, int& hi) {
    const double h = g.spacing(axis);
    lo = std::max(0, int(std::ceil((xmin - g.lo(axis)) / h - 0.5)));
    hi = std::min(g.count(axis) - 1, int(std::floor((xmax - g.lo(axis)) / h - 0.5)));
}

// Local frame of a point about the axis: e_r, e_t (theta), and the radius.
struct RingFrame {
    Vec3 er{1, 0, 0}, et{0, 1, 0};
    double r = 0;
};
RingFrame ringFrame(const Vec3& axis, const Vec3& x) {
    RingFrame f;
    const double dx = x[0] - axis[0], dy = x[1] - axis[1];
    f.r = std::hypot(dx, dy);
    if (f.r > 0) {
        f.er = Vec3(dx / f.r, dy / f.r, 0);
        f.et = Vec3(-f.er[1], f.er[0], 0);
    }
    return f;
}
Vec3 toLocal(const RingFrame& f, const Vec3& v) { return Vec3(v.dot(f.er), v.dot(f.et), v[2]); }

// The segment from A to B (3-D) as a kernel-space segment (RZ: all of 3-D).
cgterms::Segment makeSegment(const Vec3& A, const Vec3& B, const std::array<bool, 3>& res, double s0,
                             double s1) {
    cgterms::Segment s;
    Vec3 e = Vec3::Zero();
    for (int a = 0; a < 3; ++a)
        if (res[a]) {
            s.a[a] = A[a];
            e[a] = B[a] - A[a];
        }
    s.length = e.norm();
    if (s.length > 0) s.u = e / s.length;
    s.s0 = s0;
    s.s1 = s1;
    return s;
}

// Angles on the ring (r, z) about the axis where |X(theta) - P| = c, within
// [t0, t1] (shifted by 2 pi as needed).
void ballCrossings(const Vec3& axis, const Vec3& P, double c, double r, double z, double t0, double t1,
                   std::vector<double>& out) {
    const double dx = P[0] - axis[0], dy = P[1] - axis[1], dz = z - P[2];
    const double rp = std::hypot(dx, dy);
    const double A = r * r + rp * rp + dz * dz, B = 2.0 * r * rp;
    if (B <= 0.0) return;
    const double ct = (A - c * c) / B;
    if (!(ct > -1.0 && ct < 1.0)) return;
    const double tp = std::atan2(dy, dx), T = std::acos(ct);
    for (double t : {tp - T, tp + T})
        for (int k = -2; k <= 2; ++k) {
            const double u = t + 2.0 * M_PI * k;
            if (u > t0 && u < t1) out.push_back(u);
        }
}

// Add the azimuthal average of a contact segment's tensor over the ring
// (r, z) (RZ). The angles where the ring can meet the capsule about the
// segment (radius c) come from its bounding sphere; inside them the
// integrand is smooth except where the ring crosses the balls about the
// ends (found exactly) and the cylinder about the segment (sign changes of
// a trigonometric polynomial of degree 2, sampled and bisected): these are
// the pieces' ends, and each piece gets a Gauss-Legendre rule in
// t = acos(1 - 2 (theta - a)/(b - a)), which also absorbs the square-root
// behaviour at the support's edge.
void addSegmentRing(const CgKernel& k3, const Vec3& axis, const cgterms::Segment& seg3,
                    const std::array<double, 9>& T, const Vec3& mid, double reach, double r, double z,
                    double* rec) {
    const RingFrame mf = ringFrame(axis, mid);
    const double dz = z - mid[2];
    const double A = r * r + mf.r * mf.r + dz * dz, B = 2.0 * r * mf.r;
    if (A - B >= reach * reach) return;
    double delta = M_PI;
    if (B > 0.0) {
        const double cd = (A - reach * reach) / B;
        if (cd > -1.0) delta = std::acos(std::min(1.0, cd));
    }
    const double thetaM = std::atan2(mid[1] - axis[1], mid[0] - axis[0]);
    const double t0 = thetaM - delta, t1 = thetaM + delta;
    const double c = k3.cutoff();
    std::vector<double> br{t0, t1};
    const Vec3 a = seg3.a, b = seg3.a + seg3.length * seg3.u;
    ballCrossings(axis, a, c, r, z, t0, t1, br);
    ballCrossings(axis, b, c, r, z, t0, t1, br);
    if (seg3.length > 0.0) {
        auto cylinder = [&](double t) {
            const Vec3 d(axis[0] + r * std::cos(t) - a[0], axis[1] + r * std::sin(t) - a[1], z - a[2]);
            const double along = d.dot(seg3.u);
            return d.squaredNorm() - along * along - c * c;
        };
        // f = p^2 - c^2 at (cos t, sin t): sampled by a rotation recurrence
        // (no sine or cosine per sample), refined with the exact function.
        auto cylinderCS = [&](double cs, double sn) {
            const Vec3 d(axis[0] + r * cs - a[0], axis[1] + r * sn - a[1], z - a[2]);
            const double along = d.dot(seg3.u);
            return d.squaredNorm() - along * along - c * c;
        };
        constexpr int samples = 16;
        const double step = (t1 - t0) / samples, cStep = std::cos(step), sStep = std::sin(step);
        double cs = std::cos(t0), sn = std::sin(t0);
        double fPrev = cylinderCS(cs, sn), tPrev = t0;
        for (int q = 1; q <= samples; ++q) {
            const double t = t0 + step * q;
            const double c1 = cs * cStep - sn * sStep;
            sn = sn * cStep + cs * sStep, cs = c1;
            const double f = cylinderCS(cs, sn);
            if ((f > 0.0) != (fPrev > 0.0)) {
                // Illinois (regula falsi that halves the stale end's value):
                // superlinear, a few steps to 1e-9 rad (a break that far off
                // the sqrt-type edge costs ~(1e-9)^1.5 of the integral).
                double a0 = tPrev, fa = fPrev, b0 = t, fb = f;
                int side = 0;
                for (int it = 0; it < 30 && std::abs(b0 - a0) > 1e-9; ++it) {
                    const double m = (a0 * fb - b0 * fa) / (fb - fa);
                    const double fm = cylinder(m);
                    if ((fm > 0.0) == (fb > 0.0)) {
                        b0 = m, fb = fm;
                        if (side == -1) fa *= 0.5;
                        side = -1;
                    } else {
                        a0 = m, fa = fm;
                        if (side == 1) fb *= 0.5;
                        side = 1;
                    }
                    if (fm == 0.0) a0 = b0 = m;
                }
                br.push_back(0.5 * (a0 + b0));
            }
            fPrev = f, tPrev = t;
        }
    }
    std::sort(br.begin(), br.end());
    const auto& gl = gaussLegendre(segmentPieceNodes);
    double m0 = 0, mc = 0, ms = 0, mcc = 0, mcs = 0, mss = 0;
    auto node = [&](double cs, double sn, double wq) {
        const Vec3 X(axis[0] + r * cs, axis[1] + r * sn, z);
        const double f = wq * cgterms::segmentWeight(k3, seg3, X);
        if (f == 0.0) return;
        m0 += f;
        mc += f * cs;
        ms += f * sn;
        mcc += f * cs * cs;
        mcs += f * cs * sn;
        mss += f * sn * sn;
    };
    // Node offsets within a sub-panel of width h and their weights, for the
    // three kinds: cosine map to the left end, plain, cosine map to the right
    // end (and both ends when a piece is one sub-panel); the node angles are
    // then built by angle addition from the sub-panel's start.
    struct Pattern {
        double off[segmentPieceNodes], w[segmentPieceNodes], co[segmentPieceNodes], si[segmentPieceNodes];
    };
    auto pattern = [&](int kind, double h) {
        Pattern pt;
        for (int q = 0; q < segmentPieceNodes; ++q) {
            const double tau = 0.5 * M_PI * (gl.x[q] + 1.0);
            if (kind == 0) pt.off[q] = h * (1.0 - std::cos(0.5 * tau)), pt.w[q] = gl.w[q] * 0.25 * M_PI * h * std::sin(0.5 * tau);
            else if (kind == 1) pt.off[q] = 0.5 * h * (gl.x[q] + 1.0), pt.w[q] = 0.5 * h * gl.w[q];
            else if (kind == 2) pt.off[q] = h * std::sin(0.5 * tau), pt.w[q] = gl.w[q] * 0.25 * M_PI * h * std::cos(0.5 * tau);
            else pt.off[q] = 0.5 * h * (1.0 - std::cos(tau)), pt.w[q] = gl.w[q] * 0.25 * M_PI * h * std::sin(tau);
            pt.co[q] = std::cos(pt.off[q]);
            pt.si[q] = std::sin(pt.off[q]);
        }
        return pt;
    };
    for (std::size_t p = 0; p + 1 < br.size(); ++p) {
        const double len = br[p + 1] - br[p];
        if (!(len > 0.0)) continue;
        // Sub-panels no longer than segmentPanelArc cutoffs of arc, nor a
        // quarter turn (the frame's rotation); the end ones (a kink or the
        // support's edge at one side) in the cosine map.
        const int m = std::max({1, int(std::ceil(r * len / (segmentPanelArc * c))), int(std::ceil(len / (0.5 * M_PI)))});
        const double h = len / m;
        const Pattern first = pattern(m == 1 ? 3 : 0, h);
        const Pattern middle = m > 2 ? pattern(1, h) : first;
        const Pattern last = m > 1 ? pattern(2, h) : first;
        for (int sp = 0; sp < m; ++sp) {
            const double lo = br[p] + sp * h;
            const Pattern& pt = sp == 0 ? first : sp == m - 1 ? last : middle;
            const double c0 = std::cos(lo), s0 = std::sin(lo);
            for (int q = 0; q < segmentPieceNodes; ++q)
                node(c0 * pt.co[q] - s0 * pt.si[q], s0 * pt.co[q] + c0 * pt.si[q], pt.w[q]);
        }
    }
    if (m0 == 0.0) return;
    const double scale = 1.0 / (2.0 * M_PI);
    m0 *= scale, mc *= scale, ms *= scale, mcc *= scale, mcs *= scale, mss *= scale;
    const double xx = T[0], xy = T[1], xz = T[2], yx = T[3], yy = T[4], yz = T[5], zx = T[6], zy = T[7],
                 zz = T[8];
    double* o = rec + cgraw::contactStress;
    o[0] += mcc * xx + mcs * (xy + yx) + mss * yy;       // rr
    o[1] += -mcs * xx + mcc * xy - mss * yx + mcs * yy;  // rt
    o[2] += mc * xz + ms * yz;                           // rz
    o[3] += -mcs * xx - mss * xy + mcc * yx + mcs * yy;  // tr
    o[4] += mss * xx - mcs * (xy + yx) + mcc * yy;       // tt
    o[5] += -ms * xz + mc * yz;                          // tz
    o[6] += mc * zx + ms * zy;                           // zr
    o[7] += -ms * zx + mc * zy;                          // zt
    o[8] += m0 * zz;                                     // zz
}

}  // namespace

CoarseGrainer::CoarseGrainer(CgGrid grid, CgKernel kernel, int azimuthalNodes)
    : grid_(std::move(grid)), kernel_(std::move(kernel)), azimuthalNodes_(azimuthalNodes) {
    if (kernel_.dims() != grid_.kernelDims())
        fail("CoarseGrainer: a ", kernel_.dims(), "-D kernel for a ", grid_.kernelDims(), "-D ",
             cgCoordinatesName(grid_.coordinates()), " grid");
    if (azimuthalNodes_ < 2 || azimuthalNodes_ > 200)
        fail<InputError>("CG: ", azimuthalNodes_, " azimuthal nodes, expected 2 to 200");
    slabAxis_ = grid_.count(2) > 1 ? 2 : grid_.count(1) > 1 ? 1 : 0;
    resolved_ = cgResolvedAxes(grid_.coordinates());
}

std::vector<CoarseGrainer::Copy> CoarseGrainer::copies(const CgSnapshot& snap, bool gridOnly) const {
    const double c = kernel_.cutoff();
    const auto res = cgResolvedAxes(grid_.coordinates());
    const bool rz = grid_.isCylindrical();
    const Box& win = grid_.window();
    // Where an object can touch the grid: the window grown by the cutoff along
    // the directions the kernel acts in (all three for RZ).
    Box reach = win;
    for (int a = 0; a < 3; ++a)
        if (rz || res[a]) {
            reach.lo[a] = (rz && a == 2 ? grid_.lo(2) : win.lo[a]) - c;
            reach.hi[a] = (rz && a == 2 ? grid_.hi(2) : win.hi[a]) + c;
        }
    // Image shifts: one period either way along periodic directions.
    std::vector<Vec3> shifts{Vec3::Zero()};
    for (int a = 0; a < 3; ++a) {
        if (!snap.domain.periodic[a]) continue;
        const double L = snap.domain.period(a);
        std::vector<Vec3> more;
        for (const auto& s : shifts)
            for (double k : {-1.0, 1.0}) {
                Vec3 t = s;
                t[a] += k * L;
                more.push_back(t);
            }
        shifts.insert(shifts.end(), more.begin(), more.end());
    }

    std::vector<Copy> out;
    out.reserve(snap.particles.size() + snap.pairs.size() + snap.walls.size());
    auto place = [&](Copy::Kind kind, int index, const Vec3& A, const Vec3& B) {
        const Vec3 bmin = A.cwiseMin(B), bmax = A.cwiseMax(B);
        for (const auto& s : shifts) {
            bool meets = true;
            for (int a = 0; a < 3 && meets; ++a)
                meets = bmax[a] + s[a] >= reach.lo[a] && bmin[a] + s[a] <= reach.hi[a];
            if (!meets) continue;
            Copy cp;
            cp.kind = kind;
            cp.index = index;
            cp.shift = s;
            const Vec3 a = A + s, b = B + s;
            if (!rz) {
                // Along averaged axes: a particle counts if its centre is in the
                // window, a segment for its part inside, a wall's traction if
                // its contact point is inside.
                bool particleIn = true, segmentIn = true, pointIn = true;
                for (int ax = 0; ax < 3; ++ax) {
                    if (res[ax]) continue;
                    if (kind == Copy::particle) {
                        particleIn = particleIn && a[ax] >= win.lo[ax] && a[ax] < win.hi[ax];
                        continue;
                    }
                    segmentIn = segmentIn && clipToSlab(a[ax], b[ax], win.lo[ax], win.hi[ax], cp.s0, cp.s1);
                    pointIn = pointIn && b[ax] >= win.lo[ax] && b[ax] < win.hi[ax];
                }
                if (kind == Copy::particle ? !particleIn : !(segmentIn || (kind == Copy::wall && pointIn)))
                    continue;
                if (!segmentIn) cp.s0 = cp.s1 = 0.0;
                cp.pointInside = kind == Copy::wall && pointIn;
                Vec3 clo = Vec3::Constant(1e300), chi = Vec3::Constant(-1e300);
                if (kind == Copy::particle) clo = chi = a;
                if (cp.s1 > cp.s0) {
                    const Vec3 sa = a + cp.s0 * (b - a), sb = a + cp.s1 * (b - a);
                    clo = sa.cwiseMin(sb), chi = sa.cwiseMax(sb);
                }
                if (cp.pointInside) clo = clo.cwiseMin(b), chi = chi.cwiseMax(b);
                bool empty = false;
                for (int ax = 0; ax < 3; ++ax) {
                    if (!res[ax]) {
                        cp.lo[ax] = cp.hi[ax] = 0;
                        continue;
                    }
                    indexRange(grid_, ax, clo[ax] - c, chi[ax] + c, cp.lo[ax], cp.hi[ax]);
                    empty = empty || cp.lo[ax] > cp.hi[ax];
                }
                if (!empty || !gridOnly) out.push_back(cp);
            } else {
                // RZ: radii the segment's bounding box spans about the axis.
                const Vec3 ax = grid_.axisOrigin();
                const Vec3 lo = a.cwiseMin(b), hi = a.cwiseMax(b);
                const double nx = std::clamp(ax[0], lo[0], hi[0]) - ax[0];
                const double ny = std::clamp(ax[1], lo[1], hi[1]) - ax[1];
                const double fx = std::max(std::abs(lo[0] - ax[0]), std::abs(hi[0] - ax[0]));
                const double fy = std::max(std::abs(lo[1] - ax[1]), std::abs(hi[1] - ax[1]));
                indexRange(grid_, 0, std::hypot(nx, ny) - c, std::hypot(fx, fy) + c, cp.lo[0], cp.hi[0]);
                indexRange(grid_, 2, lo[2] - c, hi[2] + c, cp.lo[2], cp.hi[2]);
                cp.lo[1] = cp.hi[1] = 0;
                if ((cp.lo[0] <= cp.hi[0] && cp.lo[2] <= cp.hi[2]) || !gridOnly) out.push_back(cp);
            }
        }
    };
    for (std::size_t i = 0; i < snap.particles.size(); ++i)
        place(Copy::particle, int(i), snap.particles[i].x, snap.particles[i].x);
    for (std::size_t i = 0; i < snap.pairs.size(); ++i)
        place(Copy::pair, int(i), snap.pairs[i].xi, snap.pairs[i].xj);
    for (std::size_t i = 0; i < snap.walls.size(); ++i)
        place(Copy::wall, int(i), snap.walls[i].x, snap.walls[i].point);
    return out;
}

// A copy made ready for its grid points: everything that does not depend on
// the point, computed once.
struct CoarseGrainer::Prepared {
    Copy::Kind kind = Copy::particle;
    Vec3 x = Vec3::Zero();      // particle centre (shifted), or the segment's end B = contact point
    cgterms::Particle terms;    // particle (RZ: in its local frame)
    cgterms::Segment segment;   // pair or wall segment (kernel space)
    std::array<double, 9> T{};  // f (x) (A - B) / averaged volume
    bool hasSegment = false, hasPoint = false;
    Vec3 force = Vec3::Zero();  // wall force (RZ: in the contact point's local frame)
    Vec3 mid = Vec3::Zero();    // RZ: segment midpoint, and the capsule's bounding radius
    double reach = 0.0;
    double scale = 1.0;         // 1 / averaged volume
};

CoarseGrainer::Prepared CoarseGrainer::prepare(const Copy& cp, const CgSnapshot& snap) const {
    Prepared p;
    p.kind = cp.kind;
    const bool rz = grid_.isCylindrical();
    const auto res = rz ? std::array<bool, 3>{{true, true, true}} : cgResolvedAxes(grid_.coordinates());
    p.scale = rz ? 1.0 : 1.0 / grid_.averagedVolume();
    if (cp.kind == Copy::particle) {
        const CgParticle& q = snap.particles[cp.index];
        p.x = q.x + cp.shift;
        if (rz) {
            const RingFrame fr = ringFrame(grid_.axisOrigin(), p.x);
            p.terms = cgterms::particle(q, toLocal(fr, q.v), toLocal(fr, q.omega));
        } else {
            p.terms = cgterms::particle(q, q.v, q.omega);
        }
        return p;
    }
    Vec3 A, B, f;
    if (cp.kind == Copy::pair) {
        const auto& c = snap.pairs[cp.index];
        A = c.xi, B = c.xj, f = c.force;
    } else {
        const auto& w = snap.walls[cp.index];
        A = w.x, B = w.point, f = w.force;
    }
    const Vec3 a = A + cp.shift, b = B + cp.shift;
    p.x = b;
    p.hasSegment = cp.s1 > cp.s0;
    p.segment = makeSegment(a, b, res, cp.s0, cp.s1);
    p.T = cgterms::outer(f, A - B, p.scale);
    p.hasPoint = cp.kind == Copy::wall && cp.pointInside;
    p.force = rz ? toLocal(ringFrame(grid_.axisOrigin(), b), f) : f;
    p.mid = 0.5 * (a + b);
    p.reach = 0.5 * p.segment.length + kernel_.cutoff();
    return p;
}

// Deposit one copy on the grid points of its range whose slab index lies in
// [slabLo, slabHi].
void CoarseGrainer::deposit(const Copy& cp, const CgSnapshot& snap, int slabLo, int slabHi,
                            CgRawFields& out) const {
    int lo[3] = {cp.lo[0], cp.lo[1], cp.lo[2]}, hi[3] = {cp.hi[0], cp.hi[1], cp.hi[2]};
    lo[slabAxis_] = std::max(lo[slabAxis_], slabLo);
    hi[slabAxis_] = std::min(hi[slabAxis_], slabHi);
    if (lo[slabAxis_] > hi[slabAxis_]) return;
    const Prepared p = prepare(cp, snap);
    Vec3 g;
    for (int k = lo[2]; k <= hi[2]; ++k) {
        g[2] = grid_.coord(2, k);
        for (int j = lo[1]; j <= hi[1]; ++j) {
            g[1] = grid_.coord(1, j);
            for (int i = lo[0]; i <= hi[0]; ++i) {
                g[0] = grid_.coord(0, i);
                apply(p, g, out.at(grid_.index(i, j, k)));
            }
        }
    }
}

void CoarseGrainer::apply(const Prepared& p, const Vec3& point, double* rec) const {
    if (!grid_.isCylindrical()) {
        const auto& res = resolved_;
        Vec3 g = Vec3::Zero();
        for (int a = 0; a < 3; ++a)
            if (res[a]) g[a] = point[a];
        auto distance2 = [&](const Vec3& x) {
            double d2 = 0;
            for (int a = 0; a < 3; ++a)
                if (res[a]) d2 += (g[a] - x[a]) * (g[a] - x[a]);
            return d2;
        };
        const bool unit = kernel_.dims() == 0;
        if (p.kind == Copy::particle) {
            const double r2 = distance2(p.x);
            if (unit || r2 < kernel_.cutoff2()) cgterms::addParticle(rec, p.terms, kernel_.value(r2) * p.scale);
            return;
        }
        if (p.hasSegment) {
            const double lambda = cgterms::segmentWeight(kernel_, p.segment, g);
            if (lambda != 0.0) cgterms::addTensor(rec, p.T, lambda);
        }
        if (p.hasPoint) {
            const double r2 = distance2(p.x);
            if (unit || r2 < kernel_.cutoff2()) {
                const double psi = kernel_.value(r2) * p.scale;
                for (int a = 0; a < 3; ++a) rec[cgraw::wallForce + a] += p.force[a] * psi;
            }
        }
        return;
    }

    // RZ: point = (r, -, z).
    const Vec3& axis = grid_.axisOrigin();
    const double r = point[0], z = point[2];
    auto weightsAt = [&](const Vec3& x) {
        const RingFrame fr = ringFrame(axis, x);
        const double dz = z - x[2];
        return cgterms::ringWeights(kernel_, r * r + fr.r * fr.r + dz * dz, 2.0 * r * fr.r, azimuthalNodes_);
    };
    if (p.kind == Copy::particle) {
        const auto w = weightsAt(p.x);
        if (!w.zero()) cgterms::addParticleRing(rec, p.terms, w);
        return;
    }
    addSegmentRing(kernel_, axis, p.segment, p.T, p.mid, p.reach, r, z, rec);
    if (p.hasPoint) {
        const auto w = weightsAt(p.x);
        if (!w.zero()) cgterms::addVectorRing(rec, cgraw::wallForce, p.force, w);
    }
}

CgRawFields CoarseGrainer::compute(const CgSnapshot& snap, int threads, CgCounts* counts) const {
    const auto list = copies(snap, true);
    if (counts) {
        *counts = CgCounts{};
        for (const auto& c : list)
            (c.kind == Copy::particle ? counts->particles : c.kind == Copy::pair ? counts->pairs : counts->walls)++;
    }
    CgRawFields out(grid_.size());
    const int nSlab = grid_.count(slabAxis_);
    const int nThreads = threads > 0 ? threads : omp_get_max_threads();
    // Several slabs per thread, handed out dynamically: particles crowd in
    // parts of a silo, so equal slabs are not equal work.
    const int chunks = std::min(nSlab, 4 * nThreads);
#pragma omp parallel for schedule(dynamic, 1) num_threads(nThreads)
    for (int ch = 0; ch < chunks; ++ch) {
        const int k0 = int(std::int64_t(nSlab) * ch / chunks);
        const int k1 = int(std::int64_t(nSlab) * (ch + 1) / chunks) - 1;
        for (const auto& c : list)
            if (c.hi[slabAxis_] >= k0 && c.lo[slabAxis_] <= k1) deposit(c, snap, k0, k1, out);
    }
    return out;
}

CgRawFields CoarseGrainer::evaluateAt(const std::vector<Vec3>& points, const CgSnapshot& snap) const {
    // Every copy at every point: apply does the cutoff tests.
    const auto list = copies(snap, false);
    CgRawFields out(points.size());
    for (const auto& c : list) {
        const Prepared prep = prepare(c, snap);
        for (std::size_t p = 0; p < points.size(); ++p) apply(prep, points[p], out.at(p));
    }
    return out;
}

}  // namespace granair
