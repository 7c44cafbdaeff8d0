# granair_foam_lninclude(<out-var> <dir>...)
#
# Build-local lnInclude trees for OpenFOAM source directories whose headers
# tools/install-deps.sh does not link (e.g. twoPhaseEulerFoam's phase system
# and interfacial models, the thermophysical and phase-compressible
# turbulence headers). For every <dir> (relative to OPENFOAM_SRC_DIR) this
# makes <build>/foam-lnInclude/<dir>/ holding a symbolic link to every
# header and template source below <dir>, as OpenFOAM's wmakeLnInclude does
# (same file patterns, same pruned folders: lnInclude, Make, config, noLink),
# and appends that folder to <out-var>.
#
# Why here and not in the shared source tree: the tree in .cache is shared
# by several builds and stamped done by install-deps.sh; links made in the
# build directory need no change of it, are made again by every fresh
# configure, and vanish with the build.
# A missing <dir> stops the configure with its path (never a build that
# fails later on a missing header).
function(granair_foam_lninclude out)
  set(dirs ${${out}})
  foreach(rel ${ARGN})
    set(src "${OPENFOAM_SRC_DIR}/${rel}")
    if(NOT IS_DIRECTORY "${src}")
      message(FATAL_ERROR "OpenFOAM source directory ${src} does not exist (needed for its headers).\n"
                          "Run ./tools/install-deps.sh (or ./granair deps), or set -DOPENFOAM_SRC_DIR=<tree>.")
    endif()
    set(dst "${PROJECT_BINARY_DIR}/foam-lnInclude/${rel}")
    set(stamp "${dst}/.granair-lninclude")
    if(NOT EXISTS "${stamp}")
      file(REMOVE_RECURSE "${dst}")
      file(MAKE_DIRECTORY "${dst}")
      file(GLOB_RECURSE files LIST_DIRECTORIES false RELATIVE "${src}"
           "${src}/*.[CHch]" "${src}/*.cc" "${src}/*.hh" "${src}/*.[ch]xx"
           "${src}/*.[ch]pp" "${src}/*.type")
      set(n 0)
      foreach(f ${files})
        if(f MATCHES "(^|/)(lnInclude|Make|config|noLink)/")
          continue()
        endif()
        get_filename_component(name "${f}" NAME)
        if(NOT EXISTS "${dst}/${name}")
          file(CREATE_LINK "${src}/${f}" "${dst}/${name}" SYMBOLIC)
          math(EXPR n "${n} + 1")
        endif()
      endforeach()
      if(n EQUAL 0)
        message(FATAL_ERROR "OpenFOAM source directory ${src} holds no headers")
      endif()
      file(WRITE "${stamp}" "${n} links from ${src}\n")
    endif()
    list(APPEND dirs "${dst}")
  endforeach()
  set(${out} ${dirs} PARENT_SCOPE)
endfunction()
