# FindLammpsHeaders.cmake - locate the LAMMPS headers (and, if available, the library)
# hardcontact is compiled against.
#
# Two modes:
#
#  system (default)
#     The Debian/Ubuntu liblammps (find_package(LAMMPS CONFIG), else pkg-config liblammps)
#     plus the full header set of the SAME version, cached by .ci/setup.sh in
#     <source>/.cache/lammps-headers/<debian-source-version>/ (liblammps-dev only ships 34
#     headers; a fix needs e.g. neigh_request.h, fmt/ and lammpsplugin.h).
#     Override the header directory with -DLAMMPS_HEADERS_DIR=<dir>.
#
#  source (-DLAMMPS_SOURCE_DIR=/path/to/lammps/src)
#     Headers of another LAMMPS source tree. Nothing is linked: a LAMMPS plugin is a MODULE
#     library whose LAMMPS (and MPI) symbols are resolved by the lmp that loads it.
#     -DLAMMPS_SIZES=smallbig|bigbig|smallsmall must match how that LAMMPS was built.
#     -DLAMMPS_MPI_STUBS=ON compiles against <src>/STUBS/mpi.h for a LAMMPS built without MPI.
#
# Results:
#   LammpsHeaders_FOUND
#   LAMMPS_HEADERS_MODE          "system" or "source"
#   LAMMPS_HEADERS_DIR           directory holding version.h, fix.h, neigh_request.h, ...
#   LAMMPS_HEADERS_VERSION       e.g. "29 Sep 2021 Update 2" (from version.h)
#   LAMMPS_HEADERS_VERSION_NUM   e.g. 20210929
#   LAMMPS_HEADERS_INCLUDE_DIRS, LAMMPS_HEADERS_DEFINITIONS   (also for try_compile checks)
#   LAMMPS_HAS_LIBRARY           TRUE when a liblammps to link executables against was found
#   target hardcontact::lammps_headers  INTERFACE: include dirs (SYSTEM) + definitions + MPI
#                                        includes and MPI C-only definitions; no libraries
#   target hardcontact::lammps           (system mode only) the library + MPI, for executables
#
# MPI: code for a plugin must see the MPI C API only, as LAMMPS itself does (it builds with
# MPI_CXX_SKIP_MPICXX). Open MPI's / MPICH's mpi.h otherwise pulls in the C++ bindings, whose
# inline code references libmpi_cxx (MPI::Comm::Comm(), ompi_mpi_cxx_op_intercept, ...); an lmp
# not linked to libmpi_cxx then refuses the plugin at `plugin load` (dlopen: undefined symbol
# _ZN3MPI8Datatype4FreeEv). Hence OMPI_SKIP_MPICXX / MPICH_SKIP_MPICXX (MPI_CXX_COMPILE_DEFINITIONS)
# on hardcontact::lammps_headers, which the plugin's objects compile with.

include(FindPackageHandleStandardArgs)

set(LAMMPS_SOURCE_DIR "" CACHE PATH
    "Path to a LAMMPS src/ directory: build only the plugin against its headers")
set(LAMMPS_HEADERS_DIR "" CACHE PATH
    "Full LAMMPS header set matching the system liblammps (default: .cache/lammps-headers/<version>)")
set(LAMMPS_SIZES "smallbig" CACHE STRING "LAMMPS integer sizes (source mode): smallbig, bigbig or smallsmall")
set_property(CACHE LAMMPS_SIZES PROPERTY STRINGS smallbig bigbig smallsmall)
option(LAMMPS_MPI_STUBS "Source mode: compile against <LAMMPS_SOURCE_DIR>/STUBS/mpi.h (serial LAMMPS)" OFF)

set(LAMMPS_HAS_LIBRARY FALSE)
set(LAMMPS_HEADERS_DEFINITIONS "")
set(_lh_mpi_includes "")
set(_lh_mpi_definitions "")

