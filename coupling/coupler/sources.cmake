list(APPEND GRANAIR_COUPLING_SOURCES coupler/BedDrag.cpp coupler/CouplingSettings.cpp coupler/CouplingStep.cpp
  coupler/RunSettings.cpp)
