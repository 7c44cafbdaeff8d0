/*---------------------------------------------------------------------------*\
    granair: CoupledRun (see CoupledRun.H for the coupling step)
\*---------------------------------------------------------------------------*/
#include "coupled/CoupledRun.H"
#include "coupled/DemProcessorGrid.H"

#include "core/CapacityBytes.hpp"
#include "core/Error.hpp"
#include "core/StopSignal.hpp"
#include "monitor/Progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
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
    settings_(::granair::CouplingSettings::read(dict_)),
    run_(::granair::RunSettings::read(dict_))
{
    // Every reader of couplingProperties has read it (the monitors too):
    // a key nobody asked for is a misspelling, stop before any work.
    if (settings_.airOn)
    {
        monitors_ = std::make_unique<MonitorSet>(mesh_, dict_);
    }
    else
    {
        dict_.allow({"monitors"});   // air monitors: nothing to monitor
    }
    dict_.checkKnownKeys();
    restart_ = findRestart();
    openDem();
    checkTimeSteps();
    openCfd();
    openOutput();
    printSummary();
}


CoupledRun::~CoupledRun() = default;


bool CoupledRun::findRestart()
{
    const fileName caseDir = runTime_.globalPath();
    const fileName dir = restartDirectory(caseDir, runTime_.timeName());
    const double t = runTime_.value(), tol = 1e-6*runTime_.deltaTValue();
    if (isFile(dir/"coupling"))
    {
        restartState_ = RestartState::read(dir/"coupling");
        if (std::abs(restartState_.time - t) > tol)
        {
            ::granair::fail<::granair::CollectiveError>
            (
                "restart: ", dir/"coupling", " is the restart point of t = ", restartState_.time,
                " s, but system/controlDict starts at t = ", t, " s (was the directory copied or renamed?)"
            );
        }
        return true;
    }
    if (isDir(dir))
    {
        ::granair::fail<::granair::CollectiveError>
        (
            "restart: ", dir, " has no 'coupling' file: the restart point of t = ", t,
            " s is incomplete (the run ended while writing it); start from an earlier write time"
        );
    }
    // No restart point: a fresh start. One at a time an earlier run of this
    // case passed would overwrite its time series and start the DEM from
    // the script's particles, not those of that time.
    std::ifstream csv(caseDir/"postProcessing"/"timeSeries.csv");
    std::string line;
    std::getline(csv, line);
    bool first = true;
    while (std::getline(csv, line))
    {
        const double tRow = std::strtod(line.c_str(), nullptr);
        if (!first && std::abs(tRow - t) <= tol)
        {
            ::granair::fail<::granair::CollectiveError>
            (
                "system/controlDict starts at t = ", t, " s, a time an earlier run of this case passed ",
                "(postProcessing/timeSeries.csv has a row there), but there is no restart point ", dir,
                "/: granairFoam writes one with every field write time. Start from a time that has ",
                "one (ls ", caseDir/"restart", "), or remove postProcessing/timeSeries.* to start afresh"
            );
        }
        first = false;
    }
    return false;
}


