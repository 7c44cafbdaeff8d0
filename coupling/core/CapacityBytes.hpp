// CapacityBytes.hpp: bytes a vector holds (its capacity, i.e. its high-water
// mark), for the memory reports of the coupling layer's buffers, and growing
// one exactly.
#pragma once
#include <algorithm>
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

// Room for n elements, growing by an eighth when it must grow (a vector
// filled by push_back doubles: its high-water mark, which the memory report
// counts and the process keeps, is up to twice what it ever held). Amortised
// O(1) per element still, at about eight copies per element over all growths.
template <class T>
void reserveGrowing(std::vector<T>& v, std::size_t n) {
    if (v.capacity() < n) v.reserve(std::max(n, v.capacity() + v.capacity() / 8));
}

}  // namespace granair