# "29 Sep 2021" -> 20210929
function(_lh_date_to_num date out)
  set(_months Jan Feb Mar Apr May Jun Jul Aug Sep Oct Nov Dec)
  if(date MATCHES "^([0-9]+) ([A-Za-z]+) ([0-9]+)$")
    list(FIND _months "${CMAKE_MATCH_2}" _m)
    math(EXPR _m "${_m} + 1")
    math(EXPR _d "${CMAKE_MATCH_1}")     # drops leading zeros
    if(_m LESS 10)
      set(_m "0${_m}")
    endif()
    if(_d LESS 10)
      set(_d "0${_d}")
    endif()
    set(${out} "${CMAKE_MATCH_3}${_m}${_d}" PARENT_SCOPE)
  else()
    set(${out} "" PARENT_SCOPE)
  endif()
endfunction()

function(_lh_read_version dir out_str out_num)
  set(_str "")
  set(_num "")
  if(EXISTS "${dir}/version.h")
    file(STRINGS "${dir}/version.h" _v REGEX "#define LAMMPS_(VERSION|UPDATE) ")
    foreach(_l IN LISTS _v)
      if(_l MATCHES "LAMMPS_VERSION \"([^\"]*)\"")
        set(_date "${CMAKE_MATCH_1}")
      elseif(_l MATCHES "LAMMPS_UPDATE \"([^\"]*)\"")
        set(_upd "${CMAKE_MATCH_1}")
      endif()
    endforeach()
    set(_str "${_date}")
    if(_upd AND NOT _upd STREQUAL "Development")
      string(APPEND _str " ${_upd}")
    endif()
    _lh_date_to_num("${_date}" _num)
  endif()
  set(${out_str} "${_str}" PARENT_SCOPE)
  set(${out_num} "${_num}" PARENT_SCOPE)
endfunction()

# ------------------------------------------------------------------------------------- source
if(LAMMPS_SOURCE_DIR)
  set(LAMMPS_HEADERS_MODE "source")
  get_filename_component(LAMMPS_SOURCE_DIR "${LAMMPS_SOURCE_DIR}" ABSOLUTE)
  if(NOT EXISTS "${LAMMPS_SOURCE_DIR}/fix.h" AND EXISTS "${LAMMPS_SOURCE_DIR}/src/fix.h")
    message(STATUS "LAMMPS_SOURCE_DIR: using ${LAMMPS_SOURCE_DIR}/src")
    set(LAMMPS_SOURCE_DIR "${LAMMPS_SOURCE_DIR}/src")
  endif()
  foreach(_h version.h fix.h neigh_request.h lammpsplugin.h)
    if(NOT EXISTS "${LAMMPS_SOURCE_DIR}/${_h}")
      message(FATAL_ERROR "LAMMPS_SOURCE_DIR=${LAMMPS_SOURCE_DIR} has no ${_h}: "
                          "point it at the src/ folder of a LAMMPS source tree (with the PLUGIN "
                          "package, for lammpsplugin.h).")
    endif()
  endforeach()
  set(LAMMPS_HEADERS_DIR "${LAMMPS_SOURCE_DIR}")
  set(LAMMPS_HEADERS_INCLUDE_DIRS "${LAMMPS_SOURCE_DIR}")
  if(LAMMPS_SIZES STREQUAL "bigbig")
    list(APPEND LAMMPS_HEADERS_DEFINITIONS LAMMPS_BIGBIG)
  elseif(LAMMPS_SIZES STREQUAL "smallsmall")
    list(APPEND LAMMPS_HEADERS_DEFINITIONS LAMMPS_SMALLSMALL)
  elseif(LAMMPS_SIZES STREQUAL "smallbig")
    list(APPEND LAMMPS_HEADERS_DEFINITIONS LAMMPS_SMALLBIG)
  else()
    message(FATAL_ERROR "LAMMPS_SIZES must be smallbig, bigbig or smallsmall, not '${LAMMPS_SIZES}'")
  endif()
  if(LAMMPS_MPI_STUBS)
    if(NOT EXISTS "${LAMMPS_SOURCE_DIR}/STUBS/mpi.h")
      message(FATAL_ERROR "LAMMPS_MPI_STUBS=ON but ${LAMMPS_SOURCE_DIR}/STUBS/mpi.h does not exist")
    endif()
    set(_lh_mpi_includes "${LAMMPS_SOURCE_DIR}/STUBS")
  else()
    find_package(MPI REQUIRED COMPONENTS CXX)
    set(_lh_mpi_includes ${MPI_CXX_INCLUDE_DIRS})
    set(_lh_mpi_definitions ${MPI_CXX_COMPILE_DEFINITIONS} MPICH_SKIP_MPICXX OMPI_SKIP_MPICXX)
  endif()

