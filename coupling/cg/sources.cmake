# cg/: CG fields, continuum fields from DEM particles and contacts
# (docs/cg-fields.md). The granairCG command is in cg/app.cmake.
list(APPEND GRANAIR_COUPLING_SOURCES
  cg/GaussLegendre.cpp
  cg/CgKernel.cpp
  cg/GaussKernel.cpp
  cg/HeavisideKernel.cpp
  cg/LucyKernel.cpp
  cg/registerCgKernels.cpp
  cg/CgGrid.cpp
  cg/CgPointTerms.cpp
  cg/CoarseGrainer.cpp
  cg/CgTimeAverage.cpp
  cg/CgFields.cpp
  cg/LiggghtsDump.cpp
  cg/CgSnapshotReader.cpp
  cg/CgWriters.cpp
  cg/CgOptions.cpp
  cg/CgRun.cpp)
