// CgGrid.hpp: the coordinate system and the grid the CG fields live on.
//
// Cartesian systems resolve some of x, y, z and average over the others
// inside the window (a box): XYZ (3-D), XY, XZ, YZ (2-D: XZ averages over y,
// e.g. a slot silo's depth), X, Y, Z (1-D profiles) and O (no direction
// resolved: one average over the whole window, e.g. a shear-cell region).
// A particle counts when its centre lies in the window along the averaged
// directions, a contact for the part of its branch inside; fields are per
// unit volume (divided by the window's extent along the averaged directions).
//
// RZ is axisymmetric about the axis x = x0, y = y0 along z: a field at (r, z)
// is the azimuthal average of the 3-D field on the ring of radius r (kernel
// in 3-D), with vectors and tensors in the local (r, theta, z) frame.
//
// Grid points are bin centres: along a resolved axis with n points over
// [lo, hi], x_i = lo + (i + 1/2)(hi - lo)/n. Points are numbered with x (or
// r) fastest, then y, then z, as VTK orders them.
#pragma once
#include <array>
#include <cstddef>
#include <string>

#include "core/Vec3.hpp"

namespace granair {

enum class CgCoordinates { XYZ, XY, XZ, YZ, X, Y, Z, O, RZ };

// "XYZ", "XZ", ... (case-sensitive); unknown names throw InputError listing the valid ones.
CgCoordinates parseCgCoordinates(const std::string& name, const std::string& where);
std::string cgCoordinatesName(CgCoordinates c);
// Which of x, y, z a Cartesian system resolves (RZ: r as axis 0 and z).
std::array<bool, 3> cgResolvedAxes(CgCoordinates c);

class CgGrid {
public:
    // Cartesian: window box, points per axis (entries of averaged axes ignored).
    CgGrid(CgCoordinates c, const Box& window, const std::array<int, 3>& n);
    // RZ about the axis (x0, y0): r in [rmin, rmax], z in [zmin, zmax].
    static CgGrid cylindrical(double x0, double y0, double rmin, double rmax, double zmin, double zmax,
                              int nr, int nz);

    CgCoordinates coordinates() const { return coords_; }
    bool isCylindrical() const { return coords_ == CgCoordinates::RZ; }
    int dims() const { return dims_; }  // resolved directions of the grid
    // Dimension of the kernel: the resolved directions, 3 for RZ.
    int kernelDims() const { return isCylindrical() ? 3 : dims_; }
    bool resolved(int axis) const { return resolved_[axis]; }
    int count(int axis) const { return n_[axis]; }
    double lo(int axis) const { return lo_[axis]; }
    double hi(int axis) const { return hi_[axis]; }
    double spacing(int axis) const { return h_[axis]; }
    double coord(int axis, int i) const { return lo_[axis] + (i + 0.5) * h_[axis]; }
    std::size_t size() const { return std::size_t(n_[0]) * n_[1] * n_[2]; }
    std::size_t index(int i, int j, int k) const { return i + std::size_t(n_[0]) * (j + std::size_t(n_[1]) * k); }
    // Grid point coordinates: (x, y, z) with the window centre along averaged
    // axes; RZ: (r, 0, z).
    Vec3 point(std::size_t idx) const;

    // Cartesian window (RZ: the box around the rings, x0 +- rmax, y0 +- rmax).
    const Box& window() const { return window_; }
    Vec3 axisOrigin() const { return axis_; }  // RZ: (x0, y0, 0)
    // Product of the window's extents along the averaged axes (1 if none).
    double averagedVolume() const { return averagedVolume_; }
    // Volume a grid point stands for in integrals over the window [m^3]
    // (RZ: 2 pi r dr dz).
    double cellVolume(std::size_t idx) const;
    // Component labels of vectors and tensors: x y z, or r t z (t = theta).
    std::array<std::string, 3> componentNames() const;
    std::string describe() const;

private:
    CgGrid() = default;
    void finish();

    CgCoordinates coords_ = CgCoordinates::XYZ;
    int dims_ = 3;
    std::array<bool, 3> resolved_{{true, true, true}};
    std::array<int, 3> n_{{1, 1, 1}};
    std::array<double, 3> lo_{}, hi_{}, h_{};
    Box window_;
    Vec3 axis_ = Vec3::Zero();
    double averagedVolume_ = 1.0;
};

}  // namespace granair