# ------------------------------------------------------------------------------------- system
else()
  set(LAMMPS_HEADERS_MODE "system")

  # the library: CMake package config (Debian ships one), else pkg-config
  find_package(LAMMPS CONFIG QUIET)
  set(_lh_lib_version "")
  if(TARGET LAMMPS::lammps)
    set(LAMMPS_HAS_LIBRARY TRUE)
    set(_lh_lib_version "${LAMMPS_VERSION}")
    get_target_property(_lh_defs LAMMPS::lammps INTERFACE_COMPILE_DEFINITIONS)
    if(_lh_defs)
      list(APPEND LAMMPS_HEADERS_DEFINITIONS ${_lh_defs})
    endif()
    set(_lh_how "CMake package ${LAMMPS_DIR}")
  else()
    find_package(PkgConfig QUIET)
    if(PKG_CONFIG_FOUND)
      pkg_check_modules(PC_LIBLAMMPS QUIET IMPORTED_TARGET liblammps)
    endif()
    if(PC_LIBLAMMPS_FOUND)
      set(LAMMPS_HAS_LIBRARY TRUE)
      set(_lh_lib_version "${PC_LIBLAMMPS_VERSION}")
      foreach(_f IN LISTS PC_LIBLAMMPS_CFLAGS_OTHER)
        if(_f MATCHES "^-D(.*)")
          list(APPEND LAMMPS_HEADERS_DEFINITIONS "${CMAKE_MATCH_1}")
        endif()
      endforeach()
      set(_lh_how "pkg-config liblammps")
    endif()
  endif()
  if(NOT LAMMPS_HAS_LIBRARY)
    message(FATAL_ERROR "No system LAMMPS library found (neither find_package(LAMMPS CONFIG) nor "
                        "pkg-config liblammps). Run 'bash .ci/setup.sh' as root (installs "
                        "liblammps-dev), or build only the plugin with -DLAMMPS_SOURCE_DIR=<lammps/src>.")
  endif()
  # Debian's LAMMPSConfigVersion.cmake says 20210929; Ubuntu-style versions may be dotted
  string(REGEX REPLACE "[^0-9]" "" _lh_lib_version "${_lh_lib_version}")

  # the header set: explicit dir, else the one .ci/setup.sh cached for the installed package
  if(NOT LAMMPS_HEADERS_DIR)
    set(_lh_cache "${PROJECT_SOURCE_DIR}/.cache/lammps-headers")
    set(_lh_candidates "")
    find_program(DPKG_QUERY_EXECUTABLE dpkg-query)
    if(DPKG_QUERY_EXECUTABLE)
      execute_process(COMMAND ${DPKG_QUERY_EXECUTABLE} -W -f=\${Version} liblammps-dev
                      OUTPUT_VARIABLE _lh_pkgver ERROR_QUIET RESULT_VARIABLE _lh_rc)
      if(_lh_rc EQUAL 0 AND _lh_pkgver)
        string(REGEX REPLACE "\\+b[0-9]+$" "" _lh_pkgver "${_lh_pkgver}")   # binNMU
        string(REGEX REPLACE "^[0-9]+:" "" _lh_pkgver "${_lh_pkgver}")      # epoch
        list(APPEND _lh_candidates "${_lh_cache}/${_lh_pkgver}")
      endif()
    endif()
    # any other cached set of the same LAMMPS version (e.g. no dpkg-query)
    file(GLOB _lh_glob LIST_DIRECTORIES true "${_lh_cache}/*")
    list(APPEND _lh_candidates ${_lh_glob})
    foreach(_d IN LISTS _lh_candidates)
      if(EXISTS "${_d}/.hardcontact-complete" AND EXISTS "${_d}/neigh_request.h")
        _lh_read_version("${_d}" _s _n)
        if(_n STREQUAL _lh_lib_version)
          # a normal variable: searched again at every configure (follows package upgrades)
          set(LAMMPS_HEADERS_DIR "${_d}")
          break()
        endif()
      endif()
    endforeach()
    if(NOT LAMMPS_HEADERS_DIR)
      message(FATAL_ERROR "No cached LAMMPS header set matching the installed liblammps "
                          "(version ${_lh_lib_version}) in ${_lh_cache}. Run 'bash .ci/setup.sh' "
                          "(it fetches the headers of the installed version from the Debian source "
                          "package), or pass -DLAMMPS_HEADERS_DIR=<dir with fix.h, neigh_request.h, "
                          "fmt/, lammpsplugin.h>.")
    endif()
  endif()
  foreach(_h version.h fix.h neigh_request.h lammpsplugin.h fmt/format.h)
    if(NOT EXISTS "${LAMMPS_HEADERS_DIR}/${_h}")
      message(FATAL_ERROR "LAMMPS_HEADERS_DIR=${LAMMPS_HEADERS_DIR} has no ${_h}")
    endif()
  endforeach()
  _lh_read_version("${LAMMPS_HEADERS_DIR}" _s _n)
  if(_lh_lib_version AND NOT _n STREQUAL _lh_lib_version)
    message(FATAL_ERROR "The installed liblammps (${_lh_how}, version ${_lh_lib_version}) and the "
                        "header set in ${LAMMPS_HEADERS_DIR} (LAMMPS ${_s}, ${_n}) are different "
                        "versions. Re-run 'bash .ci/setup.sh' or fix -DLAMMPS_HEADERS_DIR.")
  endif()
  set(LAMMPS_HEADERS_INCLUDE_DIRS "${LAMMPS_HEADERS_DIR}")

  find_package(MPI REQUIRED COMPONENTS CXX)
  set(_lh_mpi_includes ${MPI_CXX_INCLUDE_DIRS})
  set(_lh_mpi_definitions ${MPI_CXX_COMPILE_DEFINITIONS} MPICH_SKIP_MPICXX OMPI_SKIP_MPICXX)

  if(NOT TARGET hardcontact::lammps)
    add_library(hardcontact::lammps INTERFACE IMPORTED)
    if(TARGET LAMMPS::lammps)
      target_link_libraries(hardcontact::lammps INTERFACE LAMMPS::lammps MPI::MPI_CXX)
    else()
      target_link_libraries(hardcontact::lammps INTERFACE PkgConfig::PC_LIBLAMMPS MPI::MPI_CXX)
    endif()
  endif()
