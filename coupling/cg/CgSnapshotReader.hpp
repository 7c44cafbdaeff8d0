// CgSnapshotReader.hpp: LIGGGHTS dumps -> CgSnapshot, one time step at a time.
//
// Inputs (the dumps dem-side/liggghts/cg-dumps.liggghts writes):
//  - particles, `dump custom`: columns id, x y z (or xu yu zu), vx vy vz,
//    radius, mass; omegax omegay omegaz optional (spin field);
//  - pair contacts, `compute pair/gran/local` + `dump local`: the compute's
//    keywords are given as `pairLayout` (default "pos id force"); LIGGGHTS
//    3.8 writes them in a fixed order whatever the order on its line (pos 6,
//    vel 6, id 3, force 3, force_normal 3, force_tangential 3, torque 3,
//    torque_normal 3, torque_tangential 3, contactArea 1, delta 1, heatFlux 1,
//    contactPoint 3, ms_id 2). `force` is the force on the first particle
//    from the second; positions come from `pos` or, without it, from the
//    particle dump by id. Each contact is listed once; the branch vector is
//    taken as the minimum image across periodic directions;
//  - mesh-wall contacts, `compute wall/gran/local` + `dump local`, layout
//    `wallLayout` (default "pos id force"): `pos` holds the contact point,
//    then the particle centre; `force` is the wall's force on the particle.
//    LIGGGHTS 3.8 reports mesh walls only (of the last `fix wall/gran ...
//    mesh` in the script) and fills no `contactPoint` for walls;
//  - primitive plane walls (`fix wall/gran ... primitive ... xplane X
//    store_force yes`): the per-particle wall force the fix stores, dumped as
//    f_force_<fixID>[1..3] in the particle dump; the contact point is the
//    centre projected on the plane.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "cg/CgSnapshot.hpp"
#include "cg/LiggghtsDump.hpp"

namespace granair {

struct CgPlaneWall {
    std::string fix;  // the fix ID: columns f_force_<fix>[1..3]
    int axis = 2;     // 0, 1, 2 for an xplane, yplane, zplane
    double position = 0.0;  // [m]
};

struct CgReadOptions {
    std::string particles;  // file or glob pattern (required)
    std::string pairs;      // optional
    std::string walls;      // optional
    std::string pairLayout = "pos id force";
    std::string wallLayout = "pos id force";
    std::vector<CgPlaneWall> planeWalls;
    double dt = 0.0;  // DEM time step [s]; time = step * dt (0: time = step)
};

// Column offsets of a pair/gran/local or wall/gran/local layout.
struct CgLocalLayout {
    int width = 0;
    int pos = -1, id = -1, force = -1;
    // keywords: as on the compute line; where: for messages.
    static CgLocalLayout parse(const std::string& keywords, const std::string& where);
};

class CgSnapshotReader {
public:
    explicit CgSnapshotReader(const CgReadOptions& opt);
    // The particle dump's time steps (each must also be in the contact dumps).
    std::vector<long> steps() const { return particles_->steps(); }
    CgSnapshot read(long step) const;
    double timeOf(long step) const { return opt_.dt > 0.0 ? step * opt_.dt : double(step); }

private:
    CgReadOptions opt_;
    CgLocalLayout pairLayout_, wallLayout_;
    std::unique_ptr<LiggghtsDumpSeries> particles_, pairs_, walls_;
};

}  // namespace granair
