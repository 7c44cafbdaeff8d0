list(APPEND GRANAIR_COUPLING_SOURCES output/TimeSeriesWriter.cpp)
