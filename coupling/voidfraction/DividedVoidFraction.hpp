// DividedVoidFraction.hpp: the divided (satellite-point) void-fraction model ("divided").
//
// Summary: the sphere is cut into N equal-volume pieces, each represented by
// one point; each piece's volume goes to the cell holding its point.
//
// Points (offsets from the particle centre, in units of the radius r):
//   N = 1 + 24 S points for S shells (parameter `shells`, default 1 -> N = 25).
//   - the centre, standing for the inner ball of radius a_0 = N^(-1/3) r;
//   - shell k = 1..S spans the radii a_{k-1} .. a_k with a_k = ((1 + 24k)/N)^(1/3) r,
//     i.e. volume 24/N of the sphere, split equally among 24 points at radius
//         r_k = sqrt( 3/5 (a_k^5 - a_{k-1}^5) / (a_k^3 - a_{k-1}^3) ),
//     the rms radius of the shell (so each shell keeps its second moment);
//   - the 24 directions of every shell are the orbit of u = (p, q, s) under all
//     sign changes and cyclic permutations of the axes, with
//         p^2 = (1 - 1/sqrt5)/8,  q^2 = (1 + 1/sqrt5)/8,  s^2 = 3/4,
//     chosen so p^4 + q^4 + s^4 = 3/5: then the 24 directions average every
//     polynomial of degree <= 5 exactly as the sphere does (a spherical
//     5-design). So the points reproduce the sphere's volume, centroid and
//     (up to the inner ball's share, a relative N^(-5/3)) its second moment.
//   Every point stands for exactly V_p / N. No direction has a zero component,
//   and the set is symmetric under each axis reflection: a particle centred on
//   a cell face puts exactly half of each shell on either side, and only the
//   centre point (1/N) breaks the tie.
//
// Stencil: each point x_p + offset is located with mesh.findCell(point,
// centreCell); a point not found on this rank (another rank's cells, or outside
// the domain) counts for the centre cell, as in CFDEMcoupling, so the volume is
// conserved exactly. Weight of cell c = (number of points counted for c) / N,
// an exact fraction; the weights sum to 1 to round-off. Each cell appears once.
//
// Validity: cells comparable to or larger than the particle; it smooths the
// jump of eps as a particle crosses a face over a distance of about one
// radius. Accuracy of the face split against exact sphere-cap volumes: a
// 1-shell stencil is within about 4/N of the geometric overlap; over a sweep
// of plane distances its worst error is 0.13 for axis-aligned faces and 0.12
// for planes of random orientation, against 0.16 and 0.19 for CFDEMcoupling's
// 29-point layout (our offline comparison). Cells much smaller than the
// particle get a speckled field (each point lands in one cell); use `gaussian`
// there. Near a processor boundary the points beyond it count for the centre
// cell, so results differ slightly from a serial run.
//
// Parameters:
//   shells   number of point shells, integer 1..4 [-], default 1 (25 points;
//            2 -> 49, 3 -> 73, 4 -> 97). Cost is one findCell per point
//            (on a BoxMesh roughly 0.4-1.4 us per particle for 25 points).
//
// Reference: CFDEMcoupling documentation, voidFractionModel_dividedVoidFraction
// (https://www.cfdem.com/media/CFDEM/docu/voidFractionModel_dividedVoidFraction.html),
// whose 29 points (centre + 2 shells of 14 at 0.624 r and 0.918 r) we
// replaced by the equal-volume 5-design layout above (fewer points, exact
// reflection symmetry); Goniva, C., Kloss, C., Deen, N.G., Kuipers, J.A.M.,
// Pirker, S. (2012), Influence of rolling friction on single spout fluidized
// bed simulation, Particuology 10(5):582-591.
#pragma once
#include "core/Dictionary.hpp"
#include "core/Vec3.hpp"
#include "voidfraction/VoidFractionModel.hpp"

namespace granair {

class DividedVoidFraction : public VoidFractionModel {
public:
    static constexpr const char* typeName = "divided";
    static constexpr int defaultShells = 1;
    static constexpr int maxShells = 4;

    // Throws ParameterError (core/Registry.hpp) naming `shells`.
    explicit DividedVoidFraction(long shells = defaultShells);
    // Reads `shells` (optional); through the registry errors name the file and key.
    static std::unique_ptr<VoidFractionModel> fromDictionary(const Dictionary& dict);

    std::string name() const override { return typeName; }
    void stencil(const CellLocator& mesh, const ParticleState& p, int centreCell,
                 std::vector<CellWeight>& out) const override;

    // Point offsets in units of the radius; points()[0] is the centre. Each
    // point stands for 1/nPoints() of the particle volume.
    const std::vector<Vec3>& points() const { return points_; }
    int nPoints() const { return static_cast<int>(points_.size()); }
    int shells() const { return shells_; }

private:
    int shells_;
    std::vector<Vec3> points_;
};

}  // namespace granair
