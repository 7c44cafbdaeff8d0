// CgAverager.hpp: CG fields averaged over snapshots, as a library call.
//
//   CoarseGrainer cg(CgGrid(CgCoordinates::Z, box, {{1, 1, 80}}), CgKernel(shape, 1));
//   CgAverager avg(cg);
//   for (const CgSnapshot& s : snapshots) avg.add(s, 1.0 / snapshots.size());
//   const auto fields = avg.fields();   // pressure, shear_rate, inertial_number, ...
//
// A box-region average (e.g. for a mu(I) calibration from a shear cell's
// bulk) is the same with CgGrid(CgCoordinates::O, box, {{1, 1, 1}}) and
// CgKernel(nullptr, 0); a profile across the gap (Z, X, ...) also gives the
// shear rate. Weights: CgTimeAverage::weights (uniform or Gaussian in time).
// granairCG (CgRun) uses this class.
#pragma once
#include <vector>

#include "cg/CgFields.hpp"
#include "cg/CoarseGrainer.hpp"

namespace granair {

class CgAverager {
public:
    explicit CgAverager(const CoarseGrainer& cg, int threads = 0)
        : cg_(cg), threads_(threads), sum_(cg.grid().size()) {}

    // Add one snapshot with its weight; returns its raw fields (for per-snapshot output).
    CgRawFields add(const CgSnapshot& s, double weight, CgCounts* counts = nullptr) {
        CgRawFields raw = cg_.compute(s, threads_, counts);
        sum_.addScaled(raw, weight);
        weight_ += weight;
        spin_ = spin_ || s.hasSpin;
        return raw;
    }
    double weight() const { return weight_; }  // sum of the weights added
    const CgRawFields& raw() const { return sum_; }
    std::vector<CgField> fields(CgFieldOptions opt = {}) const {
        opt.spin = opt.spin || spin_;
        return cgFields(cg_.grid(), sum_, opt);
    }

private:
    const CoarseGrainer& cg_;
    int threads_;
    CgRawFields sum_;
    double weight_ = 0.0;
    bool spin_ = false;
};

}  // namespace granair
