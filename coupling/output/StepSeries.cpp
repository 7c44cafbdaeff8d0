// StepSeries.cpp: see StepSeries.hpp.
#include "output/StepSeries.hpp"

#include "core/Error.hpp"

namespace granair {

std::vector<Column> StepSeries::columns(const Layout& layout) {
    std::vector<Column> cols{{"t", "s"}};
    if (layout.discharge) {
        cols.push_back({"discharged_kg", "kg"});
        cols.push_back({"mass_flow_kg_s", "kg/s"});
    }
    cols.push_back({"particles", "1"});
    if (layout.air) {
        cols.push_back({"voidfraction_min", "1"});
        cols.push_back({"voidfraction_floor_hits", "cells"});
        cols.insert(cols.end(), layout.monitorColumns.begin(), layout.monitorColumns.end());
    }
    return cols;
}

StepSeries::StepSeries(MPI_Comm comm, const std::string& stem, Layout layout, long keepRows)
    : layout_(std::move(layout)),
      writer_(std::make_unique<TimeSeriesWriter>(comm, stem, columns(layout_), keepRows)) {}

void StepSeries::append(const StepRecord& r) {
    if (layout_.air && r.monitors.size() != layout_.monitorColumns.size())
        fail("StepSeries: ", r.monitors.size(), " monitor values for ", layout_.monitorColumns.size(), " columns");
    row_.assign(1, r.t);
    if (layout_.discharge) {
        row_.push_back(r.dischargedKg);
        row_.push_back(r.massFlowKgS);
    }
    row_.push_back(r.particles);
    if (layout_.air) {
        row_.push_back(r.voidFractionMin);
        row_.push_back(r.floorHits);
        row_.insert(row_.end(), r.monitors.begin(), r.monitors.end());
    }
    writer_->append(row_);
    last_ = r;
}

long StepSeries::rows() const { return writer_->rows(); }

void StepSeries::close() { writer_->close(); }

}  // namespace granair
