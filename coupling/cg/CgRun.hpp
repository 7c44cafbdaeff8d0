// CgRun.hpp: what granairCG does, as a library call (the command is a thin main).
//
// Read the snapshots the time average selects, compute each one's raw CG
// fields on the grid (CoarseGrainer), sum them with the time weights, derive
// the fields (CgFields) and write them; optionally every snapshot too.
// Prints one progress line per snapshot and a summary with the mass on the
// grid against the particle mass in the window.
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

#include "cg/CgGrid.hpp"
#include "cg/CgOptions.hpp"
#include "cg/CgSnapshotReader.hpp"
#include "cg/CgTimeAverage.hpp"

namespace granair {

struct CgRunSettings {
    CgReadOptions read;
    CgCoordinates coordinates = CgCoordinates::XYZ;
    std::string kernel = "gauss";
    double width = 0.0, cutoff = 3.0, std = 0.0;  // width or std [m]; cutoff in widths (gauss)
    std::vector<long> n;                          // points per resolved axis (empty: from spacing)
    double spacing = 0.0;                         // [m] (0: the kernel's standard deviation)
    bool haveMin = false, haveMax = false;
    Vec3 min = Vec3::Zero(), max = Vec3::Zero();
    bool haveAxis = false;
    double axisX = 0.0, axisY = 0.0, rmin = 0.0, rmax = 0.0;  // RZ (rmax 0: default)
    CgTimeAverage average;
    bool every = false;
    std::string out = "cg";
    std::vector<std::string> formats{"vti", "h5", "csv"};
    int threads = 0;
    double minVolumeFraction = 1e-3;
    int azimuthalNodes = 16;

    // Checks every value; errors name the option or dictionary key.
    static CgRunSettings fromOptions(const CgOptions& o);
};

struct CgRunResult {
    std::size_t snapshots = 0;
    std::vector<std::string> files;  // written
    double gridMass = 0.0, windowMass = 0.0;  // time-averaged [kg]
};

CgRunResult runCg(const CgRunSettings& s, std::ostream& log);

// The grid for the settings, given the first snapshot's box (for defaults).
CgGrid makeCgGrid(const CgRunSettings& s, const CgDomain& domain, double kernelStd);

}  // namespace granair
