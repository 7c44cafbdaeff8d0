# Void-fraction models: one name per line, the class in
# voidfraction/<Name>.hpp/.cpp (with typeName and fromDictionary), parameters
# for the shared tests in tests/data/voidfraction/<typeName>.dict. This list is
# the only place a new model is named: it builds the file and registers it
# (cmake/GranairModels.cmake, docs/adding-a-model.md).
granair_models(FAMILY voidfraction LIST VoidFractionModelList MODELS
  CentreVoidFraction
  DividedVoidFraction
  GaussianVoidFraction
)
# The rest of the module.
list(APPEND GRANAIR_COUPLING_SOURCES
  voidfraction/SolidVolume.cpp
  voidfraction/registerVoidFractionModels.cpp)
