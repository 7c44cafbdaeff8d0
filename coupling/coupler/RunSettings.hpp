// RunSettings.hpp: what a coupled run reads from constant/couplingProperties
// besides the coupling itself (CouplingSettings): the DEM script, the
// discharge accounting, particle output and log options.
//
//   dem       { script dem/in.liggghts; restartScript dem/in.liggghts; }
//   discharge { outletZ 0; sinkZ -0.05; massFlowWindow 0.1; depthScale 1; }
//   output    { vtkInterval 0.01; }     // particles for ParaView [s]
//   airSolverLog off;                   // OpenFOAM's solver lines
// (docs/case-format.md has every key.)
#pragma once
#include <optional>
#include <string>

#include "core/Dictionary.hpp"

namespace granair {

struct DischargeSettings {
    double outletZ = 0;         // [m] particles below it count as discharged, once
    double sinkZ = 0;           // [m] particles at or below it are deleted (default outletZ)
    double massFlowWindow = 0;  // [s] sliding window of the mass flow rate
    double depthScale = 1;      // multiplies mass and mass flow (thin slice -> full depth)
};

struct RunSettings {
    std::string demScript = "dem/in.liggghts";  // relative to the case
    std::string demRestartScript;               // for a restart; default demScript
    std::optional<DischargeSettings> discharge;
    double vtkInterval = 0;  // [s] of simulated time between particle outputs; 0: none
    bool airSolverLog = false;

    static RunSettings read(const Dictionary& dict);
};

}  // namespace granair