void CoupledRun::openDem()
{
    // The case's LIGGGHTS script sets everything up, with no coupled run.
    // A restart runs the restart script with ${granair_restart}, the
    // LIGGGHTS restart file of the restart point (an index variable: a
    // script's own `variable granair_restart index ...` does not override it).
    const fileName caseDir = runTime_.globalPath();
    dem_ = std::make_unique<::granair::dem::LiggghtsDriver>(MPI_COMM_WORLD, caseDir/"log");
    if (restart_)
    {
        dem_->command
        (
            "variable granair_restart index "
          + restartDirectory(caseDir, runTime_.timeName()) + "/dem.restart"
        );
    }
    // LIGGGHTS' processor grid follows the CFD decomposition (a script's
    // own `processors` command comes later and wins).
    const DemProcessorGrid grid(runTime_);
    if (!grid.command().empty())
    {
        dem_->command(grid.command());
    }
    dem_->runFile(caseDir/(restart_ ? run_.demRestartScript : run_.demScript));
    if (restart_)
    {
        checkRestartedDem();
        dem_->alignTime(restartState_.demTime);
    }
    // The fluid force and discharge state fixes: after a restart they take
    // their per-particle values back from LIGGGHTS' restart file.
    if (settings_.airOn)
    {
        dem_->enableFluidForces();
    }
    if (run_.discharge)
    {
        const ::granair::DischargeSettings& d = *run_.discharge;
        discharge_ = std::make_unique<::granair::dem::DischargeCounter>(*dem_, d.outletZ, d.sinkZ);
        massFlow_ = std::make_unique<::granair::MassFlowRate>(d.massFlowWindow);
        if (restart_)
        {
            if (!restartState_.discharge)
            {
                ::granair::fail<::granair::CollectiveError>
                (
                    "restart at t = ", runTime_.value(), " s: constant/couplingProperties has a discharge ",
                    "counter, the restart point has none (the case was changed)"
                );
            }
            discharge_->restore(restartState_.balance, restartState_.maxTagSeen);
            massFlow_->restore(restartState_.massFlow);
        }
    }
    if (restart_)
    {
        // The global totals so far, held by rank 0 (the end report sums).
        floorHitsTotal_ = Pstream::master() ? restartState_.floorHitsTotal : 0;
        minRawEps_ = restartState_.minRawVoidFraction;
    }
}


void CoupledRun::checkRestartedDem() const
{
    const RestartState& s = restartState_;
    const std::int64_t n = dem_->nGlobal();
    if (dem_->step() != s.demStep || n != s.particles)
    {
        ::granair::fail<::granair::CollectiveError>
        (
            "restart: DEM and CFD times do not match. The CFD starts at t = ", s.time, " s, whose restart point ",
            restartDirectory(runTime_.globalPath(), s.timeName), "/coupling has LIGGGHTS at step ", s.demStep,
            " (t_DEM = ", s.demTime, " s) with ", s.particles, " particles; after the restart script ",
            run_.demRestartScript, " LIGGGHTS is at step ", dem_->step(), " (t_DEM = ", dem_->time(), " s) with ",
            n, " particles. The restart script must read the restart point's particles: ",
            "`read_restart ${granair_restart}` (docs/case-format.md, Restart)"
        );
    }
}


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


void CoupledRun::openCfd()
{
    locator_ = std::make_unique<FoamCellLocator>(mesh_);
    exchange_ = std::make_unique<::granair::ParticleExchange>(MPI_COMM_WORLD, *locator_);
    if (settings_.airOn)
    {
        air_ = std::make_unique<AirSolver>(mesh_);
        step_ = std::make_unique<::granair::CouplingStep>
        (
            settings_, *locator_, ::granair::FluidProperties{air_->rho(), air_->mu()}
        );
        // The coupling fields go to the time directories with U and p (only
        // at the controlDict write times, so it costs nothing in between).
        air_->Ksl().writeOpt() = IOobject::AUTO_WRITE;
        air_->Us().writeOpt() = IOobject::AUTO_WRITE;
        return;
    }
    // DEM only: the void fraction for the output, with the case's model.
    step_ = std::make_unique<::granair::CouplingStep>(settings_, *locator_, ::granair::FluidProperties{});
    demVoidFraction_ = std::make_unique<volScalarField>
    (
        IOobject("voidfraction", runTime_.timeName(), mesh_, IOobject::NO_READ, IOobject::AUTO_WRITE),
        mesh_,
        dimensionedScalar("one", dimless, 1.0),
        "zeroGradient"
    );
}


