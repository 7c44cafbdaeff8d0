# FindOpenFOAM: OpenFOAM v1912 from Debian packages (libraries in /usr/lib) plus
# the matching header tree from Debian's source package (lnInclude generated).
#
# Cache variables:
#   OPENFOAM_SRC_DIR  the OpenFOAM source tree root (becomes WM_PROJECT_DIR at run time)
# Defines the imported target OpenFOAM::OpenFOAM and OPENFOAM_FOUND.
set(_granair_foam_default "$ENV{GRANAIR_OPENFOAM_SRC}")
if(NOT _granair_foam_default)
  set(_granair_foam_default "${PROJECT_SOURCE_DIR}/.cache/openfoam-OpenFOAM-v1912.200626")
endif()
set(OPENFOAM_SRC_DIR "${_granair_foam_default}" CACHE PATH
    "OpenFOAM v1912 source tree with lnInclude directories (made by tools/install-deps.sh)")

set(_foam_hint "Run ./tools/install-deps.sh (or ./granair deps) to install OpenFOAM and its headers, or set -DOPENFOAM_SRC_DIR=<tree>.")
if(NOT EXISTS "${OPENFOAM_SRC_DIR}/src/finiteVolume/lnInclude/fvCFD.H")
  message(FATAL_ERROR "OpenFOAM headers not found: ${OPENFOAM_SRC_DIR}/src/finiteVolume/lnInclude/fvCFD.H is missing.\n${_foam_hint}")
endif()
if(NOT EXISTS "${OPENFOAM_SRC_DIR}/etc/controlDict")
  message(FATAL_ERROR "OpenFOAM tree ${OPENFOAM_SRC_DIR} has no etc/controlDict.\n${_foam_hint}")
endif()

foreach(_lib OpenFOAM finiteVolume meshTools)
  find_library(OPENFOAM_${_lib}_LIBRARY NAMES ${_lib} PATHS /usr/lib NO_DEFAULT_PATH)
  if(NOT OPENFOAM_${_lib}_LIBRARY)
    message(FATAL_ERROR "OpenFOAM library lib${_lib}.so not found in /usr/lib (Debian packages openfoam, libopenfoam).\n${_foam_hint}")
  endif()
endforeach()
find_library(OPENFOAM_Pstream_LIBRARY NAMES Pstream PATHS /usr/lib/openmpi-system NO_DEFAULT_PATH)
if(NOT OPENFOAM_Pstream_LIBRARY)
  message(FATAL_ERROR "OpenFOAM's MPI Pstream (/usr/lib/openmpi-system/libPstream.so) not found.\n${_foam_hint}")
endif()

set(_s "${OPENFOAM_SRC_DIR}/src")
add_library(OpenFOAM::OpenFOAM INTERFACE IMPORTED)
target_compile_definitions(OpenFOAM::OpenFOAM INTERFACE
  OMPI_SKIP_MPICXX OPENFOAM=1912 WM_DP WM_LABEL_SIZE=32 NoRepository linux64)
target_compile_options(OpenFOAM::OpenFOAM INTERFACE -m64 -ftemplate-depth-100
  -Wno-old-style-cast -Wno-deprecated-copy -Wno-unused-parameter)
# SYSTEM: warnings inside OpenFOAM's headers are not ours to fix.
target_include_directories(OpenFOAM::OpenFOAM SYSTEM INTERFACE
  ${_s}/finiteVolume/lnInclude ${_s}/meshTools/lnInclude
  ${_s}/OpenFOAM/lnInclude ${_s}/OSspecific/POSIX/lnInclude)
# --no-as-needed: OpenFOAM registers models in static initialisers, so a
# library must be linked even when no symbol of it is referenced directly.
target_link_options(OpenFOAM::OpenFOAM INTERFACE -Wl,--no-as-needed)
target_link_libraries(OpenFOAM::OpenFOAM INTERFACE
  ${OPENFOAM_finiteVolume_LIBRARY} ${OPENFOAM_meshTools_LIBRARY}
  ${OPENFOAM_OpenFOAM_LIBRARY} ${OPENFOAM_Pstream_LIBRARY} MPI::MPI_CXX dl m)
set(OPENFOAM_FOUND TRUE)
message(STATUS "OpenFOAM v1912: headers ${OPENFOAM_SRC_DIR}, libraries /usr/lib")
