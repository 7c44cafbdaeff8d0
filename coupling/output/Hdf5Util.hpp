// Hdf5Util.hpp: what the HDF5 writers share (TimeSeriesWriter, the CG fields'
// writer): a guard that silences HDF5's error stack (failures become our own
// messages), and a string attribute.
#pragma once
#include <hdf5.h>

#include <string>

namespace granair {

// HDF5 prints its error stack to stderr by default; we turn failures into
// exceptions with our own message instead, so silence it while we work.
class QuietHdf5 {
public:
    QuietHdf5() {
        H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
        H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    }
    ~QuietHdf5() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }
    QuietHdf5(const QuietHdf5&) = delete;
    QuietHdf5& operator=(const QuietHdf5&) = delete;

private:
    H5E_auto2_t func_ = nullptr;
    void* data_ = nullptr;
};

// Fixed-length, null-terminated string attribute on an HDF5 object; false on failure.
bool writeStringAttribute(hid_t object, const char* name, const std::string& value);

}  // namespace granair
