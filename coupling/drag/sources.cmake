# Drag laws: one name per line, the class in drag/<Name>.hpp/.cpp (with
# typeName and fromDictionary), reference data in tests/data/drag/<Name>.py
# and <Name>.dat. This list is the only place a new law is named: it builds
# the file and registers it (cmake/GranairModels.cmake, docs/adding-a-model.md).
granair_models(FAMILY drag LIST DragLawList MODELS
  BeetstraVanDerHoefKuipers
  DiFelice
  ErgunGidaspow
  SchillerNaumann
  WenYu
)
# The rest of the module.
list(APPEND GRANAIR_COUPLING_SOURCES
  drag/DragInputCheck.cpp
  drag/parcelBeta.cpp
  drag/registerDragLaws.cpp)
