# HardcontactLammpsApi.cmake - which LAMMPS fix API do the headers in use offer?
#
# LAMMPS has no numeric version macro, and on 24 Mar 2022 it renamed what a fix uses:
#   old:    neighbor->request(this, instance_me); requests[i]->size = 1;  comm->forward_comm_fix(this)
#   modern: neighbor->add_request(this, NeighConst::REQ_SIZE);            comm->forward_comm(this)
# Both variants are compiled (not linked: the probe is built as a static library) against
# LAMMPS_HEADERS_INCLUDE_DIRS / LAMMPS_HEADERS_DEFINITIONS from FindLammpsHeaders.cmake.
# Result: HARDCONTACT_MODERN_API (0/1), added as a compile definition for all targets.
# If neither variant compiles the headers are unusable and configuration stops.

include(CheckCXXSourceCompiles)
include(CMakePushCheckState)

function(hardcontact_detect_lammps_api)
  cmake_push_check_state(RESET)
  set(CMAKE_REQUIRED_INCLUDES ${LAMMPS_HEADERS_INCLUDE_DIRS})
  set(CMAKE_REQUIRED_DEFINITIONS "")
  foreach(_d IN LISTS LAMMPS_HEADERS_DEFINITIONS)
    list(APPEND CMAKE_REQUIRED_DEFINITIONS "-D${_d}")
  endforeach()
  set(CMAKE_REQUIRED_QUIET ON)
  set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)    # no liblammps to link against
  # the probe results depend on the header set: re-check when it changes
  string(MD5 _key "${LAMMPS_HEADERS_INCLUDE_DIRS}|${LAMMPS_HEADERS_DEFINITIONS}")
  string(SUBSTRING "${_key}" 0 8 _key)

  set(_prologue "
#include \"comm.h\"
#include \"fix.h\"
#include \"neigh_request.h\"
#include \"neighbor.h\"
using namespace LAMMPS_NS;
")
  check_cxx_source_compiles("${_prologue}
void hardcontact_probe(Neighbor *neighbor, Comm *comm, Fix *fix)
{
  NeighRequest *req = neighbor->add_request(fix, NeighConst::REQ_SIZE);
  req->set_cutoff(1.0);
  comm->forward_comm(fix);
  comm->reverse_comm(fix);
}
" HARDCONTACT_PROBE_MODERN_${_key})

  check_cxx_source_compiles("${_prologue}
void hardcontact_probe(Neighbor *neighbor, Comm *comm, Fix *fix)
{
  int irequest = neighbor->request(fix, 0);
  neighbor->requests[irequest]->size = 1;
  comm->forward_comm_fix(fix);
  comm->reverse_comm_fix(fix);
}
" HARDCONTACT_PROBE_OLD_${_key})
  cmake_pop_check_state()

  if(HARDCONTACT_PROBE_MODERN_${_key})
    set(_modern 1)
    set(_what "modern (add_request / forward_comm(Fix *), LAMMPS >= 24 Mar 2022)")
  elseif(HARDCONTACT_PROBE_OLD_${_key})
    set(_modern 0)
    set(_what "old (request + requests[i]->size / forward_comm_fix, LAMMPS < 24 Mar 2022)")
  else()
    message(FATAL_ERROR
      "Neither the modern nor the old LAMMPS fix API compiles against the headers in "
      "${LAMMPS_HEADERS_INCLUDE_DIRS} (defines: ${LAMMPS_HEADERS_DEFINITIONS}). The header set is "
      "incomplete or unusable; see CMakeFiles/CMakeError.log (or CMakeConfigureLog.yaml).")
  endif()
  set(HARDCONTACT_MODERN_API ${_modern} PARENT_SCOPE)
  message(STATUS "LAMMPS fix API: ${_what} -> HARDCONTACT_MODERN_API=${_modern}")
  add_compile_definitions(HARDCONTACT_MODERN_API=${_modern})
endfunction()

hardcontact_detect_lammps_api()
