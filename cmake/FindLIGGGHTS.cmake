# FindLIGGGHTS: LIGGGHTS-PUBLIC 3.8.0 from Debian (liggghts, libliggghts-dev).
# Defines the imported target LIGGGHTS::LIGGGHTS and LIGGGHTS_FOUND.
find_path(LIGGGHTS_INCLUDE_DIR NAMES library.h fix_external.h PATHS /usr/include/liggghts NO_DEFAULT_PATH)
find_library(LIGGGHTS_LIBRARY NAMES liggghts)
if(NOT LIGGGHTS_INCLUDE_DIR OR NOT LIGGGHTS_LIBRARY)
  message(FATAL_ERROR "LIGGGHTS not found (need /usr/include/liggghts/library.h and libliggghts.so from the Debian packages liggghts and libliggghts-dev).\nRun ./tools/install-deps.sh (or ./granair deps).")
endif()
add_library(LIGGGHTS::LIGGGHTS INTERFACE IMPORTED)
target_include_directories(LIGGGHTS::LIGGGHTS SYSTEM INTERFACE ${LIGGGHTS_INCLUDE_DIR})
target_link_libraries(LIGGGHTS::LIGGGHTS INTERFACE ${LIGGGHTS_LIBRARY} MPI::MPI_CXX)
set(LIGGGHTS_FOUND TRUE)
message(STATUS "LIGGGHTS: ${LIGGGHTS_LIBRARY}")
