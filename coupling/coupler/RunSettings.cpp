// RunSettings.cpp: see RunSettings.hpp.
#include "coupler/RunSettings.hpp"

#include <cmath>

#include "core/Error.hpp"

namespace granair {

RunSettings RunSettings::read(const Dictionary& dict) {
    RunSettings s;
    if (dict.has("dem")) {
        const Dictionary& d = dict.subDict("dem");
        s.demScript = d.getString("script", s.demScript);
        s.demRestartScript = d.getString("restartScript", s.demScript);
    } else {
        s.demRestartScript = s.demScript;
    }
    if (dict.has("discharge")) {
        const Dictionary& d = dict.subDict("discharge");
        DischargeSettings ds;
        ds.outletZ = d.getDouble("outletZ");
        ds.sinkZ = d.getDouble("sinkZ", ds.outletZ);
        if (ds.sinkZ > ds.outletZ)
            fail<InputError>(d.where("sinkZ"), " = ", ds.sinkZ, " m: expected sinkZ <= outletZ (", ds.outletZ,
                             " m; particles pass the outlet, then reach the sink)");
        ds.massFlowWindow = d.getDouble("massFlowWindow", 1e-6, 1e6);
        ds.depthScale = d.getDouble("depthScale", 1.0);
        if (!(ds.depthScale > 0))
            fail<InputError>(d.where("depthScale"), " = ", ds.depthScale, ": expected a positive factor");
        s.discharge = ds;
    }
    if (dict.has("output")) {
        const Dictionary& d = dict.subDict("output");
        s.vtkInterval = d.getDouble("vtkInterval");
        if (!(s.vtkInterval > 0))
            fail<InputError>(d.where("vtkInterval"), " = ", s.vtkInterval,
                             ": expected a positive interval of simulated time [s]");
    }
    s.airSolverLog = dict.getBool("airSolverLog", false);
    return s;
}

}  // namespace granair
