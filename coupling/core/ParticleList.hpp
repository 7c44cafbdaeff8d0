// ParticleList.hpp: a rank's DEM particles as the coupling layer reads them.
//
// By index and by value, so that the list can be a view of the DEM's own
// arrays (LiggghtsDriver::particles(): no per-particle copy in the coupling
// layer, which would be 64 bytes of its 150-byte budget per particle) as
// well as a vector (ParticleVector: tests, benchmarks, the particle VTK).
// The exchange reads a particle a few times per coupling step; a virtual call
// costs a few ns of the ~250 ns per particle the mapping and exchange take.
#pragma once
#include <cstddef>
#include <vector>

#include "core/Particle.hpp"

namespace granair {

class ParticleList {
public:
    virtual ~ParticleList() = default;
    virtual std::size_t size() const = 0;
    virtual ParticleState operator[](std::size_t i) const = 0;
};

// A vector seen as a ParticleList (the vector must outlive the view's use).
class ParticleVector final : public ParticleList {
public:
    explicit ParticleVector(const std::vector<ParticleState>* v = nullptr) : v_(v) {}
    void reset(const std::vector<ParticleState>* v) { v_ = v; }
    std::size_t size() const override { return v_ ? v_->size() : 0; }
    ParticleState operator[](std::size_t i) const override { return (*v_)[i]; }

private:
    const std::vector<ParticleState>* v_;
};

}  // namespace granair
