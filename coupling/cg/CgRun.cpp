// CgRun.cpp: see CgRun.hpp.
#include "cg/CgRun.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <ostream>
#include <sstream>

#include "cg/CgAverager.hpp"
#include "cg/CgFields.hpp"
#include "cg/CgKernel.hpp"
#include "cg/CgWriters.hpp"
#include "cg/CoarseGrainer.hpp"
#include "core/Error.hpp"
#include "output/FormatExact.hpp"

namespace granair {

namespace {

int axisIndex(const std::string& w, const std::string& where) {
    if (w == "x" || w == "X" || w == "0") return 0;
    if (w == "y" || w == "Y" || w == "1") return 1;
    if (w == "z" || w == "Z" || w == "2") return 2;
    fail<InputError>(where, ": plane-wall axis '", w, "', expected x, y or z");
}

CgKernel makeKernel(const CgRunSettings& s, int dims) {
    if (dims == 0) return CgKernel(nullptr, 0);
    Dictionary d("the granairCG settings");
    d.set("type", s.kernel);
    d.set("width", formatExact(s.std > 0.0 ? 1.0 : s.width));
    if (s.kernel == "gauss") d.set("cutoff", formatExact(s.cutoff));
    std::shared_ptr<const CgKernelShape> shape = cgKernelShapes().create(d);
    if (s.std > 0.0) return CgKernel::withStandardDeviation(*shape, dims, s.std);
    return CgKernel(shape, dims);
}

// Particle mass inside the window: centre within the box (Cartesian) or the
// ring region (RZ), positions wrapped into the box along periodic directions.
double windowMass(const CgGrid& g, const CgSnapshot& snap) {
    double m = 0.0;
    for (const auto& q : snap.particles) {
        CgParticle p = q;
        for (int a = 0; a < 3; ++a)
            if (snap.domain.periodic[a] && snap.domain.period(a) > 0)
                p.x[a] -= snap.domain.period(a) * std::floor((p.x[a] - snap.domain.box.lo[a]) / snap.domain.period(a));
        bool in;
        if (g.isCylindrical()) {
            const double r = std::hypot(p.x[0] - g.axisOrigin()[0], p.x[1] - g.axisOrigin()[1]);
            in = r >= g.lo(0) && r < g.hi(0) && p.x[2] >= g.lo(2) && p.x[2] < g.hi(2);
        } else {
            in = (p.x.array() >= g.window().lo.array()).all() && (p.x.array() < g.window().hi.array()).all();
        }
        if (in) m += p.mass;
    }
    return m;
}

double gridMass(const CgGrid& g, const CgRawFields& raw) {
    double m = 0.0;
    for (std::size_t p = 0; p < g.size(); ++p) m += raw.at(p)[cgraw::density] * g.cellVolume(p);
    return m;
}

}  // namespace

CgRunSettings CgRunSettings::fromOptions(const CgOptions& o) {
    CgRunSettings s;
    s.read.particles = o.getString("particles");
    s.read.pairs = o.getString("pairs", "");
    s.read.walls = o.getString("walls", "");
    s.read.pairLayout = o.getString("pairLayout", s.read.pairLayout);
    s.read.wallLayout = o.getString("wallLayout", s.read.wallLayout);
    const auto& pw = o.words("planeWalls");
    for (std::size_t i = 0; i + 2 < pw.size(); i += 3) {
        CgPlaneWall w;
        w.fix = pw[i];
        w.axis = axisIndex(pw[i + 1], o.where("planeWalls"));
        char* end = nullptr;
        w.position = std::strtod(pw[i + 2].c_str(), &end);
        if (end == pw[i + 2].c_str() || *end || !std::isfinite(w.position))
            fail<InputError>(o.where("planeWalls"), ": plane-wall position '", pw[i + 2], "' is not a number");
        s.read.planeWalls.push_back(w);
    }
    s.read.dt = o.getDouble("dt", 0.0);
    if (s.read.dt < 0.0) fail<InputError>(o.where("dt"), ": time step ", s.read.dt, " s, expected > 0");

    s.coordinates = parseCgCoordinates(o.getString("coordinates", "XYZ"), o.where("coordinates"));
    s.kernel = o.getString("kernel", "gauss");
    if (!cgKernelShapes().has(s.kernel)) {
        std::string list;
        for (const auto& n : cgKernelShapes().names()) list += " " + n;
        fail<InputError>(o.where("kernel"), ": unknown kernel '", s.kernel, "'. Known kernels:", list);
    }
    s.width = o.getDouble("width", 0.0);
    s.std = o.getDouble("std", 0.0);
    s.cutoff = o.getDouble("cutoff", 3.0);
    if (o.has("cutoff") && s.kernel != "gauss")
        fail<InputError>(o.where("cutoff"), ": only the gauss kernel takes a cutoff (",
                         s.kernel, " is cut at its width)");
    if (s.kernel == "gauss" && !(s.cutoff >= 1.0 && s.cutoff <= 10.0))
        fail<InputError>(o.where("cutoff"), ": value ", s.cutoff, " out of range, expected 1 <= cutoff <= 10 widths");
    if (s.coordinates != CgCoordinates::O) {
        if (o.has("width") && o.has("std"))
            fail<InputError>(o.where("std"), ": give the kernel's width or its standard deviation, not both");
        if (!o.has("width") && !o.has("std"))
            fail<InputError>("kernel size missing: give --width W [m] (gauss w, heaviside/lucy cutoff radius) "
                             "or --std S [m] (standard deviation per axis)");
        if (o.has("width") && !(s.width > 0.0))
            fail<InputError>(o.where("width"), ": kernel width ", s.width, " m, expected > 0");
        if (o.has("std") && !(s.std > 0.0))
            fail<InputError>(o.where("std"), ": standard deviation ", s.std, " m, expected > 0");
    }
    if (o.has("n")) {
        for (double v : o.getNumbers("n", 1, 3)) {
            if (v != std::floor(v) || v < 1 || v > 1e7)
                fail<InputError>(o.where("n"), ": ", v, " grid points, expected a whole number >= 1");
            s.n.push_back(long(v));
        }
        if (o.has("spacing")) fail<InputError>(o.where("spacing"), ": give --n or --spacing, not both");
    }
    s.spacing = o.getDouble("spacing", 0.0);
    if (o.has("spacing") && !(s.spacing > 0.0))
        fail<InputError>(o.where("spacing"), ": grid spacing ", s.spacing, " m, expected > 0");
    if ((s.haveMin = o.has("min"))) {
        const auto v = o.getNumbers("min", 3, 3);
        s.min = Vec3(v[0], v[1], v[2]);
    }
    if ((s.haveMax = o.has("max"))) {
        const auto v = o.getNumbers("max", 3, 3);
        s.max = Vec3(v[0], v[1], v[2]);
    }
    if ((s.haveAxis = o.has("axis"))) {
        const auto v = o.getNumbers("axis", 2, 2);
        s.axisX = v[0], s.axisY = v[1];
    }
    s.rmin = o.getDouble("rmin", 0.0);
    s.rmax = o.getDouble("rmax", 0.0);
    if (o.has("rmax") && !(s.rmax > s.rmin))
        fail<InputError>(o.where("rmax"), ": ", s.rmax, " m, expected rmax > rmin = ", s.rmin, " m");
    if (s.rmin < 0.0) fail<InputError>(o.where("rmin"), ": ", s.rmin, " m, expected >= 0");

    s.average.kind = CgTimeAverage::parseKind(o.getString("timeAverage", "uniform"), o.where("timeAverage"));
    s.average.from = o.getDouble("from", -1e300);
    s.average.to = o.getDouble("to", 1e300);
    if (s.average.to < s.average.from)
        fail<InputError>(o.where("to"), ": ", s.average.to, " is before --from ", s.average.from);
    if (s.average.kind == CgTimeAverage::Kind::gauss) {
        s.average.centre = o.getDouble("centre");
        s.average.width = o.getDouble("timeWidth");
        if (!(s.average.width > 0.0))
            fail<InputError>(o.where("timeWidth"), ": ", s.average.width, ", expected a width > 0");
    }
    s.every = o.flag("every");
    s.out = o.getString("out", "cg");
    if (o.has("format")) {
        s.formats.clear();
        for (const auto& w : o.words("format")) {
            const std::string f = w == "vtk" ? "vti" : w == "hdf5" ? "h5" : w;
            if (f != "vti" && f != "h5" && f != "csv")
                fail<InputError>(o.where("format"), ": unknown format '", w, "', expected vti, h5 or csv");
            s.formats.push_back(f);
        }
    }
    s.threads = int(o.getInt("threads", 0));
    if (s.threads < 0 || s.threads > 1024) fail<InputError>(o.where("threads"), ": ", s.threads, " threads");
    s.minVolumeFraction = o.getDouble("minVolumeFraction", 1e-3);
    if (!(s.minVolumeFraction >= 0.0 && s.minVolumeFraction < 1.0))
        fail<InputError>(o.where("minVolumeFraction"), ": ", s.minVolumeFraction, ", expected 0 <= value < 1");
    s.azimuthalNodes = int(o.getInt("azimuthalNodes", 16));
    if (s.azimuthalNodes < 2 || s.azimuthalNodes > 200)
        fail<InputError>(o.where("azimuthalNodes"), ": ", s.azimuthalNodes, ", expected 2 to 200");
    return s;
}

CgGrid makeCgGrid(const CgRunSettings& s, const CgDomain& domain, double kernelStd) {
    Box win = domain.box;
    if (s.haveMin) win.lo = s.min;
    if (s.haveMax) win.hi = s.max;
    const auto res = cgResolvedAxes(s.coordinates);
    const double h = s.spacing > 0.0 ? s.spacing : kernelStd;
    auto countFor = [&](double length) { return std::max(1L, long(std::lround(length / h))); };
    std::vector<int> axes;
    for (int a = 0; a < 3; ++a)
        if (res[a]) axes.push_back(a);
    std::array<long, 3> n{{1, 1, 1}};
    if (s.coordinates == CgCoordinates::RZ) {
        const double x0 = s.haveAxis ? s.axisX : 0.5 * (win.lo[0] + win.hi[0]);
        const double y0 = s.haveAxis ? s.axisY : 0.5 * (win.lo[1] + win.hi[1]);
        const double rmax = s.rmax > 0.0 ? s.rmax
                                         : std::min({x0 - win.lo[0], win.hi[0] - x0, y0 - win.lo[1], win.hi[1] - y0});
        if (!(rmax > s.rmin))
            fail<InputError>("RZ grid: the axis (", x0, ", ", y0, ") leaves no radius in the box; give --axis and --rmax");
        long nr, nz;
        if (!s.n.empty()) {
            if (s.n.size() != 1 && s.n.size() != 2)
                fail<InputError>("RZ grid: --n takes one or two numbers (nr nz), found ", s.n.size());
            nr = s.n[0], nz = s.n.size() == 2 ? s.n[1] : s.n[0];
        } else {
            nr = countFor(rmax - s.rmin), nz = countFor(win.hi[2] - win.lo[2]);
        }
        return CgGrid::cylindrical(x0, y0, s.rmin, rmax, win.lo[2], win.hi[2], int(nr), int(nz));
    }
    if (!s.n.empty()) {
        if (s.n.size() != 1 && s.n.size() != axes.size())
            fail<InputError>(cgCoordinatesName(s.coordinates), " grid: --n takes 1 or ", axes.size(),
                             " numbers (one per resolved axis), found ", s.n.size());
        for (std::size_t i = 0; i < axes.size(); ++i) n[axes[i]] = s.n.size() == 1 ? s.n[0] : s.n[i];
    } else {
        for (int a : axes) n[a] = countFor(win.hi[a] - win.lo[a]);
    }
    for (int a = 0; a < 3; ++a)
        if (n[a] > 100000000L) fail<InputError>("CG grid: ", n[a], " points along one axis");
    return CgGrid(s.coordinates, win, {{int(n[0]), int(n[1]), int(n[2])}});
}

CgRunResult runCg(const CgRunSettings& s, std::ostream& log) {
    using clock = std::chrono::steady_clock;
    const auto start = clock::now();
    CgRunResult result;
    const CgSnapshotReader reader(s.read);
    const auto steps = reader.steps();
    std::vector<double> times;
    for (long st : steps) times.push_back(reader.timeOf(st));
    const auto weights = s.average.weights(times);
    std::vector<std::size_t> chosen;
    for (std::size_t k = 0; k < steps.size(); ++k)
        if (weights[k] > 0.0) chosen.push_back(k);

    const CgSnapshot first = reader.read(steps[chosen.front()]);
    int dims = 0;
    for (bool r : cgResolvedAxes(s.coordinates)) dims += r;
    if (s.coordinates == CgCoordinates::RZ) dims = 3;  // the kernel acts in 3-D
    CgKernel kernel = makeKernel(s, dims);
    const CgGrid grid = [&] {
        try {
            return makeCgGrid(s, first.domain, kernel.standardDeviation());
        } catch (const InputError& e) {
            fail<InputError>("the grid (--coordinates, --min/--max or the dump's box, --n or --spacing, RZ: "
                             "--axis/--rmin/--rmax): ", e.what());
        }
    }();
    const CoarseGrainer cg(grid, kernel, s.azimuthalNodes);

    log.precision(6);
    log << "granairCG: " << grid.describe() << " (" << grid.size() << " points)\n";
    if (dims > 0)
        log << "  kernel " << kernel.name() << ": width " << kernel.shape().width() << " m, cutoff "
            << kernel.cutoff() << " m, standard deviation " << kernel.standardDeviation() << " m per axis\n";
    else
        log << "  window average (no kernel)\n";
    log << "  " << chosen.size() << " of " << steps.size() << " snapshots (" << times.front() << " to "
        << times.back() << (s.read.dt > 0 ? " s" : " steps") << "), time average " << s.average.describe()
        << "\n";

    std::filesystem::path outDir = std::filesystem::path(s.out).parent_path();
    if (!outDir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(outDir, ec);
        if (ec) fail<InputError>("cannot create the output directory '", outDir.string(), "' (", ec.message(), ")");
    }
    CgFieldOptions fopt;
    fopt.minVolumeFraction = s.minVolumeFraction;
    fopt.spin = first.hasSpin;
    auto has = [&](const char* f) { return std::find(s.formats.begin(), s.formats.end(), f) != s.formats.end(); };
    CgAttributes attrs{{"coordinates", cgCoordinatesName(s.coordinates)},
                       {"grid", grid.describe()},
                       {"kernel", dims > 0 ? kernel.name() : "window"},
                       {"kernel_width_m", formatExact(dims > 0 ? kernel.shape().width() : 0.0)},
                       {"kernel_cutoff_m", formatExact(kernel.cutoff())},
                       {"kernel_std_m", formatExact(kernel.standardDeviation())},
                       {"time_average", s.average.describe()},
                       {"stress_sign", "compression positive"},
                       {"particles", s.read.particles},
                       {"pairs", s.read.pairs},
                       {"walls", s.read.walls}};
    auto writeAll = [&](const std::string& stem, const std::vector<CgField>& fields, const CgAttributes& at) {
        if (has("vti")) writeCgVti(stem + ".vti", grid, fields), result.files.push_back(stem + ".vti");
        if (has("h5")) writeCgHdf5(stem + ".h5", grid, fields, at), result.files.push_back(stem + ".h5");
        if (has("csv")) writeCgCsv(stem + ".csv", grid, fields), result.files.push_back(stem + ".csv");
    };

    std::unique_ptr<CgSeriesCsv> series;
    if (grid.dims() == 0) {
        series = std::make_unique<CgSeriesCsv>(s.out + "_series.csv", grid);
        result.files.push_back(s.out + "_series.csv");
    }
    std::vector<std::pair<double, std::string>> pvd;
    CgAverager average(cg, s.threads);
    for (std::size_t c = 0; c < chosen.size(); ++c) {
        const std::size_t k = chosen[c];
        const auto t0 = clock::now();
        const CgSnapshot snap = c == 0 ? first : reader.read(steps[k]);
        const auto t1 = clock::now();
        const CgRawFields raw = average.add(snap, weights[k]);
        const auto t2 = clock::now();
        result.windowMass += weights[k] * windowMass(grid, snap);
        if (s.every || series) {
            const auto fields = cgFields(grid, raw, fopt);
            if (series) series->append(snap.time, snap.step, fields);
            if (s.every) {
                const std::string stem = s.out + "_" + std::to_string(snap.step);
                CgAttributes at = attrs;
                at.push_back({"time", formatExact(snap.time)});
                at.push_back({"step", std::to_string(snap.step)});
                writeAll(stem, fields, at);
                pvd.emplace_back(snap.time, std::filesystem::path(stem).filename().string() + ".vti");
            }
        }
        log << "  snapshot " << c + 1 << "/" << chosen.size() << ": step " << snap.step << ", t = " << snap.time
            << ", " << snap.particles.size() << " particles, " << snap.pairs.size() << " pair and "
            << snap.walls.size() << " wall contacts; read "
            << std::chrono::duration<double>(t1 - t0).count() << " s, fields "
            << std::chrono::duration<double>(t2 - t1).count() << " s, weight " << weights[k] << "\n";
        log.flush();
    }
    result.snapshots = chosen.size();
    result.gridMass = gridMass(grid, average.raw());
    attrs.push_back({"snapshots", std::to_string(chosen.size())});
    writeAll(s.out, average.fields(fopt), attrs);
    if (s.every && has("vti")) {
        writeCgPvd(s.out + ".pvd", pvd);
        result.files.push_back(s.out + ".pvd");
    }
    log << "  mass on the grid " << result.gridMass << " kg, particle mass in the window " << result.windowMass
        << " kg (they differ by the kernel's reach across the window's edges)\n";
    log << "  wrote";
    for (const auto& f : result.files) log << " " << f;
    log << "\n  done in " << std::chrono::duration<double>(clock::now() - start).count() << " s\n";
    return result;
}

}  // namespace granair
