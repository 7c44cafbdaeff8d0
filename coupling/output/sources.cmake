list(APPEND GRANAIR_COUPLING_SOURCES output/TimeSeriesWriter.cpp)
list(APPEND GRANAIR_COUPLING_SOURCES output/ParticleVtkWriter.cpp)
list(APPEND GRANAIR_COUPLING_SOURCES output/FormatExact.cpp output/StepSeries.cpp)
list(APPEND GRANAIR_COUPLING_SOURCES output/Hdf5Util.cpp)
