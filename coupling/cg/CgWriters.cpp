// CgWriters.cpp: see CgWriters.hpp.
#include "cg/CgWriters.hpp"

#include <hdf5.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>

#include "core/Error.hpp"
#include "output/FormatExact.hpp"
#include "output/Hdf5Util.hpp"

namespace granair {

namespace {

struct FileCloser {
    void operator()(std::FILE* f) const {
        if (f) std::fclose(f);
    }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

File openOut(const std::string& path, const char* what) {
    File f(std::fopen(path.c_str(), "wb"));
    if (!f) fail<InputError>("cannot write ", what, " '", path, "' (", std::strerror(errno), ")");
    return f;
}

void closeOut(File& f, const std::string& path, const char* what) {
    const bool bad = std::ferror(f.get()) != 0;
    const int rc = std::fclose(f.release());
    if (bad || rc != 0) fail<InputError>("error writing ", what, " '", path, "' (disk full?)");
}

void putNumber(std::FILE* f, double v) {
    if (std::isnan(v)) std::fputs("nan", f);
    else std::fprintf(f, "%.12g", v);
}

std::vector<int> resolvedAxes(const CgGrid& g) {
    std::vector<int> a;
    for (int i = 0; i < 3; ++i)
        if (g.resolved(i)) a.push_back(i);
    return a;
}

}  // namespace

std::vector<std::string> cgColumnNames(const CgField& f, const CgGrid& grid) {
    const auto c = grid.componentNames();
    std::vector<std::string> names;
    if (f.components == 1) names.push_back(f.name);
    else if (f.components == 3)
        for (int a = 0; a < 3; ++a) names.push_back(f.name + "_" + c[a]);
    else
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) names.push_back(f.name + "_" + c[a] + c[b]);
    return names;
}

void writeCgCsv(const std::string& path, const CgGrid& grid, const std::vector<CgField>& fields) {
    File f = openOut(path, "CG CSV file");
    const auto axes = resolvedAxes(grid);
    const auto comp = grid.componentNames();
    bool first = true;
    auto sep = [&]() {
        if (!first) std::fputc(',', f.get());
        first = false;
    };
    for (int a : axes) sep(), std::fputs(comp[a].c_str(), f.get());
    for (const auto& fl : fields)
        for (const auto& n : cgColumnNames(fl, grid)) sep(), std::fputs(n.c_str(), f.get());
    std::fputc('\n', f.get());
    for (std::size_t p = 0; p < grid.size(); ++p) {
        first = true;
        const Vec3 x = grid.point(p);
        for (int a : axes) sep(), putNumber(f.get(), x[a]);
        for (const auto& fl : fields)
            for (int c = 0; c < fl.components; ++c) sep(), putNumber(f.get(), fl.values[p * fl.components + c]);
        std::fputc('\n', f.get());
    }
    closeOut(f, path, "CG CSV file");
}

void writeCgVti(const std::string& path, const CgGrid& grid, const std::vector<CgField>& fields) {
    File f = openOut(path, "CG VTK file");
    const int nx = grid.count(0), ny = grid.count(1), nz = grid.count(2);
    const Vec3 o = grid.point(0);
    double h[3];
    for (int a = 0; a < 3; ++a) h[a] = grid.count(a) > 1 ? grid.spacing(a) : 1.0;
    std::fprintf(f.get(),
                 "<?xml version=\"1.0\"?>\n"
                 "<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
                 "  <ImageData WholeExtent=\"0 %d 0 %d 0 %d\" Origin=\"%.17g %.17g %.17g\" Spacing=\"%.17g %.17g %.17g\">\n"
                 "    <Piece Extent=\"0 %d 0 %d 0 %d\">\n      <PointData>\n",
                 nx - 1, ny - 1, nz - 1, o[0], o[1], o[2], h[0], h[1], h[2], nx - 1, ny - 1, nz - 1);
    std::uint64_t offset = 0;
    for (const auto& fl : fields) {
        std::fprintf(f.get(),
                     "        <DataArray type=\"Float64\" Name=\"%s\" NumberOfComponents=\"%d\" format=\"appended\" "
                     "offset=\"%llu\"/>\n",
                     fl.name.c_str(), fl.components, (unsigned long long)offset);
        offset += sizeof(std::uint64_t) + fl.values.size() * sizeof(double);
    }
    std::fputs("      </PointData>\n    </Piece>\n  </ImageData>\n  <AppendedData encoding=\"raw\">\n_", f.get());
    static_assert(sizeof(double) == 8, "Float64");
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
#error "writeCgVti writes little-endian data: port the byte order first"
#endif
    for (const auto& fl : fields) {
        const std::uint64_t bytes = fl.values.size() * sizeof(double);
        std::fwrite(&bytes, sizeof bytes, 1, f.get());
        std::fwrite(fl.values.data(), sizeof(double), fl.values.size(), f.get());
    }
    std::fputs("\n  </AppendedData>\n</VTKFile>\n", f.get());
    closeOut(f, path, "CG VTK file");
}

void writeCgPvd(const std::string& path, const std::vector<std::pair<double, std::string>>& entries) {
    File f = openOut(path, "ParaView collection");
    std::fputs("<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  <Collection>\n", f.get());
    for (const auto& e : entries)
        std::fprintf(f.get(), "    <DataSet timestep=\"%s\" part=\"0\" file=\"%s\"/>\n", formatExact(e.first).c_str(),
                     e.second.c_str());
    std::fputs("  </Collection>\n</VTKFile>\n", f.get());
    closeOut(f, path, "ParaView collection");
}

namespace {

bool dataset(hid_t file, const std::string& name, const std::vector<hsize_t>& dims, const double* values,
             const std::string& unit) {
    const hid_t space = H5Screate_simple(int(dims.size()), dims.data(), nullptr);
    if (space < 0) return false;
    const hid_t ds = H5Dcreate2(file, name.c_str(), H5T_IEEE_F64LE, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    bool ok = ds >= 0 && H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values) >= 0;
    if (ok && !unit.empty()) ok = writeStringAttribute(ds, "unit", unit);
    if (ds >= 0) H5Dclose(ds);
    H5Sclose(space);
    return ok;
}

}  // namespace

void writeCgHdf5(const std::string& path, const CgGrid& grid, const std::vector<CgField>& fields,
                 const CgAttributes& attributes) {
    QuietHdf5 quiet;
    const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    if (file < 0) fail<InputError>("cannot write CG HDF5 file '", path, "'");
    bool ok = true;
    for (const auto& a : attributes) ok = ok && writeStringAttribute(file, a.first.c_str(), a.second);
    const auto axes = resolvedAxes(grid);
    const auto comp = grid.componentNames();
    std::vector<hsize_t> shape;
    for (auto it = axes.rbegin(); it != axes.rend(); ++it) shape.push_back(hsize_t(grid.count(*it)));
    if (shape.empty()) shape.push_back(1);
    for (int a : axes) {
        std::vector<double> x(grid.count(a));
        for (int i = 0; i < grid.count(a); ++i) x[i] = grid.coord(a, i);
        ok = ok && dataset(file, comp[a], {hsize_t(x.size())}, x.data(), "m");
    }
    for (const auto& fl : fields) {
        auto dims = shape;
        if (fl.components > 1) dims.push_back(hsize_t(fl.components));
        ok = ok && dataset(file, fl.name, dims, fl.values.data(), fl.unit);
    }
    const bool closed = H5Fclose(file) >= 0;
    if (!ok || !closed) fail<InputError>("error writing CG HDF5 file '", path, "'");
}

CgSeriesCsv::CgSeriesCsv(const std::string& path, const CgGrid& grid) : path_(path), grid_(grid) {
    File f = openOut(path, "CG series CSV");
    closeOut(f, path, "CG series CSV");
}

void CgSeriesCsv::append(double time, long step, const std::vector<CgField>& fields) {
    File f(std::fopen(path_.c_str(), "ab"));
    if (!f) fail<InputError>("cannot append to CG series CSV '", path_, "' (", std::strerror(errno), ")");
    if (!header_) {
        std::fputs("time,step", f.get());
        for (const auto& fl : fields)
            for (const auto& n : cgColumnNames(fl, grid_)) std::fprintf(f.get(), ",%s", n.c_str());
        std::fputc('\n', f.get());
        header_ = true;
    }
    std::fprintf(f.get(), "%s,%ld", formatExact(time).c_str(), step);
    for (const auto& fl : fields)
        for (int c = 0; c < fl.components; ++c) std::fputc(',', f.get()), putNumber(f.get(), fl.values[c]);
    std::fputc('\n', f.get());
    closeOut(f, path_, "CG series CSV");
}

}  // namespace granair
