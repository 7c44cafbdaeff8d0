// CapacityBytes.hpp: bytes a vector holds (its capacity, i.e. its high-water
// mark), for the memory reports of the coupling layer's buffers, and growing
// one exactly.
#pragma once
#include <cstddef>
#include <vector>

namespace granair {

template <class T>
std::size_t capacityBytes(const std::vector<T>& v) {
    return v.capacity() * sizeof(T);
}

// Room for n elements, allocated exactly when it must grow (push_back's
// doubling would leave up to twice the bytes needed as the high-water mark).
template <class T>
void reserveAtLeast(std::vector<T>& v, std::size_t n) {
    if (v.capacity() < n) v.reserve(n);
}

}  // namespace granair
