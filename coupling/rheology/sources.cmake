# Rheologies: one name per line, the class in rheology/<Name>.hpp/.cpp (with
# typeName and fromDictionary), reference data in tests/data/rheology/
# <typeName>.py and <typeName>[.<variant>].dat. This list is the only place a
# new rheology is named: it builds the file and registers it
# (cmake/GranairModels.cmake, docs/adding-a-model.md).
granair_models(FAMILY rheology LIST RheologyList MODELS
  LatzSchmidt
  MuI
)
# The rest of the module.
list(APPEND GRANAIR_COUPLING_SOURCES
  rheology/ShearRate.cpp
  rheology/GranularTemperatureModel.cpp
  rheology/registerRheologies.cpp)
