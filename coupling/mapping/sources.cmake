list(APPEND GRANAIR_COUPLING_SOURCES mapping/BoxMesh.cpp mapping/CellLocator.cpp)
