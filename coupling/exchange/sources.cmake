# exchange/: many-to-many routing of particles between the DEM and CFD decompositions.
list(APPEND GRANAIR_COUPLING_SOURCES
  exchange/SparseExchange.cpp
  exchange/RankBoxIndex.cpp
  exchange/TagCellHints.cpp
  exchange/ParticleExchange.cpp)