void CoupledRun::openOutput()
{
    const fileName caseDir = runTime_.globalPath();
    if (Pstream::master())
    {
        mkDir(caseDir/"postProcessing");
    }
    ::granair::StepSeries::Layout layout;
    layout.discharge = bool(discharge_);
    layout.air = bool(air_);
    if (monitors_)
    {
        layout.monitorColumns = monitors_->columns();
    }
    // A restart continues the series after the rows up to its time.
    series_ = std::make_unique<::granair::StepSeries>
    (
        MPI_COMM_WORLD, caseDir/"postProcessing"/"timeSeries", layout,
        restart_ ? restartState_.seriesRows : -1
    );
    // Particles for ParaView (fields: OpenFOAM's own writeControl).
    vtkOrigin_ = restart_ ? restartState_.vtkOrigin : tStart_;
    if (run_.vtkInterval > 0)
    {
        particleVtk_ = std::make_unique<::granair::ParticleVtkWriter>
        (
            MPI_COMM_WORLD, caseDir/"postProcessing"/"particles"
        );
        if (restart_)
        {
            particleVtk_->resume(restartState_.vtkTimes);
            vtkNext_ = label(restartState_.vtkNext);
        }
    }
}


void CoupledRun::printSummary() const
{
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
        if (!settings_.forcesApplied)
        {
            Info<< nl << "  fluid forces computed but NOT applied (forces { applied off; }:"
                << " the DEM runs the air-off problem; a benchmark reference)";
        }
    }
    Info<< nl << "  " << nSteps_ << " coupling steps from t = " << tStart_ << " s to "
        << runTime_.endTime().value() << " s" << nl;
    if (particleVtk_)
    {
        Info<< "  particles to postProcessing/particles/particles.pvd every " << run_.vtkInterval
            << " s" << nl;
    }
    DemProcessorGrid(runTime_).report(*dem_);
    DemProcessorGrid::checkNeighbourBins(*dem_);
    Info<< endl;
}


void CoupledRun::mapParticles()
{
    {
        StageTimers::Scope s(timers_, StageTimers::Exchange);
        exchange_->forward(*particles_, owned_);
    }
    countSearch();
    StageTimers::Scope s(timers_, StageTimers::Mapping);
    const double* U = reinterpret_cast<const double*>(air_->U().primitiveField().cdata());
    if (settings_.oneWay)
    {
        // The air keeps eps = 1, Ksl = 0, Us = 0 (its initial values).
        const std::size_t n = std::size_t(mesh_.nCells());
        particleEps_.resize(n);
        particleKsl_.resize(n);
        particleUs_.resize(3*n);
        step_->particlesToCells
        (
            owned_, U, particleEps_.data(), particleKsl_.data(), particleUs_.data()
        );
        return;
    }
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
        exchange_->forward(*particles_, owned_, ::granair::ParticleExchange::Outside::skip);
    }
    countSearch();
    StageTimers::Scope s(timers_, StageTimers::Mapping);
    step_->voidFraction(owned_, demVoidFraction_->primitiveFieldRef().data());
    demVoidFraction_->correctBoundaryConditions();
}


void CoupledRun::countSearch()
{
    const ::granair::ExchangeStats& st = exchange_->stats();
    search_[0] += st.particlesSent;
    search_[1] += st.reordered;
    search_[2] += st.hintMisses;
    search_[3] += st.globalSearches;
    search_[4] += st.tagSearches;
}


volScalarField& CoupledRun::voidFraction()
{
    return air_ ? air_->voidfraction() : *demVoidFraction_;
}


void CoupledRun::solveAir()
{
    StageTimers::Scope s(timers_, StageTimers::CFD);
    // OpenFOAM's per-iteration solver lines would drown the progress
    // line; `airSolverLog on;` in couplingProperties keeps them.
    const int level = messageStream::level;
    if (!run_.airSolverLog)
    {
        messageStream::level = 0;
    }
    air_->solveStep();
    messageStream::level = level;
}


