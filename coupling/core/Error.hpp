// Error.hpp: the exceptions the coupling layer throws.
//
// InputError: the user's input is wrong (file, key, value, particle). Its
// message always names where the bad value came from and what was expected,
// so the top level only has to print it.
#pragma once
#include <sstream>
#include <stdexcept>
#include <string>

namespace granair {

class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class InputError : public Error {
public:
    using Error::Error;
};

// CollectiveError: raised on every rank together with the same message (see
// Collective.hpp), so the job can end cleanly instead of aborting.
class CollectiveError : public InputError {
public:
    using InputError::InputError;
};

// Build a message from streamable parts: fail<InputError>("file ", f, ": key ", k).
template <class E = Error, class... Parts>
[[noreturn]] void fail(const Parts&... parts) {
    std::ostringstream os;
    os.precision(10);
    (os << ... << parts);
    throw E(os.str());
}

}  // namespace granair
