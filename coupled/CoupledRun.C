/*---------------------------------------------------------------------------*\
    granair: CoupledRun (see CoupledRun.H for the coupling step)
\*---------------------------------------------------------------------------*/
#include "coupled/CoupledRun.H"

#include "core/Error.hpp"

#include <sys/resource.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

namespace Foam
{
namespace granair
{

using ::granair::StageTimers;

namespace
{

// Peak resident memory of this process [bytes]: VmHWM of /proc/self/status
// (Linux); 0 where that file does not exist.
double peakResidentBytes()
{
    std::ifstream in("/proc/self/status");
    for (std::string line; std::getline(in, line);)
    {
        if (line.compare(0, 6, "VmHWM:") == 0)
        {
            return 1024.0*std::strtod(line.c_str() + 6, nullptr);   // given in kB
        }
    }
    return 0;
}

// CPU time (user + system) of this process so far [s].
double cpuSeconds()
{
    rusage u;
    getrusage(RUSAGE_SELF, &u);
    return u.ru_utime.tv_sec + 1e-6*u.ru_utime.tv_usec + u.ru_stime.tv_sec + 1e-6*u.ru_stime.tv_usec;
}

template<class T>
double capacityBytes(const std::vector<T>& v)
{
    return double(v.capacity()*sizeof(T));
}

} // namespace

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
        // The coupling fields go to the time directories with U and p (only
        // at the controlDict write times, so it costs nothing in between).
        air_->Ksl().writeOpt() = IOobject::AUTO_WRITE;
        air_->Us().writeOpt() = IOobject::AUTO_WRITE;
    }
    else
    {
        // DEM only: the void fraction for the output, with the case's model.
        locator_ = std::make_unique<FoamCellLocator>(mesh_);
        exchange_ = std::make_unique<::granair::ParticleExchange>(MPI_COMM_WORLD, *locator_);
        step_ = std::make_unique<::granair::CouplingStep>
        (
            settings_, *locator_, ::granair::FluidProperties{}
        );
        demVoidFraction_ = std::make_unique<volScalarField>
        (
            IOobject
            (
                "voidfraction", runTime_.timeName(), mesh_, IOobject::NO_READ, IOobject::AUTO_WRITE
            ),
            mesh_,
            dimensionedScalar("one", dimless, 1.0),
            "zeroGradient"
        );
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

    // Particles for ParaView (fields: OpenFOAM's own writeControl).
    if (dict_.has("output"))
    {
        const ::granair::Dictionary& d = dict_.subDict("output");
        vtkInterval_ = d.getDouble("vtkInterval");
        if (!(vtkInterval_ > 0) || !std::isfinite(vtkInterval_))
        {
            ::granair::fail<::granair::CollectiveError>
            (
                d.where("vtkInterval"), " = ", vtkInterval_,
                ": expected a positive interval of simulated time [s]"
            );
        }
        particleVtk_ = std::make_unique<::granair::ParticleVtkWriter>
        (
            MPI_COMM_WORLD, caseDir/"postProcessing"/"particles"
        );
    }

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
        << runTime_.endTime().value() << " s" << nl;
    if (particleVtk_)
    {
        Info<< "  particles to postProcessing/particles/particles.pvd every " << vtkInterval_
            << " s" << nl;
    }
    Info<< endl;
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


void CoupledRun::mapParticles()
{
    {
        StageTimers::Scope s(timers_, StageTimers::Exchange);
        exchange_->forward(particles_, owned_);
    }
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
}


void CoupledRun::mapVoidFraction()
{
    {
        StageTimers::Scope s(timers_, StageTimers::Exchange);
        // Particles that left the mesh (below a DEM-only run's coarse mesh)
        // are simply not in the field: the DEM alone decides where they go.
        exchange_->forward(particles_, owned_, ::granair::ParticleExchange::Outside::skip);
    }
    StageTimers::Scope s(timers_, StageTimers::Mapping);
    step_->voidFraction(owned_, demVoidFraction_->primitiveFieldRef().data());
    demVoidFraction_->correctBoundaryConditions();
}


volScalarField& CoupledRun::voidFraction()
{
    return air_ ? air_->voidfraction() : *demVoidFraction_;
}


void CoupledRun::coupleAir()
{
    mapParticles();
    floorHitsTotal_ += step_->stats().floorHits;
    minRawEps_ = std::min(minRawEps_, step_->stats().minRawVoidFraction);
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
        // The air's own pressure gradient (Gauss on its face pressure): at a
        // bed edge fvc::grad(p) with linearly interpolated face values gives
        // the edge cell about half the gradient its particles carry.
        const volVectorField& gradP = air_->gradP();
        step_->cellsToParticles
        (
            owned_,
            reinterpret_cast<const double*>(air_->U().primitiveField().cdata()),
            reinterpret_cast<const double*>(gradP.primitiveField().cdata()),
            ownedForces_
        );
    }
    {
        StageTimers::Scope s(timers_, StageTimers::Exchange);
        exchange_->backward(ownedForces_, 3, demForces_);
    }
    StageTimers::Scope s(timers_, StageTimers::DEM);
    dem_->setFluidForces(demForces_.data(), particles_.size());
}


void CoupledRun::run()
{
    ::granair::Progress progress(tStart_, runTime_.endTime().value());
    const double loopStart = MPI_Wtime();
    const double cpuStart = cpuSeconds();
    double massFlow = 0;
    {
        StageTimers::Scope s(timers_, StageTimers::DEM);
        dem_->getParticles(particles_);
    }
    // The void fraction at the start time is that of the particles there
    // (not 0/voidfraction or its default 1): it becomes the old-time value
    // of the first step, whose d(eps)/dt would otherwise see every particle
    // appear within one CFD step and push the air out of the bed with a
    // pressure kick many times the particles' weight. It is written to the
    // start time directory (replacing any 0/voidfraction given): the bed
    // the run starts from, in the same model and floor as every later field.
    if (air_)
    {
        mapParticles();
    }
    else
    {
        mapVoidFraction();
    }
    {
        StageTimers::Scope s(timers_, StageTimers::Output);
        voidFraction().write();
    }
    if (particleVtk_)
    {
        StageTimers::Scope s(timers_, StageTimers::Output);
        writeParticles(0);
    }
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
            if (!air_ && runTime_.writeTime())
            {
                mapVoidFraction();
            }
            runTime_.write();
            if (particleVtk_)
            {
                writeParticles(k);
            }
        }
        const double nParticles = lastRow_.at(discharge_ ? 3 : 1);
        particleSteps_ += nParticles*settings_.couplingInterval;
        peakParticles_ = std::max(peakParticles_, nParticles);
        progress.update(runTime_.value(), long(dem_->step()), progressExtra(massFlow), std::cout, k == nSteps_);
    }
    loopSeconds_ = MPI_Wtime() - loopStart;
    loopCpuSeconds_ = cpuSeconds() - cpuStart;
}


