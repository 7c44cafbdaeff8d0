list(APPEND GRANAIR_COUPLING_SOURCES
  drag/DragInputCheck.cpp
  drag/ErgunGidaspow.cpp
  drag/WenYu.cpp
  drag/DiFelice.cpp
  drag/SchillerNaumann.cpp
  drag/BeetstraVanDerHoefKuipers.cpp
  drag/parcelBeta.cpp
  drag/registerDragLaws.cpp)
