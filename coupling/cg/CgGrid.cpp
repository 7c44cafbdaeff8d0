// CgGrid.cpp: see CgGrid.hpp.
#include "cg/CgGrid.hpp"

#include <cmath>
#include <sstream>

#include "core/Error.hpp"

namespace granair {

namespace {

struct Named {
    const char* name;
    CgCoordinates c;
};
constexpr Named names[] = {{"O", CgCoordinates::O},   {"RZ", CgCoordinates::RZ}, {"X", CgCoordinates::X},
                           {"XY", CgCoordinates::XY}, {"XYZ", CgCoordinates::XYZ}, {"XZ", CgCoordinates::XZ},
                           {"Y", CgCoordinates::Y},   {"YZ", CgCoordinates::YZ}, {"Z", CgCoordinates::Z}};

// Largest grid we accept: 1e8 points (at ~30 doubles each, 24 GB).
constexpr double maxPoints = 1e8;

}  // namespace

CgCoordinates parseCgCoordinates(const std::string& name, const std::string& where) {
    for (const auto& n : names)
        if (name == n.name) return n.c;
    std::string list;
    for (const auto& n : names) list += std::string(" ") + n.name;
    fail<InputError>(where, ": unknown coordinates '", name, "'. Known coordinates:", list);
}

std::string cgCoordinatesName(CgCoordinates c) {
    for (const auto& n : names)
        if (n.c == c) return n.name;
    return "?";
}

std::array<bool, 3> cgResolvedAxes(CgCoordinates c) {
    switch (c) {
        case CgCoordinates::XYZ: return {{true, true, true}};
        case CgCoordinates::XY: return {{true, true, false}};
        case CgCoordinates::XZ: return {{true, false, true}};
        case CgCoordinates::YZ: return {{false, true, true}};
        case CgCoordinates::X: return {{true, false, false}};
        case CgCoordinates::Y: return {{false, true, false}};
        case CgCoordinates::Z: return {{false, false, true}};
        case CgCoordinates::O: return {{false, false, false}};
        case CgCoordinates::RZ: return {{true, false, true}};
    }
    return {{false, false, false}};
}

CgGrid::CgGrid(CgCoordinates c, const Box& window, const std::array<int, 3>& n) {
    if (c == CgCoordinates::RZ) fail("CgGrid: use CgGrid::cylindrical for RZ");
    coords_ = c;
    resolved_ = cgResolvedAxes(c);
    const char* axisName = "xyz";
    for (int a = 0; a < 3; ++a) {
        if (!(window.hi[a] > window.lo[a]) || !std::isfinite(window.lo[a]) || !std::isfinite(window.hi[a]))
            fail<InputError>("CG window: ", axisName[a], " from ", window.lo[a], " to ", window.hi[a],
                             " m, expected min < max (finite)");
        lo_[a] = window.lo[a];
        hi_[a] = window.hi[a];
        n_[a] = 1;
        if (resolved_[a]) {
            if (n[a] < 1)
                fail<InputError>("CG grid: ", n[a], " points along ", axisName[a], ", expected at least 1");
            n_[a] = n[a];
        }
    }
    window_ = window;
    finish();
}

CgGrid CgGrid::cylindrical(double x0, double y0, double rmin, double rmax, double zmin, double zmax, int nr,
                           int nz) {
    if (!(rmin >= 0.0) || !(rmax > rmin) || !std::isfinite(rmax))
        fail<InputError>("CG RZ grid: r from ", rmin, " to ", rmax, " m, expected 0 <= rmin < rmax");
    if (!(zmax > zmin) || !std::isfinite(zmin) || !std::isfinite(zmax))
        fail<InputError>("CG RZ grid: z from ", zmin, " to ", zmax, " m, expected min < max");
    if (nr < 1 || nz < 1) fail<InputError>("CG RZ grid: ", nr, " x ", nz, " points, expected at least 1 x 1");
    if (!std::isfinite(x0) || !std::isfinite(y0)) fail<InputError>("CG RZ grid: axis (", x0, ", ", y0, ") not finite");
    CgGrid g;
    g.coords_ = CgCoordinates::RZ;
    g.resolved_ = {{true, false, true}};
    g.lo_ = {{rmin, 0.0, zmin}};
    g.hi_ = {{rmax, 1.0, zmax}};
    g.n_ = {{nr, 1, nz}};
    g.axis_ = Vec3(x0, y0, 0.0);
    g.window_ = Box{Vec3(x0 - rmax, y0 - rmax, zmin), Vec3(x0 + rmax, y0 + rmax, zmax)};
    g.finish();
    g.averagedVolume_ = 1.0;
    return g;
}

void CgGrid::finish() {
    dims_ = 0;
    averagedVolume_ = 1.0;
    for (int a = 0; a < 3; ++a) {
        h_[a] = (hi_[a] - lo_[a]) / n_[a];
        if (resolved_[a]) ++dims_;
        else averagedVolume_ *= hi_[a] - lo_[a];
    }
    if (double(n_[0]) * n_[1] * n_[2] > maxPoints)
        fail<InputError>("CG grid: ", n_[0], " x ", n_[1], " x ", n_[2], " points, more than the ", maxPoints,
                         " this tool accepts");
}

Vec3 CgGrid::point(std::size_t idx) const {
    const int i = int(idx % n_[0]);
    const int j = int((idx / n_[0]) % n_[1]);
    const int k = int(idx / (std::size_t(n_[0]) * n_[1]));
    if (isCylindrical()) return Vec3(coord(0, i), 0.0, coord(2, k));
    return Vec3(coord(0, i), coord(1, j), coord(2, k));
}

double CgGrid::cellVolume(std::size_t idx) const {
    if (isCylindrical()) return 2.0 * M_PI * point(idx)[0] * h_[0] * h_[2];
    double v = averagedVolume_;
    for (int a = 0; a < 3; ++a)
        if (resolved_[a]) v *= h_[a];
    return v;
}

std::array<std::string, 3> CgGrid::componentNames() const {
    if (isCylindrical()) return {{"r", "t", "z"}};
    return {{"x", "y", "z"}};
}

std::string CgGrid::describe() const {
    std::ostringstream os;
    os.precision(6);
    os << cgCoordinatesName(coords_) << " grid";
    if (isCylindrical()) {
        os << " about the axis (" << axis_[0] << ", " << axis_[1] << "): " << n_[0] << " x " << n_[2]
           << " points, r " << lo_[0] << " to " << hi_[0] << " m, z " << lo_[2] << " to " << hi_[2] << " m";
        return os.str();
    }
    const char* axisName = "xyz";
    os << ":";
    for (int a = 0; a < 3; ++a) {
        os << " " << axisName[a] << " " << lo_[a] << " to " << hi_[a] << " m";
        if (resolved_[a]) os << " (" << n_[a] << " points)";
        else os << " (averaged)";
    }
    return os.str();
}

}  // namespace granair