void CoupledRun::forcesToDem()
{
    {
        StageTimers::Scope s(timers_, StageTimers::Mapping);
        // The air's own pressure gradient (Gauss on its face pressure): at a
        // bed edge fvc::grad(p) with linearly interpolated face values gives
        // the edge cell about half the gradient its particles carry.
        // Each force goes straight into LIGGGHTS' fluid-force store (this
        // rank's particles) or into the message to its DEM owner, whose
        // backwardSend() stores it: no per-particle array of forces on
        // either side.
        dem_->beginFluidForces();
        const volVectorField& gradP = air_->gradP();
        const ::granair::CouplingStep::Forces force = step_->forces
        (
            owned_,
            reinterpret_cast<const double*>(air_->U().primitiveField().cdata()),
            reinterpret_cast<const double*>(gradP.primitiveField().cdata())
        );
        ::granair::dem::LiggghtsDriver& dem = *dem_;
        // `forces { applied off; }` (benchmarking): the same work, zeros
        // stored, so the DEM runs the `air off` problem (bench/README.md).
        static const double zero[3] = {0, 0, 0};
        const bool applied = settings_.forcesApplied;
        exchange_->backwardFill
        (
            3,
            [&force](std::size_t k, double* f) { force(k, f); },
            [&dem, applied](std::size_t i, const double* f)
            {
                dem.setFluidForce(i, applied ? f : zero);
            }
        );
    }
    {
        StageTimers::Scope s(timers_, StageTimers::Exchange);
        exchange_->backwardSend();
    }
    StageTimers::Scope s(timers_, StageTimers::DEM);
    dem_->endFluidForces();
    forcesSet_ = true;
}


void CoupledRun::coupleAir()
{
    mapParticles();
    floorHitsTotal_ += step_->stats().floorHits;
    minRawEps_ = std::min(minRawEps_, step_->stats().minRawVoidFraction);
    solveAir();
    forcesToDem();
}


void CoupledRun::run()
{
    ::granair::Progress progress(tStart_, runTime_.endTime().value());
    resources_.startLoop();
    double massFlow = 0;
    {
        StageTimers::Scope s(timers_, StageTimers::DEM);
        particles_ = &dem_->particles();
    }
    // The void fraction at the start time is that of the particles there
    // (not 0/voidfraction or its default 1): it becomes the old-time value
    // of the first step, whose d(eps)/dt would otherwise see every particle
    // appear within one CFD step and push the air out of the bed with a
    // pressure kick many times the particles' weight. It is written to the
    // start time directory (replacing any 0/voidfraction given): the bed
    // the run starts from, in the same model and floor as every later field.
    //   With the air on, the particles also get their fluid force from the
    // initial air fields now, for the first interval of DEM steps. At a
    // restart they have it already (LIGGGHTS' restart file: the force the
    // run computed at this time), and the start time's outputs exist.
    if (air_)
    {
        mapParticles();
        if (!restart_)
        {
            forcesToDem();
        }
    }
    else
    {
        mapVoidFraction();
    }
    if (!restart_)
    {
        StageTimers::Scope s(timers_, StageTimers::Output);
        voidFraction().write();
        if (particleVtk_)
        {
            writeParticles(0);
        }
    }
    stopSignal_ = ::granair::StopSignal::received(MPI_COMM_WORLD);
    emptied_ = dem_->nGlobal() == 0;
    for (label k = 1; k <= nSteps_ && !stopSignal_ && !emptied_; ++k)
    {
        {
            StageTimers::Scope s(timers_, StageTimers::DEM);
            dem_->advance(settings_.couplingInterval);
            if (discharge_)
            {
                discharge_->update();
            }
            particles_ = &dem_->particles();
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
                massFlow = run_.discharge->depthScale*massFlow_->add
                (
                    runTime_.value(), discharge_->balance().dischargedMass
                );
            }
            series_->append(record(massFlow));
            if (!air_ && runTime_.writeTime())
            {
                mapVoidFraction();
            }
            runTime_.write();
            if (particleVtk_)
            {
                writeParticles(k);
            }
            if (runTime_.writeTime())
            {
                writeRestartPoint();
            }
        }
        resources_.addStep(series_->last().particles, settings_.couplingInterval);
        stepsDone_ = k;
        stopSignal_ = ::granair::StopSignal::received(MPI_COMM_WORLD);
        emptied_ = series_->last().particles == 0;
        progress.update
        (
            runTime_.value(), long(dem_->step()), progressExtra(series_->last()), std::cout,
            k == nSteps_ || stopSignal_ || emptied_
        );
    }
    if (stopSignal_ || emptied_)
    {
        // An emptied domain gets the fields but no restart point: there is
        // nothing left to continue (and LIGGGHTS could not read zero atoms).
        writeStopPoint(!emptied_);
    }
    resources_.stopLoop();
}