endif()

list(REMOVE_DUPLICATES LAMMPS_HEADERS_DEFINITIONS)
_lh_read_version("${LAMMPS_HEADERS_DIR}" LAMMPS_HEADERS_VERSION LAMMPS_HEADERS_VERSION_NUM)
list(APPEND LAMMPS_HEADERS_INCLUDE_DIRS ${_lh_mpi_includes})
set(_lh_target_definitions ${LAMMPS_HEADERS_DEFINITIONS} ${_lh_mpi_definitions})
list(REMOVE_DUPLICATES _lh_target_definitions)

if(NOT TARGET hardcontact::lammps_headers)
  add_library(hardcontact::lammps_headers INTERFACE IMPORTED)
  # IMPORTED -> consumers see these include dirs as SYSTEM (no -Wextra noise from LAMMPS/fmt)
  set_target_properties(hardcontact::lammps_headers PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${LAMMPS_HEADERS_INCLUDE_DIRS}"
    INTERFACE_COMPILE_DEFINITIONS "${_lh_target_definitions}")
endif()

find_package_handle_standard_args(LammpsHeaders
  REQUIRED_VARS LAMMPS_HEADERS_DIR LAMMPS_HEADERS_VERSION
  VERSION_VAR LAMMPS_HEADERS_VERSION_NUM)
