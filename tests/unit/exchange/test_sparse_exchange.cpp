// sparseExchange (NBX) on one rank: messages to oneself and no messages at all.
// The many-rank behaviour is tested in tests/mpi/exchange/.
#include <catch2/catch.hpp>
#include <cstring>

#include "core/Error.hpp"
#include "exchange/SparseExchange.hpp"

using namespace granair;

TEST_CASE("sparse exchange on one rank: self message, empty round, duplicate destination", "[exchange]") {
    SparseInbox inbox;
    const std::vector<double> payload{1.5, -2.0, 3.25};
    sparseExchange(MPI_COMM_SELF, 7, {{0, payload.data(), payload.size() * sizeof(double)}}, inbox);
    REQUIRE(inbox.messages.size() == 1);
    CHECK(inbox.messages[0].rank == 0);
    REQUIRE(inbox.messages[0].bytes == payload.size() * sizeof(double));
    std::vector<double> got(payload.size());
    std::memcpy(got.data(), inbox.bytes.data() + inbox.messages[0].offset, inbox.messages[0].bytes);
    CHECK(got == payload);

    sparseExchange(MPI_COMM_SELF, 8, {}, inbox);
    CHECK(inbox.messages.empty());
    CHECK(inbox.bytes.empty());

    const char c = 'x';
    const std::vector<SparseSend> twice{{0, &c, 1}, {0, &c, 1}};
    CHECK_THROWS_AS(sparseExchange(MPI_COMM_SELF, 9, twice, inbox), Error);
}