void CoupledRun::writeStopPoint(bool restartPoint)
{
    StageTimers::Scope s(timers_, StageTimers::Output);
    if (!runTime_.writeTime())
    {
        if (!air_)
        {
            mapVoidFraction();
        }
        runTime_.writeNow();
        if (restartPoint)
        {
            writeRestartPoint();
        }
    }
}


void CoupledRun::writeRestartPoint()
{
    const fileName caseDir = runTime_.globalPath();
    const fileName dir = restartDirectory(caseDir, runTime_.timeName());
    if (Pstream::master())
    {
        mkDir(dir);
    }
    // LIGGGHTS writes it from its rank 0 (this process's rank 0 made the
    // directory); it re-initialises, so the next advance is a full setup.
    dem_->command("write_restart " + dir + "/dem.restart");
    RestartState s;
    s.time = runTime_.value();
    s.timeName = runTime_.timeName();
    s.demStep = dem_->step();
    s.demTime = dem_->time();
    s.particles = dem_->nGlobal();
    s.seriesRows = series_->rows();
    s.vtkOrigin = vtkOrigin_;
    s.vtkNext = long(vtkNext_);
    if (particleVtk_)
    {
        s.vtkTimes = particleVtk_->times();
    }
    if (discharge_)
    {
        s.discharge = true;
        s.balance = discharge_->balance();
        s.maxTagSeen = discharge_->maxTagSeen();
        s.massFlow = massFlow_->history();
    }
    // floorHitsTotal_ and minRawEps_ are this rank's: the state holds the
    // global ones (a restart gives the total to rank 0).
    s.floorHitsTotal = returnReduce(label(floorHitsTotal_), sumOp<label>());
    s.minRawVoidFraction = returnReduce(minRawEps_, minOp<scalar>());
    if (Pstream::master())
    {
        s.write(dir/"coupling");   // last: marks the restart point complete
    }
    purgeRestartPoints();
}


void CoupledRun::purgeRestartPoints() const
{
    // As OpenFOAM's purgeWrite N keeps the last N time directories.
    const label keep = runTime_.controlDict().lookupOrDefault<label>("purgeWrite", 0);
    if (keep <= 0 || !Pstream::master())
    {
        return;
    }
    const fileName root = runTime_.globalPath()/"restart";
    fileNameList dirs = readDir(root, fileName::DIRECTORY);
    std::vector<std::pair<scalar, fileName>> times;
    for (const fileName& d : dirs)
    {
        scalar t;
        if (readScalar(d, t))
        {
            times.emplace_back(t, d);
        }
    }
    std::sort(times.begin(), times.end());
    for (std::size_t k = 0; k + std::size_t(keep) < times.size(); ++k)
    {
        rmDir(root/times[k].second);
    }
}


void CoupledRun::writeParticles(label k)
{
    // Due at tStart + m vtkInterval (m = 1, 2, ...), at the start and at the
    // end; the tolerance absorbs the round-off of the accumulated time.
    const double t = runTime_.value();
    const double tol = 1e-6*runTime_.deltaTValue();
    if (k > 0 && k < nSteps_ && t < vtkOrigin_ + vtkNext_*run_.vtkInterval - tol)
    {
        return;
    }
    // The fluid force of this coupling step (at the start: from the initial
    // air; none with the air off or at a restart's first write), in the order
    // of particles_, read back from LIGGGHTS' store for this write only.
    std::vector<double> forces;
    if (air_ && forcesSet_)
    {
        dem_->getFluidForces(forces);
    }
    particleVtk_->write(t, *particles_, forces.empty() ? nullptr : forces.data(), particles_->size());
    vtkNext_ = label(std::floor((t - vtkOrigin_ + tol)/run_.vtkInterval)) + 1;
}


