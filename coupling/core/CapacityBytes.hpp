// CapacityBytes.hpp: bytes a vector holds (its capacity, i.e. its high-water
// mark), for the memory reports of the coupling layer's buffers.
#pragma once
#include <cstddef>
#include <vector>

namespace granair {

template <class T>
std::size_t capacityBytes(const std::vector<T>& v) {
    return v.capacity() * sizeof(T);
}

}  // namespace granair
