// Hdf5Util.cpp: see Hdf5Util.hpp.
#include "output/Hdf5Util.hpp"

namespace granair {

bool writeStringAttribute(hid_t object, const char* name, const std::string& value) {
    const hid_t type = H5Tcopy(H5T_C_S1);
    const hid_t space = H5Screate(H5S_SCALAR);
    bool ok = type >= 0 && space >= 0 && H5Tset_size(type, value.size() + 1) >= 0 &&
              H5Tset_strpad(type, H5T_STR_NULLTERM) >= 0;
    if (ok) {
        const hid_t attr = H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
        ok = attr >= 0 && H5Awrite(attr, type, value.c_str()) >= 0;
        if (attr >= 0) H5Aclose(attr);
    }
    if (space >= 0) H5Sclose(space);
    if (type >= 0) H5Tclose(type);
    return ok;
}

}  // namespace granair
