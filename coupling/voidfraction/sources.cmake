list(APPEND GRANAIR_COUPLING_SOURCES
  voidfraction/CentreVoidFraction.cpp
  voidfraction/DividedVoidFraction.cpp
  voidfraction/GaussianVoidFraction.cpp
  voidfraction/SolidVolume.cpp
  voidfraction/registerVoidFractionModels.cpp)
