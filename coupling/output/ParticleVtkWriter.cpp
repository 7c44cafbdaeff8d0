// ParticleVtkWriter.cpp: see ParticleVtkWriter.hpp.
//
// Each piece is streamed straight to its file: the XML header (whose array
// offsets follow from the particle count alone), then the appended arrays
// packed a block of points at a time, so writing needs no buffer of the size
// of the particle set. Two collective checks per output: one before any file
// is touched (argument errors), one after the pieces and the index are
// written (I/O errors; it is also the barrier after which rank 0 may add the
// output to the collection, so ParaView never sees an entry whose pieces are
// still being written).
#include "output/ParticleVtkWriter.hpp"

#include <sys/stat.h>
#include <sys/types.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <system_error>

#include "core/Collective.hpp"
#include "core/Error.hpp"
#include "output/FormatExact.hpp"

namespace granair {

namespace {

const char* byteOrder() {
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
    return "BigEndian";
#else
    return "LittleEndian";
#endif
}

// The XML header shared by .vtp and .pvtp (UInt64 block headers need file
// format version 1.0).
std::string vtkFileOpen(const char* type) {
    std::string s = "<?xml version=\"1.0\"?>\n<VTKFile type=\"";
    s += type;
    s += "\" version=\"1.0\" byte_order=\"";
    s += byteOrder();
    s += "\" header_type=\"UInt64\">\n";
    return s;
}


// One point-data or cell array of a piece.
struct ArraySpec {
    const char* name;  // nullptr: the Points array (VTK gives it no name)
    const char* type;
    int components;
    std::size_t valueBytes;
};

constexpr ArraySpec kId{"id", "Int64", 1, 8};
constexpr ArraySpec kRadius{"radius", "Float64", 1, 8};
constexpr ArraySpec kVelocity{"velocity", "Float64", 3, 8};
constexpr ArraySpec kForce{"fluidForce", "Float64", 3, 8};
constexpr ArraySpec kPoints{nullptr, "Float64", 3, 8};
constexpr ArraySpec kConnectivity{"connectivity", "Int64", 1, 8};
constexpr ArraySpec kOffsets{"offsets", "Int64", 1, 8};

// The point-data arrays, in file order (the .pvtp lists the same).
constexpr const ArraySpec* kPointData[] = {&kId, &kRadius, &kVelocity, &kForce};

void declareArray(std::ostringstream& os, const char* indent, const ArraySpec& a, std::uint64_t offset) {
    os << indent << "<DataArray type=\"" << a.type << '"';
    if (a.name) os << " Name=\"" << a.name << '"';
    os << " NumberOfComponents=\"" << a.components << "\" format=\"appended\" offset=\"" << offset
       << "\"/>\n";
}

// Streams one appended array: the UInt64 byte count, then the values of
// points [0, n), `fill(i, out)` writing the components of point i.
template <class T, class Fill>
bool streamArray(std::FILE* f, std::size_t n, int components, Fill fill) {
    const std::uint64_t bytes = static_cast<std::uint64_t>(n) * components * sizeof(T);
    if (std::fwrite(&bytes, sizeof bytes, 1, f) != 1) return false;
    constexpr std::size_t block = 1024;
    T chunk[3 * block];
    for (std::size_t first = 0; first < n; first += block) {
        const std::size_t m = std::min(block, n - first);
        for (std::size_t i = 0; i < m; ++i) fill(first + i, chunk + components * i);
        if (std::fwrite(chunk, sizeof(T), m * components, f) != m * components) return false;
    }
    return true;
}

void put3(const Vec3& v, double* out) {
    out[0] = v[0];
    out[1] = v[1];
    out[2] = v[2];
}

// Writes `text` to path through a temporary file and a rename, so a reader
// never sees half a file. Returns "" or what went wrong.
std::string replaceFile(const std::string& path, const std::string& text) {
    const std::string tmp = path + ".tmp";
    std::FILE* f = std::fopen(tmp.c_str(), "w");
    if (!f) return "cannot create '" + tmp + "': " + std::strerror(errno);
    const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
    if (std::fclose(f) != 0 || !ok) return "cannot write '" + tmp + "': " + std::strerror(errno);
    if (std::rename(tmp.c_str(), path.c_str()) != 0)
        return "cannot rename '" + tmp + "' to '" + path + "': " + std::strerror(errno);
    return "";
}

}  // namespace

ParticleVtkWriter::ParticleVtkWriter(MPI_Comm comm, std::string directory)
    : comm_(comm), directory_(std::move(directory)) {
    MPI_Comm_rank(comm_, &rank_);
    MPI_Comm_size(comm_, &size_);
    std::string problem;
    if (rank_ == 0) {
        std::error_code ec;
        std::filesystem::create_directories(directory_, ec);
        if (ec || !std::filesystem::is_directory(directory_))
            problem = "cannot create the particle output directory '" + directory_ +
                      "': " + (ec ? ec.message() : std::string("not a directory"));
    }
    raiseIfAny(comm_, problem);
}

std::string ParticleVtkWriter::indexName(int output) {
    return "particles_" + std::to_string(output) + ".pvtp";
}

std::string ParticleVtkWriter::pieceName(int output, int rank) {
    return "particles_" + std::to_string(output) + "/rank" + std::to_string(rank) + ".vtp";
}

void ParticleVtkWriter::write(double time, const std::vector<ParticleState>& particles,
                              const std::vector<Vec3>& fluidForces) {
    static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 is three contiguous doubles");
    write(time, particles, fluidForces.empty() ? nullptr : fluidForces.front().data(), fluidForces.size());
}

void ParticleVtkWriter::write(double time, const std::vector<ParticleState>& particles,
                              const double* fluidForces, std::size_t nForces) {
    write(time, ParticleVector(&particles), fluidForces, nForces);
}

void ParticleVtkWriter::write(double time, const ParticleList& particles, const double* fluidForces,
                              std::size_t nForces) {
    std::ostringstream bad;
    bad.precision(17);
    if (fluidForces && nForces != particles.size())
        bad << "particle output: " << nForces << " fluid forces for " << particles.size()
            << " particles; expected one force per particle";
    else if (!std::isfinite(time) || (!times_.empty() && !(time > times_.back())))
        bad << "particle output: time " << time << " s; expected a finite time after the last output ("
            << (times_.empty() ? 0.0 : times_.back()) << " s)";
    raiseIfAny(comm_, bad.str());

    const int output = outputs();
    std::string problem = writePiece(output, particles, fluidForces);
    if (rank_ == 0 && problem.empty()) problem = writeIndex(output);
    raiseIfAny(comm_, problem);

    times_.push_back(time);
    raiseIfAny(comm_, rank_ == 0 ? writeCollection() : std::string());
}

std::string ParticleVtkWriter::writePiece(int output, const ParticleList& particles,
                                          const double* fluidForces) const {
    // Every rank makes the folder of this output (whoever comes first wins),
    // so no rank waits for rank 0 to create it.
    const std::string folder = directory_ + "/particles_" + std::to_string(output);
    if (::mkdir(folder.c_str(), 0777) != 0 && errno != EEXIST)
        return "cannot create the particle output folder '" + folder + "': " + std::strerror(errno);
    const std::string path = directory_ + "/" + pieceName(output, rank_);

    // Header: the offset of each array follows from n alone.
    const std::size_t n = particles.size();
    std::uint64_t offset = 0;
    auto next = [&](const ArraySpec& a) {
        const std::uint64_t at = offset;
        offset += sizeof(std::uint64_t) + static_cast<std::uint64_t>(n) * a.components * a.valueBytes;
        return at;
    };
    std::ostringstream xml;
    xml << vtkFileOpen("PolyData") << "  <PolyData>\n"
        << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\"" << n
        << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
        << "      <PointData Scalars=\"radius\" Vectors=\"velocity\">\n";
    for (const ArraySpec* a : kPointData) declareArray(xml, "        ", *a, next(*a));
    xml << "      </PointData>\n      <Points>\n";
    declareArray(xml, "        ", kPoints, next(kPoints));
    xml << "      </Points>\n      <Verts>\n";
    declareArray(xml, "        ", kConnectivity, next(kConnectivity));
    declareArray(xml, "        ", kOffsets, next(kOffsets));
    xml << "      </Verts>\n    </Piece>\n  </PolyData>\n  <AppendedData encoding=\"raw\">\n   _";
    const std::string head = xml.str();

    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return "cannot create particle output file '" + path + "': " + std::strerror(errno);
    // Same order as the offsets above.
    bool ok = std::fwrite(head.data(), 1, head.size(), f) == head.size();
    ok = ok &&
         streamArray<std::int64_t>(f, n, 1, [&](std::size_t i, std::int64_t* o) { *o = particles[i].id; });
    ok = ok && streamArray<double>(f, n, 1, [&](std::size_t i, double* o) { *o = particles[i].radius; });
    ok = ok && streamArray<double>(f, n, 3, [&](std::size_t i, double* o) { put3(particles[i].v, o); });
    ok = ok && streamArray<double>(f, n, 3, [&](std::size_t i, double* o) {
             for (int d = 0; d < 3; ++d) o[d] = fluidForces ? fluidForces[3 * i + d] : 0.0;
         });
    ok = ok && streamArray<double>(f, n, 3, [&](std::size_t i, double* o) { put3(particles[i].x, o); });
    ok = ok &&
         streamArray<std::int64_t>(f, n, 1, [](std::size_t i, std::int64_t* o) { *o = std::int64_t(i); });
    ok = ok &&
         streamArray<std::int64_t>(f, n, 1, [](std::size_t i, std::int64_t* o) { *o = std::int64_t(i + 1); });
    static const char tail[] = "\n  </AppendedData>\n</VTKFile>\n";
    ok = ok && std::fwrite(tail, 1, sizeof tail - 1, f) == sizeof tail - 1;
    const int err = errno;
    if (std::fclose(f) != 0 || !ok)
        return "cannot write particle output file '" + path + "': " + std::strerror(ok ? errno : err);
    return "";
}

std::string ParticleVtkWriter::writeIndex(int output) const {
    std::ostringstream xml;
    xml << vtkFileOpen("PPolyData") << "  <PPolyData GhostLevel=\"0\">\n"
        << "    <PPointData Scalars=\"radius\" Vectors=\"velocity\">\n";
    for (const ArraySpec* a : kPointData)
        xml << "      <PDataArray type=\"" << a->type << "\" Name=\"" << a->name << "\" NumberOfComponents=\""
            << a->components << "\"/>\n";
    xml << "    </PPointData>\n    <PPoints>\n      <PDataArray type=\"" << kPoints.type
        << "\" NumberOfComponents=\"3\"/>\n    </PPoints>\n";
    for (int r = 0; r < size_; ++r) xml << "    <Piece Source=\"" << pieceName(output, r) << "\"/>\n";
    xml << "  </PPolyData>\n</VTKFile>\n";
    return replaceFile(directory_ + "/" + indexName(output), xml.str());
}

std::string ParticleVtkWriter::writeCollection() const {
    std::ostringstream xml;
    // The collection holds no binary data: the plain 0.1 header that
    // ParaView's .pvd reader has always accepted.
    xml << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\""
        << byteOrder() << "\">\n  <Collection>\n";
    for (std::size_t k = 0; k < times_.size(); ++k)
        xml << "    <DataSet timestep=\"" << formatExact(times_[k]) << "\" group=\"\" part=\"0\" file=\""
            << indexName(static_cast<int>(k)) << "\"/>\n";
    xml << "  </Collection>\n</VTKFile>\n";
    return replaceFile(collectionPath(), xml.str());
}

void ParticleVtkWriter::resume(const std::vector<double>& times) {
    for (std::size_t k = 1; k < times.size(); ++k)
        if (!(times[k] > times[k - 1]))
            fail<InputError>("particle output '", directory_, "': restart output times must increase (",
                             times[k], " after ", times[k - 1], ")");
    times_ = times;
}

}  // namespace granair
