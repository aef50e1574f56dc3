# The LAMMPS release of a source tree, from src/version.h ("4 Feb 2025"), and the refusal of
# trees older than the oldest release this package is built and tested against.
#
#   nscd_check_lammps_version(<tree>)  sets NSCD_LAMMPS_VERSION ("4 Feb 2025") and
#                                      NSCD_LAMMPS_DATE (20250204) in the caller's scope
set(NSCD_LAMMPS_MINIMUM_DATE 20230802)
set(NSCD_LAMMPS_MINIMUM_NAME "2 Aug 2023")

function(nscd_check_lammps_version tree)
  file(STRINGS "${tree}/src/version.h" _line REGEX "#define LAMMPS_VERSION ")
  if(NOT _line MATCHES "\"([0-9]+) ([A-Z][a-z][a-z]) ([0-9][0-9][0-9][0-9])\"")
    message(FATAL_ERROR "${tree}/src/version.h names no LAMMPS release (\"${_line}\"): "
                        "is LAMMPS_SOURCE_DIR a LAMMPS source tree?")
  endif()
  set(_day ${CMAKE_MATCH_1})
  set(_year ${CMAKE_MATCH_3})
  set(_months Jan Feb Mar Apr May Jun Jul Aug Sep Oct Nov Dec)
  list(FIND _months "${CMAKE_MATCH_2}" _month)
  if(_month LESS 0)
    message(FATAL_ERROR "${tree}/src/version.h: unknown month in \"${_line}\"")
  endif()
  math(EXPR _date "${_year} * 10000 + (${_month} + 1) * 100 + ${_day}")
  set(NSCD_LAMMPS_VERSION "${_day} ${CMAKE_MATCH_2} ${_year}" PARENT_SCOPE)
  set(NSCD_LAMMPS_DATE ${_date} PARENT_SCOPE)
  if(_date LESS NSCD_LAMMPS_MINIMUM_DATE)
    message(FATAL_ERROR "LAMMPS ${_day} ${CMAKE_MATCH_2} ${_year} (${tree}) is too old: this package "
                        "needs LAMMPS ${NSCD_LAMMPS_MINIMUM_NAME} or newer (its Comm, Neighbor and "
                        "Modify interfaces and the per-atom quat). Use a newer tree, or leave "
                        "LAMMPS_SOURCE_DIR empty to fetch LAMMPS 4 Feb 2025.")
  endif()
endfunction()
