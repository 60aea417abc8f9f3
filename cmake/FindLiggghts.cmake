# FindLiggghts.cmake - an installed LIGGGHTS library with its full header set (Debian:
# libliggghts-dev, LIGGGHTS 3.8.0: /usr/include/liggghts and libliggghts.so).
#
#   Liggghts_FOUND, LIGGGHTS_INCLUDE_DIR, LIGGGHTS_LIBRARY, LIGGGHTS_VERSION ("23 Nov 2013":
#   the LAMMPS version LIGGGHTS 3.8 was forked from, the only version macro its headers carry)
#   target Liggghts::liggghts  (headers as SYSTEM includes, the library, MPI)
#
# Hints: -DLIGGGHTS_INCLUDE_DIR=<dir with lammps.h and signal_handling.h>,
#        -DLIGGGHTS_LIBRARY=<libliggghts.so>.
find_path(LIGGGHTS_INCLUDE_DIR NAMES signal_handling.h lammps.h fix_wall_gran.h
          PATH_SUFFIXES liggghts DOC "LIGGGHTS headers (libliggghts-dev)")
find_library(LIGGGHTS_LIBRARY NAMES liggghts DOC "LIGGGHTS library (libliggghts-dev)")

if(LIGGGHTS_INCLUDE_DIR AND EXISTS "${LIGGGHTS_INCLUDE_DIR}/version.h")
  file(STRINGS "${LIGGGHTS_INCLUDE_DIR}/version.h" _lig_version REGEX "LAMMPS_VERSION")
  string(REGEX REPLACE ".*\"(.*)\".*" "\\1" LIGGGHTS_VERSION "${_lig_version}")
endif()
if(LIGGGHTS_INCLUDE_DIR AND NOT EXISTS "${LIGGGHTS_INCLUDE_DIR}/fix_wall_gran.h")
  set(LIGGGHTS_INCLUDE_DIR LIGGGHTS_INCLUDE_DIR-NOTFOUND)    # a LAMMPS, not a LIGGGHTS
endif()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(Liggghts REQUIRED_VARS LIGGGHTS_LIBRARY LIGGGHTS_INCLUDE_DIR)

if(Liggghts_FOUND AND NOT TARGET Liggghts::liggghts)
  find_package(MPI REQUIRED COMPONENTS CXX)
  add_library(Liggghts::liggghts UNKNOWN IMPORTED)
  set_target_properties(Liggghts::liggghts PROPERTIES
    IMPORTED_LOCATION "${LIGGGHTS_LIBRARY}"
    INTERFACE_SYSTEM_INCLUDE_DIRECTORIES "${LIGGGHTS_INCLUDE_DIR}"
    INTERFACE_INCLUDE_DIRECTORIES "${LIGGGHTS_INCLUDE_DIR}")
  target_link_libraries(Liggghts::liggghts INTERFACE MPI::MPI_CXX)
endif()
mark_as_advanced(LIGGGHTS_INCLUDE_DIR LIGGGHTS_LIBRARY)
