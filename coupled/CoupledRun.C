/*---------------------------------------------------------------------------*\
    granair: CoupledRun (see CoupledRun.H for the coupling step)
\*---------------------------------------------------------------------------*/
#include "coupled/CoupledRun.H"

#include "core/Error.hpp"

#include <cmath>
#include <iostream>
#include <sstream>

namespace Foam
{
namespace granair
{

using ::granair::StageTimers;

CoupledRun::CoupledRun(Time& runTime, fvMesh& mesh)
:
    runTime_(runTime),
    mesh_(mesh),
    dict_(::granair::Dictionary::fromFile(runTime.globalPath()/"constant"/"couplingProperties")),
    settings_(::granair::CouplingSettings::read(dict_))
{
    const fileName caseDir = runTime.globalPath();
    // DEM side: the case's LIGGGHTS script sets everything up, no run.
    dem_ = std::make_unique<::granair::dem::LiggghtsDriver>(MPI_COMM_WORLD, caseDir/"log");
    const std::string script = dict_.has("dem")
        ? dict_.subDict("dem").getString("script", "dem/in.liggghts") : "dem/in.liggghts";
    dem_->runFile(caseDir/script);
    if (settings_.airOn)
    {
        dem_->enableFluidForces();
    }
    if (dict_.has("discharge"))
    {
        const ::granair::Dictionary& d = dict_.subDict("discharge");
        const double zOut = d.getDouble("outletZ");
        discharge_ = std::make_unique<::granair::dem::DischargeCounter>
        (
            *dem_, zOut, d.getDouble("sinkZ", zOut)
        );
        massFlow_ = std::make_unique<::granair::MassFlowRate>(d.getDouble("massFlowWindow", 1e-6, 1e6));
        depthScale_ = d.getDouble("depthScale", 1.0);
        if (!(depthScale_ > 0))
        {
            ::granair::fail<::granair::InputError>(d.where("depthScale"), ": expected a positive factor");
        }
    }

    checkTimeSteps();
    airSolverLog_ = dict_.getBool("airSolverLog", false);

    // CFD side.
    if (settings_.airOn)
    {
        air_ = std::make_unique<AirSolver>(mesh_);
        locator_ = std::make_unique<FoamCellLocator>(mesh_);
        exchange_ = std::make_unique<::granair::ParticleExchange>(MPI_COMM_WORLD, *locator_);
        step_ = std::make_unique<::granair::CouplingStep>
        (
            settings_, *locator_, ::granair::FluidProperties{air_->rho(), air_->mu()}
        );
        monitors_ = std::make_unique<MonitorSet>(mesh_, dict_);
        mapInitialVoidFraction();
    }

    // Time series.
    std::vector<::granair::Column> cols{{"t", "s"}};
    if (discharge_)
    {
        cols.push_back({"discharged_kg", "kg"});
        cols.push_back({"mass_flow_kg_s", "kg/s"});
    }
    cols.push_back({"particles", "1"});
    if (air_)
    {
        cols.push_back({"voidfraction_min", "1"});
        cols.push_back({"voidfraction_floor_hits", "cells"});
        cols.insert(cols.end(), monitors_->columns().begin(), monitors_->columns().end());
    }
    if (Pstream::master())
    {
        mkDir(caseDir/"postProcessing");
    }
    series_ = std::make_unique<::granair::TimeSeriesWriter>
    (
        MPI_COMM_WORLD, caseDir/"postProcessing"/"timeSeries", cols
    );

    Info<< "granairFoam: " << returnReduce(mesh_.nCells(), sumOp<label>()) << " cells, "
        << dem_->nGlobal() << " particles, " << Pstream::nProcs() << " rank(s)" << nl
        << "  air " << (settings_.airOn ? "on" : "OFF (DEM-only reference run)")
        << ", coupling interval " << settings_.couplingInterval << " DEM steps of "
        << dem_->timestep() << " s";
    if (settings_.airOn)
    {
        Info<< ", drag " << settings_.drag->name().c_str()
            << ", void fraction " << settings_.voidFraction->name().c_str()
            << ", coarse graining s = " << settings_.coarseGrainingFactor;
    }
    Info<< nl << "  " << nSteps_ << " coupling steps from t = " << tStart_ << " s to "
        << runTime_.endTime().value() << " s" << nl << endl;
}


CoupledRun::~CoupledRun() = default;


void CoupledRun::checkTimeSteps()
{
    const double dtCfd = runTime_.deltaTValue();
    const double dtDem = dem_->timestep();
    const int n = settings_.couplingInterval;
    if (std::abs(dtCfd - n*dtDem) > 1e-9*dtCfd)
    {
        ::granair::fail<::granair::CollectiveError>
        (
            "time steps do not match: system/controlDict deltaT = ", dtCfd,
            " s must equal couplingInterval (", n, ", constant/couplingProperties) x the DEM ",
            "timestep (", dtDem, " s, from the LIGGGHTS script) = ", n*dtDem, " s"
        );
    }
    tStart_ = runTime_.value();
    const double span = runTime_.endTime().value() - tStart_;
    nSteps_ = label(std::llround(span/dtCfd));
    if (nSteps_ < 1 || std::abs(nSteps_*dtCfd - span) > 1e-6*dtCfd)
    {
        ::granair::fail<::granair::CollectiveError>
        (
            "system/controlDict: endTime - startTime (", span, " s) must be a positive whole ",
            "number of deltaT (", dtCfd, " s)"
        );
    }
}


void CoupledRun::mapInitialVoidFraction()
{
    // The void fraction at the start time from the particles as the DEM
    // script left them (a filled or settled bed). It becomes the old-time
    // level of the first step; without it that step's d(eps)/dt would be
    // (eps(particles) - eps(0/voidfraction))/dt: a bed present at the start
    // would appear within one step, and the air it displaces would make a
    // pressure spike that kicks the bed (a settled 9 mm bed was thrown up by
    // 0.7 mm). K and Us are set too, and recomputed at the first step.
    dem_->getParticles(particles_);
    exchange_->forward(particles_, owned_);
    const double* U = reinterpret_cast<const double*>(air_->U().primitiveField().cdata());
    step_->particlesToCells
    (
        owned_, U,
        air_->voidfraction().primitiveFieldRef().data(),
        air_->Ksl().primitiveFieldRef().data(),
        reinterpret_cast<double*>(air_->Us().primitiveFieldRef().data())
    );
    air_->voidfraction().correctBoundaryConditions();
    air_->Ksl().correctBoundaryConditions();
    air_->Us().correctBoundaryConditions();
}


void CoupledRun::coupleAir()
{
    {
        StageTimers::Scope s(timers_, StageTimers::Exchange);
        exchange_->forward(particles_, owned_);
    }
    {
        StageTimers::Scope s(timers_, StageTimers::Mapping);
        const double* U = reinterpret_cast<const double*>(air_->U().primitiveField().cdata());
        step_->particlesToCells
        (
            owned_, U,
            air_->voidfraction().primitiveFieldRef().data(),
            air_->Ksl().primitiveFieldRef().data(),
            reinterpret_cast<double*>(air_->Us().primitiveFieldRef().data())
        );
        air_->voidfraction().correctBoundaryConditions();
        air_->Ksl().correctBoundaryConditions();
        air_->Us().correctBoundaryConditions();
        floorHitsTotal_ += step_->stats().floorHits;
        minRawEps_ = std::min(minRawEps_, step_->stats().minRawVoidFraction);
    }
    {
        StageTimers::Scope s(timers_, StageTimers::CFD);
        // OpenFOAM's per-iteration solver lines would drown the progress
        // line; `airSolverLog on;` in couplingProperties keeps them.
        const int level = messageStream::level;
        if (!airSolverLog_)
        {
            messageStream::level = 0;
        }
        air_->solveStep();
        messageStream::level = level;
    }
    {
        StageTimers::Scope s(timers_, StageTimers::Mapping);
        const volVectorField gradP(fvc::grad(air_->p()));
        step_->cellsToParticles
        (
            reinterpret_cast<const double*>(air_->U().primitiveField().cdata()),
            reinterpret_cast<const double*>(gradP.primitiveField().cdata()),
            ownedForces_
        );
    }
    {
        StageTimers::Scope s(timers_, StageTimers::Exchange);
        exchange_->backward(ownedForces_, 3, demForces_);
    }
    forces_.resize(particles_.size());
    for (size_t i = 0; i < particles_.size(); ++i)
    {
        forces_[i] = ::granair::Vec3(demForces_[3*i], demForces_[3*i + 1], demForces_[3*i + 2]);
    }
    StageTimers::Scope s(timers_, StageTimers::DEM);
    dem_->setFluidForces(forces_);
}


void CoupledRun::run()
{
    ::granair::Progress progress(tStart_, runTime_.endTime().value());
    double massFlow = 0;
    for (label k = 1; k <= nSteps_; ++k)
    {
        {
            StageTimers::Scope s(timers_, StageTimers::DEM);
            dem_->advance(settings_.couplingInterval);
            if (discharge_)
            {
                discharge_->update();
            }
            dem_->getParticles(particles_);
        }
        ++runTime_;
        if (air_)
        {
            coupleAir();
        }
        {
            StageTimers::Scope s(timers_, StageTimers::Output);
            if (discharge_)
            {
                massFlow = depthScale_*massFlow_->add
                (
                    runTime_.value(), discharge_->balance().dischargedMass
                );
            }
            writeRow(runTime_.value(), massFlow);
            runTime_.write();
        }
        progress.update(runTime_.value(), long(dem_->step()), progressExtra(massFlow), std::cout, k == nSteps_);
    }
}


void CoupledRun::writeRow(double t, double massFlow)
{
    std::vector<double> row{t};
    if (discharge_)
    {
        row.push_back(depthScale_*discharge_->balance().dischargedMass);
        row.push_back(massFlow);
    }
    row.push_back(double(dem_->nGlobal()));
    if (air_)
    {
        double epsMin = gMin(air_->eps().primitiveField());
        label hits = returnReduce(label(step_->stats().floorHits), sumOp<label>());
        row.push_back(epsMin);
        row.push_back(double(hits));
        monitors_->values(*air_, row);
    }
    series_->append(row);
    lastRow_ = row;
}


std::string CoupledRun::progressExtra(double massFlow) const
{
    std::ostringstream os;
    os.precision(4);
    os << "particles " << lastRow_.at(discharge_ ? 3 : 1);
    if (discharge_)
    {
        os << " | discharged " << lastRow_[1] << " kg | W " << massFlow << " kg/s";
    }
    if (air_)
    {
        os << " | min eps " << lastRow_.at(discharge_ ? 4 : 2);
    }
    return os.str();
}


void CoupledRun::finish()
{
    series_->close();
    std::ostringstream os;
    if (discharge_)
    {
        discharge_->report(os);
    }
    if (air_)
    {
        const label hits = returnReduce(label(floorHitsTotal_), sumOp<label>());
        const scalar minEps = returnReduce(minRawEps_, minOp<scalar>());
        os  << "Void fraction floor " << settings_.voidFractionFloor << " hit in " << hits
            << " cell-steps (smallest void fraction before the floor: " << minEps << ")\n"
            << "Air continuity error (cumulative): " << air_->cumulativeContinuityError() << "\n";
    }
    timers_.report(MPI_COMM_WORLD, os);
    Info<< os.str().c_str() << endl;
}

} // namespace granair
} // namespace Foam
