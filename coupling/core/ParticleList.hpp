// ParticleList.hpp: a rank's DEM particles as the coupling layer reads them.
//
// By index and by value, so that the list can be a view of the DEM's own
// arrays (LiggghtsDriver::particles(): no per-particle copy in the coupling
// layer, which would be 64 bytes of its 150-byte budget per particle) as
// well as a vector (ParticleVector: tests, benchmarks, the particle VTK).
// The exchange reads a particle a few times per coupling step; a virtual call
// costs a few ns of the ~75 ns per particle and coupling step the mapping and
// exchange take (bench/coupled, 1e5 particles, one rank).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/Particle.hpp"

namespace granair {

class ParticleList {
public:
    virtual ~ParticleList() = default;
    virtual std::size_t size() const = 0;
    virtual ParticleState operator[](std::size_t i) const = 0;
    // One field of particle i, for the passes that need no more: the whole
    // state is 64 bytes read from four of the DEM's arrays (and a position
    // check), and each coupling step reads every particle several times (a
    // 1e5-particle rank streams ~7 MB per full pass, past the caches).
    virtual Vec3 position(std::size_t i) const { return (*this)[i].x; }
    virtual std::int64_t id(std::size_t i) const { return (*this)[i].id; }
    virtual double radius(std::size_t i) const { return (*this)[i].radius; }
    virtual Vec3 velocity(std::size_t i) const { return (*this)[i].v; }
};

// A vector seen as a ParticleList (the vector must outlive the view's use).
class ParticleVector final : public ParticleList {
public:
    explicit ParticleVector(const std::vector<ParticleState>* v = nullptr) : v_(v) {}
    void reset(const std::vector<ParticleState>* v) { v_ = v; }
    std::size_t size() const override { return v_ ? v_->size() : 0; }
    ParticleState operator[](std::size_t i) const override { return (*v_)[i]; }
    Vec3 position(std::size_t i) const override { return (*v_)[i].x; }
    std::int64_t id(std::size_t i) const override { return (*v_)[i].id; }
    double radius(std::size_t i) const override { return (*v_)[i].radius; }
    Vec3 velocity(std::size_t i) const override { return (*v_)[i].v; }

private:
    const std::vector<ParticleState>* v_;
};

}  // namespace granair