void CoupledRun::writeParticles(label k)
{
    // Due at tStart + m vtkInterval (m = 1, 2, ...), at the start and at the
    // end; the tolerance absorbs the round-off of the accumulated time.
    const double t = runTime_.value();
    const double tol = 1e-6*runTime_.deltaTValue();
    if (k > 0 && k < nSteps_ && t < tStart_ + vtkNext_*vtkInterval_ - tol)
    {
        return;
    }
    // The fluid force of this coupling step (zero at the start and with the
    // air off), in the order of particles_.
    const bool haveForces = air_ && k > 0 && demForces_.size() == 3*particles_.size();
    particleVtk_->write(t, particles_, haveForces ? demForces_.data() : nullptr, particles_.size());
    vtkNext_ = label(std::floor((t - tStart_ + tol)/vtkInterval_)) + 1;
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
    reportMemory(os);
    Info<< os.str().c_str() << endl;
}


void CoupledRun::reportMemory(std::ostream& os) const
{
    // The coupling loop alone (the timing table above includes the set-up).
    double loop = loopSeconds_;
    MPI_Allreduce(MPI_IN_PLACE, &loop, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    char line[256];
    std::snprintf
    (
        line, sizeof line,
        "Coupling loop: %.3f s wall for %ld coupling steps, %.4g particle-steps, %.4g particle-steps/s\n",
        loop, long(nSteps_), particleSteps_, loop > 0 ? particleSteps_/loop : 0.0
    );
    os << line;
    // CPU time is less disturbed than wall time by other load on the machine
    // (not by a rank waiting, busy, for a descheduled one).
    double cpu[2] = {loopCpuSeconds_, loopCpuSeconds_};
    MPI_Allreduce(MPI_IN_PLACE, &cpu[0], 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    MPI_Allreduce(MPI_IN_PLACE, &cpu[1], 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    std::snprintf
    (
        line, sizeof line,
        "Coupling loop CPU time (user + system): %.3f s on the busiest rank, %.3f s on all ranks\n",
        cpu[0], cpu[1]
    );
    os << line;

    // Peak resident memory, and what the coupling layer's own buffers hold
    // (vector capacities = their high-water marks; OpenFOAM's extra fields
    // voidfraction, Ksl, Us and LIGGGHTS' fluid-force arrays not included).
    const double hwm = peakResidentBytes();
    double hwmMax = hwm;
    MPI_Allreduce(MPI_IN_PLACE, &hwmMax, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    double sums[6] =
    {
        hwm,
        capacityBytes(particles_) + capacityBytes(owned_) + capacityBytes(ownedForces_)
      + capacityBytes(demForces_),
        exchange_ ? double(exchange_->bufferBytes()) : 0.0,
        step_ ? double(step_->particleBufferBytes()) : 0.0,
        step_ ? double(step_->cellBufferBytes()) : 0.0,
        double(mesh_.nCells())
    };
    MPI_Allreduce(MPI_IN_PLACE, sums, 6, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
    const double mib = 1024.0*1024.0;
    std::snprintf
    (
        line, sizeof line, "Peak memory (VmHWM): %.1f MiB on the largest rank, %.1f MiB on all %d rank(s)\n",
        hwmMax/mib, sums[0]/mib, Pstream::nProcs()
    );
    os << line;
    const double np = std::max(peakParticles_, 1.0), nc = std::max(sums[5], 1.0);
    std::snprintf
    (
        line, sizeof line,
        "Coupling buffers (all ranks): %.1f B/particle (run %.1f, exchange %.1f, coupling step %.1f) "
        "for %.0f particles; %.1f B/cell for %.0f cells\n",
        (sums[1] + sums[2] + sums[3])/np, sums[1]/np, sums[2]/np, sums[3]/np, peakParticles_,
        sums[4]/nc, sums[5]
    );
    os << line;
}

} // namespace granair
} // namespace Foam