::granair::StepRecord CoupledRun::record(double massFlow) const
{
    ::granair::StepRecord r;
    r.t = runTime_.value();
    if (discharge_)
    {
        r.dischargedKg = run_.discharge->depthScale*discharge_->balance().dischargedMass;
        r.massFlowKgS = massFlow;
    }
    r.particles = double(dem_->nGlobal());
    if (air_)
    {
        r.voidFractionMin = settings_.oneWay
            ? returnReduce
              (
                  particleEps_.empty()
                ? 1.0 : *std::min_element(particleEps_.begin(), particleEps_.end()),
                  minOp<scalar>()
              )
            : gMin(air_->eps().primitiveField());
        r.floorHits = double(returnReduce(label(step_->stats().floorHits), sumOp<label>()));
        monitors_->values(*air_, r.monitors);
    }
    return r;
}


std::string CoupledRun::progressExtra(const ::granair::StepRecord& r) const
{
    std::ostringstream os;
    os.precision(4);
    os << "particles " << r.particles;
    if (discharge_)
    {
        os << " | discharged " << r.dischargedKg << " kg | W " << r.massFlowKgS << " kg/s";
    }
    if (air_)
    {
        os << " | min eps " << r.voidFractionMin;
    }
    return os.str();
}


::granair::ResourceUsage::Buffers CoupledRun::bufferBytes() const
{
    using ::granair::capacityBytes;
    ::granair::ResourceUsage::Buffers b;
    b.run = double
    (
        owned_.bufferBytes()
    );
    b.exchange = double(exchange_->bufferBytes());
    b.stepParticles = double(step_->particleBufferBytes());
    b.stepCells = double(step_->cellBufferBytes() + locator_->cellArrayBytes());
    b.cells = double(mesh_.nCells());
    return b;
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
    {
        // How well the exchange's cell-search hints work (ParticleExchange.hpp).
        std::int64_t total[5];
        MPI_Allreduce(search_, total, 5, MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD);
        const double n = total[0] > 0 ? double(total[0]) : 1.0;
        os  << "Cell search: " << total[0] << " particle records; re-sorted since the last step "
            << 100*total[1]/n << " % (found by tag search " << 100*total[4]/n
            << " %), not in their last cell or its neighbours " << 100*total[2]/n
            << " %, whole-mesh searches " << 100*total[3]/n << " %\n";
    }
    timers_.report(MPI_COMM_WORLD, os);
    resources_.report(MPI_COMM_WORLD, long(stepsDone_), bufferBytes(), os);
    if (stopSignal_)
    {
        os  << "\ngranairFoam: stopped by " << ::granair::StopSignal::name(stopSignal_) << " at t = "
            << runTime_.value() << " s, after coupling step " << stepsDone_ << " of " << nSteps_
            << " (end time " << runTime_.endTime().value() << " s).\n"
            << "  The outputs are complete up to that time: postProcessing/timeSeries.{csv,h5} have every "
            << "step to t = " << runTime_.value() << " s, and the fields and a restart point of t = "
            << runTime_.timeName() << " are written: continue with startFrom latestTime.\n"
            << "  Exit code " << ::granair::StopSignal::exitCode(stopSignal_) << ".\n";
    }
    else if (emptied_)
    {
        os  << "\ngranairFoam: no particles left in the DEM domain at t = " << runTime_.value()
            << " s, after coupling step " << stepsDone_ << " of " << nSteps_ << " (end time "
            << runTime_.endTime().value() << " s): the run ends here.\n"
            << "  The outputs are complete up to that time: postProcessing/timeSeries.{csv,h5} have every "
            << "step to t = " << runTime_.value() << " s and the fields of t = " << runTime_.timeName()
            << " are written.\n";
    }
    Info<< os.str().c_str() << endl;
}

} // namespace granair
} // namespace Foam
