// RecordMessage.hpp: the wire format of the particle records ParticleExchange
// sends from a DEM owner to a candidate CFD owner.
//
// One message = the records, then a trailer:
//     record[0] .. record[n-1]          64 bytes each (see below)
//     multi[0] .. multi[m-1]            int64: positions (0-based, ascending) of
//                                       the records also sent to other ranks
//     m                                 int64
// A record is {int64 id; double x[3], v[3], radius} as raw bytes: the same
// binary runs on every rank (homogeneous cluster), so no conversion is done.
// The trailer comes last so records can be appended while the multi list is
// still growing, with no copy before sending.
#pragma once
#include <cstdint>
#include <cstring>
#include <vector>

#include "core/Particle.hpp"

namespace granair {
namespace record {

constexpr std::size_t kRecordBytes = 8 * sizeof(double);
static_assert(sizeof(std::int64_t) == sizeof(double), "records are 8-byte words");

// Append one particle to a message under construction.
inline void append(std::vector<char>& message, const ParticleState& p) {
    double words[8];
    std::memcpy(&words[0], &p.id, sizeof(double));
    for (int a = 0; a < 3; ++a) {
        words[1 + a] = p.x[a];
        words[4 + a] = p.v[a];
    }
    words[7] = p.radius;
    const std::size_t at = message.size();
    message.resize(at + kRecordBytes);
    std::memcpy(message.data() + at, words, kRecordBytes);
}

// Finish a message: append the multi-candidate positions and their count.
inline void appendTrailer(std::vector<char>& message, const std::vector<std::int64_t>& multi) {
    const std::int64_t m = static_cast<std::int64_t>(multi.size());
    const std::size_t at = message.size();
    message.resize(at + (multi.size() + 1) * sizeof(std::int64_t));
    if (m > 0) std::memcpy(message.data() + at, multi.data(), multi.size() * sizeof(std::int64_t));
    std::memcpy(message.data() + message.size() - sizeof(std::int64_t), &m, sizeof(m));
}

// Read the k-th record of a message starting at `records`.
inline ParticleState read(const char* records, std::size_t k) {
    double words[8];
    std::memcpy(words, records + k * kRecordBytes, kRecordBytes);
    ParticleState p;
    std::memcpy(&p.id, &words[0], sizeof(double));
    p.x = Vec3(words[1], words[2], words[3]);
    p.v = Vec3(words[4], words[5], words[6]);
    p.radius = words[7];
    return p;
}

// Layout of a received message of `bytes` bytes. Returns false when the
// sizes are inconsistent (never for a message written by append/appendTrailer).
struct Layout {
    std::size_t nRecords = 0;
    std::size_t nMulti = 0;
    const char* multi = nullptr;  // nMulti int64, read with multiAt()
};

inline bool parse(const char* message, std::size_t bytes, Layout& layout) {
    if (bytes < sizeof(std::int64_t)) return false;
    std::int64_t m = 0;
    std::memcpy(&m, message + bytes - sizeof(std::int64_t), sizeof(m));
    if (m < 0 || static_cast<std::size_t>(m) >= bytes / sizeof(std::int64_t)) return false;
    const std::size_t trailer = (static_cast<std::size_t>(m) + 1) * sizeof(std::int64_t);
    if ((bytes - trailer) % kRecordBytes != 0) return false;
    layout.nRecords = (bytes - trailer) / kRecordBytes;
    layout.nMulti = static_cast<std::size_t>(m);
    layout.multi = message + layout.nRecords * kRecordBytes;
    return layout.nMulti <= layout.nRecords;
}

inline std::int64_t multiAt(const Layout& layout, std::size_t i) {
    std::int64_t pos = 0;
    std::memcpy(&pos, layout.multi + i * sizeof(std::int64_t), sizeof(pos));
    return pos;
}

}  // namespace record
}  // namespace granair
