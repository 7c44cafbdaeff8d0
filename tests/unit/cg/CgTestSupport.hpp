// CgTestSupport.hpp: kernels, snapshots and integrals shared by the CG tests.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "CgQuadrature.hpp"
#include "cg/CgGrid.hpp"
#include "cg/CgKernel.hpp"
#include "cg/CoarseGrainer.hpp"
#include "cg/GaussKernel.hpp"
#include "cg/HeavisideKernel.hpp"
#include "cg/LucyKernel.hpp"

namespace granair::cgtest {

// A kernel shape by name and width (gauss: width w, cutoff k widths).
inline std::shared_ptr<const CgKernelShape> shape(const std::string& name, double width, double k = 3.0) {
    if (name == "gauss") return std::make_shared<GaussKernel>(width, k);
    if (name == "heaviside") return std::make_shared<HeavisideKernel>(width);
    return std::make_shared<LucyKernel>(width);
}

// Every registered kernel at two widths: narrow and wide against d = 1 mm.
struct KernelCase {
    std::string name;
    double width, k;
};
inline std::vector<KernelCase> kernelCases() {
    return {{"gauss", 0.3e-3, 3.0},  {"gauss", 1.5e-3, 3.0}, {"gauss", 0.5e-3, 2.0},
            {"heaviside", 0.7e-3, 0}, {"heaviside", 3e-3, 0}, {"lucy", 0.7e-3, 0},
            {"lucy", 3e-3, 0}};
}

inline const std::vector<CgCoordinates>& cartesianSystems() {
    static const std::vector<CgCoordinates> s{CgCoordinates::XYZ, CgCoordinates::XY, CgCoordinates::XZ,
                                              CgCoordinates::YZ,  CgCoordinates::X,  CgCoordinates::Y,
                                              CgCoordinates::Z,   CgCoordinates::O};
    return s;
}

// A grain on a coarse grid over a 20 mm box (the grid itself is not used by evaluateAt).
inline CoarseGrainer makeCg(CgCoordinates c, const KernelCase& kc, const Box& window) {
    const CgGrid g(c, window, {{4, 4, 4}});
    return CoarseGrainer(g, CgKernel(shape(kc.name, kc.width, kc.k), g.kernelDims()));
}

inline Box testWindow() { return Box{Vec3(-0.01, -0.008, -0.012), Vec3(0.012, 0.01, 0.009)}; }

// Integrate raw field components over a Cartesian system's resolved space
// (times the averaged volume): nodes from the breaks, fields by evaluateAt.
inline std::vector<double> integrateCartesian(const CoarseGrainer& cg, const CgSnapshot& snap,
                                              const Breaks& breaks, int n,
                                              const std::function<Vec3(const double*)>& toPoint) {
    const auto& grid = cg.grid();
    const auto nodes = nestedRule(grid.dims(), breaks, n);
    std::vector<double> sum(cgraw::count, 0.0);
    constexpr std::size_t batch = 100000;  // points per evaluateAt call (memory)
    for (std::size_t b0 = 0; b0 < nodes.size(); b0 += batch) {
        const std::size_t b1 = std::min(nodes.size(), b0 + batch);
        std::vector<Vec3> points;
        points.reserve(b1 - b0);
        for (std::size_t p = b0; p < b1; ++p) points.push_back(toPoint(nodes[p].u));
        const CgRawFields f = cg.evaluateAt(points, snap);
        for (std::size_t p = b0; p < b1; ++p)
            for (int c = 0; c < cgraw::count; ++c) sum[c] += nodes[p].w * f.at(p - b0)[c];
    }
    for (auto& s : sum) s *= grid.averagedVolume();
    return sum;
}

// The resolved axes of a Cartesian system, in order.
inline std::vector<int> resolvedAxes(CgCoordinates c) {
    std::vector<int> a;
    const auto r = cgResolvedAxes(c);
    for (int i = 0; i < 3; ++i)
        if (r[i]) a.push_back(i);
    return a;
}

}  // namespace granair::cgtest
