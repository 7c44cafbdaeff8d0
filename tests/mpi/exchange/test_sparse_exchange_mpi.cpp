// sparseExchange (NBX) across ranks: many back-to-back rounds of random
// sparse patterns (including empty messages and messages to oneself) on the
// two alternating tags; each rank receives exactly the messages addressed to
// it in that round, sorted by source, with their contents intact.
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>

#include "exchange/SparseExchange.hpp"

using namespace granair;

namespace {

// Deterministic pseudo-random pattern every rank can evaluate for any pair.
std::uint64_t mix(std::uint64_t a, std::uint64_t b, std::uint64_t c) {
    std::uint64_t h = 0x9E3779B97F4A7C15ull ^ (a * 0xBF58476D1CE4E5B9ull) ^ (b * 0x94D049BB133111EBull) ^
                      (c + 0x632BE59BD9B4E019ull);
    h ^= h >> 31;
    h *= 0xD6E8FEB86659FD93ull;
    h ^= h >> 32;
    return h;
}
bool sends(int round, int from, int to) { return mix(round, from, to) % 3 == 0; }
std::size_t length(int round, int from, int to) { return mix(to, round, from) % 40; }  // 0 .. 39 words
std::int64_t word(int round, int from, int to, std::size_t k) {
    return ((static_cast<std::int64_t>(round) * 1000 + from) * 1000 + to) * 1000 +
           static_cast<std::int64_t>(k);
}

}  // namespace

TEST_CASE("NBX delivers random sparse patterns round after round", "[exchange][mpi]") {
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    MPI_Comm comm;
    MPI_Comm_dup(MPI_COMM_WORLD, &comm);

    SparseInbox inbox;
    std::vector<std::vector<std::int64_t>> payloads;
    int wrongSources = 0, wrongPayloads = 0;
    long received = 0;
    for (int round = 0; round < 60; ++round) {
        payloads.clear();
        std::vector<SparseSend> out;
        for (int to = 0; to < size; ++to) {
            if (!sends(round, rank, to)) continue;
            std::vector<std::int64_t> w(length(round, rank, to));
            for (std::size_t k = 0; k < w.size(); ++k) w[k] = word(round, rank, to, k);
            payloads.push_back(std::move(w));
        }
        int slot = 0;
        for (int to = 0; to < size; ++to)
            if (sends(round, rank, to)) {
                out.push_back({to, payloads[slot].data(), payloads[slot].size() * sizeof(std::int64_t)});
                ++slot;
            }
        // The two tags alternate between consecutive rounds (SparseExchange.hpp).
        sparseExchange(comm, 300 + round % 2, out, inbox);

        std::vector<int> expected;
        for (int from = 0; from < size; ++from)
            if (sends(round, from, rank)) expected.push_back(from);
        std::vector<int> got;
        for (const auto& m : inbox.messages) got.push_back(m.rank);
        wrongSources += got != expected;
        for (const auto& m : inbox.messages) {
            ++received;
            const std::size_t n = length(round, m.rank, rank);
            if (m.bytes != n * sizeof(std::int64_t) || m.offset % 8 != 0) {
                ++wrongPayloads;
                continue;
            }
            for (std::size_t k = 0; k < n; ++k) {
                std::int64_t v;
                std::memcpy(&v, inbox.bytes.data() + m.offset + k * sizeof(v), sizeof(v));
                wrongPayloads += v != word(round, m.rank, rank, k);
            }
        }
    }
    CHECK(wrongSources == 0);
    CHECK(wrongPayloads == 0);
    CHECK(received > 0);
    MPI_Comm_free(&comm);
}
