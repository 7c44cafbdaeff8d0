// CgWriters.hpp: write CG fields as CSV, VTK image data (.vti, ParaView) and HDF5.
//
//   CSV:  one row per grid point: the resolved coordinates (x y z, or r z,
//         none for O), then every field, tensors as name_xx name_xy ...
//         (RZ: name_rr name_rt ... with t = theta), NaN where undefined.
//   VTI:  XML ImageData, appended raw Float64, point data; vectors and
//         tensors as 3- and 9-component arrays (ParaView shows tensors);
//         RZ grids lie in the x-z plane with x = r; averaged directions are
//         one point thick at the window's centre.
//   HDF5: attributes describing the average (coordinates, kernel, widths,
//         snapshots, time average), coordinate datasets per resolved axis,
//         and one dataset per field shaped (resolved counts, slowest first
//         [, components]) with its unit as attribute.
// Every writer throws InputError naming the file when it cannot write it.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "cg/CgFields.hpp"
#include "cg/CgGrid.hpp"

namespace granair {

// What the files say about how the fields were made.
using CgAttributes = std::vector<std::pair<std::string, std::string>>;

void writeCgCsv(const std::string& path, const CgGrid& grid, const std::vector<CgField>& fields);
void writeCgVti(const std::string& path, const CgGrid& grid, const std::vector<CgField>& fields);
void writeCgHdf5(const std::string& path, const CgGrid& grid, const std::vector<CgField>& fields,
                 const CgAttributes& attributes);

// ParaView collection: (time, file name relative to the .pvd) pairs.
void writeCgPvd(const std::string& path, const std::vector<std::pair<double, std::string>>& entries);

// One row per snapshot of the fields at one point (coordinates O: the
// window average): time, step, fields.
class CgSeriesCsv {
public:
    CgSeriesCsv(const std::string& path, const CgGrid& grid);
    // fields at the grid's first point
    void append(double time, long step, const std::vector<CgField>& fields);

private:
    std::string path_;
    CgGrid grid_;
    bool header_ = false;
};

// CSV/HDF5 column labels of a field's components: name, name_x ..., name_xx ...
std::vector<std::string> cgColumnNames(const CgField& f, const CgGrid& grid);

}  // namespace granair
