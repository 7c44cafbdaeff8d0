list(APPEND GRANAIR_COUPLING_SOURCES monitor/StageTimers.cpp monitor/MassFlowRate.cpp monitor/Progress.cpp
  monitor/ResourceUsage.cpp)
