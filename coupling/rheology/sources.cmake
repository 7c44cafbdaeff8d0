list(APPEND GRANAIR_COUPLING_SOURCES
  rheology/ShearRate.cpp
  rheology/MuI.cpp
  rheology/LatzSchmidt.cpp
  rheology/GranularTemperatureModel.cpp
  rheology/registerRheologies.cpp)
