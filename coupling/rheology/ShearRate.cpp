// ShearRate.cpp: see ShearRate.hpp.
#include "rheology/ShearRate.hpp"

#include <cmath>

namespace granair {

double shearRate(const Eigen::Matrix3d& gradU) {
    const Eigen::Matrix3d d = 0.5 * (gradU + gradU.transpose());
    return std::sqrt(2.0 * d.cwiseProduct(d).sum());
}

double deviatoricShearRate(const Eigen::Matrix3d& gradU) {
    Eigen::Matrix3d d = 0.5 * (gradU + gradU.transpose());
    d.diagonal().array() -= d.trace() / 3.0;
    return std::sqrt(2.0 * d.cwiseProduct(d).sum());
}

}  // namespace granair
