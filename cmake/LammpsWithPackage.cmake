# Builds LAMMPS (unpatched) with our package in src/ compiled into it.
#
# Our style headers are appended to the GLOBAL properties that LAMMPS' own
# StyleHeaderUtils.cmake turns into style_*.h, before LAMMPS' cmake/ directory is added;
# our sources are then added to the `lammps` target. Result: ${CMAKE_BINARY_DIR}/lmp.
#
# -DNSCD_INTREE_LAMMPS_DIR=<tree> instead builds the in-tree route: <tree> is a LAMMPS tree
# holding the package as src/NSCD, lib/nscd and cmake/Modules/Packages/NSCD.cmake
# (tools/build_intree.sh prepares it); LAMMPS compiles the package itself (-DPKG_NSCD=on),
# with its own main(), and this project only adds the tests.

set(LAMMPS_SOURCE_DIR "" CACHE PATH
    "LAMMPS source tree (the directory holding cmake/ and src/); empty = fetch Debian's")
set(NSCD_LAMMPS_RELEASE "4Feb2025" CACHE STRING
    "LAMMPS release tools/fetch_lammps.sh fetches when LAMMPS_SOURCE_DIR is empty (4Feb2025, 4Jul2026)")
set(NSCD_CACHE_DIR "$ENV{HOME}/.cache/nscd-lammps" CACHE PATH
    "Where tools/fetch_lammps.sh keeps the fetched LAMMPS source")

set(NSCD_INTREE_LAMMPS_DIR "" CACHE PATH
    "A LAMMPS tree with this package installed in-tree (tools/build_intree.sh); empty = the external build")
if(NSCD_INTREE_LAMMPS_DIR)
  if(NOT EXISTS "${NSCD_INTREE_LAMMPS_DIR}/src/NSCD" OR
     NOT EXISTS "${NSCD_INTREE_LAMMPS_DIR}/cmake/Modules/Packages/NSCD.cmake")
    message(FATAL_ERROR "NSCD_INTREE_LAMMPS_DIR=${NSCD_INTREE_LAMMPS_DIR} holds no NSCD package "
                        "(src/NSCD, cmake/Modules/Packages/NSCD.cmake): prepare it with tools/build_intree.sh")
  endif()
  set(LAMMPS_SOURCE_DIR "${NSCD_INTREE_LAMMPS_DIR}" CACHE PATH "LAMMPS source tree" FORCE)
  set(PKG_NSCD ON CACHE BOOL "The NSCD package, in-tree" FORCE)
endif()
if(NOT LAMMPS_SOURCE_DIR)
  message(STATUS "No LAMMPS_SOURCE_DIR given: fetching LAMMPS ${NSCD_LAMMPS_RELEASE} (Debian's "
                 "source package) into ${NSCD_CACHE_DIR}")
  execute_process(
    COMMAND bash ${PROJECT_SOURCE_DIR}/tools/fetch_lammps.sh ${NSCD_CACHE_DIR} ${NSCD_LAMMPS_RELEASE}
    OUTPUT_VARIABLE _fetched OUTPUT_STRIP_TRAILING_WHITESPACE
    RESULT_VARIABLE _fetch_rc)
  if(NOT _fetch_rc EQUAL 0 OR NOT EXISTS "${_fetched}/cmake/CMakeLists.txt")
    message(FATAL_ERROR "Could not fetch the LAMMPS source (tools/fetch_lammps.sh exit ${_fetch_rc}). "
                        "Pass an existing tree with -DLAMMPS_SOURCE_DIR=/path/to/lammps")
  endif()
  set(LAMMPS_SOURCE_DIR "${_fetched}" CACHE PATH "LAMMPS source tree" FORCE)
endif()
if(EXISTS "${LAMMPS_SOURCE_DIR}/../cmake/CMakeLists.txt" AND NOT EXISTS "${LAMMPS_SOURCE_DIR}/cmake/CMakeLists.txt")
  get_filename_component(LAMMPS_SOURCE_DIR "${LAMMPS_SOURCE_DIR}/.." ABSOLUTE)   # user gave .../src
endif()
if(NOT EXISTS "${LAMMPS_SOURCE_DIR}/cmake/CMakeLists.txt")
  message(FATAL_ERROR "LAMMPS_SOURCE_DIR=${LAMMPS_SOURCE_DIR} has no cmake/CMakeLists.txt: "
                      "point it at the top of a LAMMPS source tree")
endif()
set(NSCD_LAMMPS_TREE "${LAMMPS_SOURCE_DIR}")
include(${CMAKE_CURRENT_LIST_DIR}/LammpsVersion.cmake)
nscd_check_lammps_version("${NSCD_LAMMPS_TREE}")
message(STATUS "LAMMPS source tree: ${NSCD_LAMMPS_TREE} (LAMMPS ${NSCD_LAMMPS_VERSION})")

# LAMMPS settings this package relies on (users may still add more packages with -DPKG_...)
set(BUILD_MPI ON CACHE BOOL "Build LAMMPS with MPI")
set(PKG_MOLECULE ON CACHE BOOL "Bonds and angles (wire)")
set(PKG_BODY ON CACHE BOOL "Soft-contact spheropolyhedra, for comparison")
# LAMMPS' GRANULAR package (pair_style granular, fix wall/gran/region): the peer deck of
# benchmarks/loops (Guerra & Holmes' columns of grains and elastic loops) in the same lmp.
# Off by default: only that benchmark needs it, and it adds 22 source files (9.9k lines) to a
# clean build: 137 s of CPU time without ccache (measured: 123 s user + 14 s system, 249 s
# wall on the shared 2-core machine under load), next to the 433 objects of the default lmp.
option(NSCD_WITH_GRANULAR "Compile LAMMPS' GRANULAR package into lmp (benchmarks/loops peer deck)" OFF)
if(NSCD_WITH_GRANULAR)
  set(PKG_GRANULAR ON CACHE BOOL "LAMMPS GRANULAR package (NSCD_WITH_GRANULAR)" FORCE)
endif()
# LAMMPS as a shared library, liblammps.so, which lmp, the LAMMPS-driving tests and LAMMPS'
# `lammps` Python module (build/python, below) all load: one build serves the command line
# and Python. Measured against the static library (doc/build.md): lmp takes about 1.5 % more
# CPU time on a short deck, while linking lmp and the 15 test executables that use LAMMPS
# takes 7 s of CPU instead of 58 s and the build tree 1.9 GB instead of 5.0 GB.
# FORCE: a build tree configured before this option switches over too.
option(NSCD_LAMMPS_SHARED "Build LAMMPS as liblammps.so (lmp, the tests and the lammps Python module load it)" ON)
set(BUILD_SHARED_LIBS ${NSCD_LAMMPS_SHARED} CACHE BOOL "Build shared libraries (NSCD_LAMMPS_SHARED)" FORCE)
set(LAMMPS_EXCEPTIONS ON CACHE BOOL "error->all throws; tests check messages (always on from LAMMPS 2024)")
set(ENABLE_TESTING OFF CACHE BOOL "LAMMPS' own tests download googletest: keep off")
set(WITH_JPEG OFF CACHE BOOL "")
set(WITH_PNG OFF CACHE BOOL "")
set(WITH_FFMPEG OFF CACHE BOOL "")
# No scene of this package needs an FFT; a package that does (KSPACE, ...) gets FFTW3 instead of
# LAMMPS' fallback KISS FFT.
if(PKG_KSPACE OR PKG_ELECTRODE OR PKG_AMOEBA OR PKG_SCAFACOS)
  set(FFT "FFTW3" CACHE STRING "FFT library of LAMMPS (this package: FFTW3)")
  if(NOT FFT STREQUAL "FFTW3")
    message(WARNING "FFT=${FFT}: this package's build uses FFTW3 (Debian libfftw3-dev)")
  endif()
endif()
find_package(MPI REQUIRED)

# LAMMPS' own Python package (python/lammps of the LAMMPS tree) in <build>/python/lammps with
# a link to liblammps.so beside it, where the package looks first: with
# PYTHONPATH=<build>/python, `import lammps` drives this build in-process
# (examples/python/column.py, test python.column_example). Copied again at every build (a
# few files), so that it follows the LAMMPS tree and the library.
function(nscd_python_module)
  if(NOT BUILD_SHARED_LIBS OR NOT EXISTS ${NSCD_LAMMPS_TREE}/python/lammps/__init__.py)
    return()
  endif()
  set(_module ${CMAKE_BINARY_DIR}/python/lammps)
  add_custom_target(nscd_python_module ALL
    COMMAND ${CMAKE_COMMAND} -E copy_directory ${NSCD_LAMMPS_TREE}/python/lammps ${_module}
    COMMAND ${CMAKE_COMMAND} -E create_symlink $<TARGET_FILE:lammps> ${_module}/liblammps.so
    COMMENT "LAMMPS' Python package with this build's liblammps.so: ${CMAKE_BINARY_DIR}/python"
    VERBATIM)
  add_dependencies(nscd_python_module lammps)
endfunction()

# The core library inside lmp, for tests that call lib/ next to LAMMPS: LAMMPS' private
# lib/nscd in-tree, our nscd_core in the external build.
if(NSCD_INTREE_LAMMPS_DIR)
  set(NSCD_LAMMPS_CORE nscd)
  add_subdirectory(${NSCD_LAMMPS_TREE}/cmake ${CMAKE_BINARY_DIR}/lammps)
  set_target_properties(lmp PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR})
  nscd_python_module()
  return()
endif()

set(NSCD_LAMMPS_CORE nscd_core)

# Register our styles with LAMMPS' style-header generator.
file(GLOB NSCD_PACKAGE_HEADERS CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/*.h)
file(GLOB NSCD_PACKAGE_SOURCES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/src/*.cpp)
foreach(_header ${NSCD_PACKAGE_HEADERS})
  file(STRINGS ${_header} _style_line REGEX "^(Atom|Pair|Fix|Bond|Angle|Compute|Command|Dump)Style\\(")
  if(_style_line MATCHES "^Atom")
    set(_prop ATOM_VEC)
  elseif(_style_line MATCHES "^([A-Z][a-z]+)Style")
    string(TOUPPER "${CMAKE_MATCH_1}" _prop)
  else()
    continue()
  endif()
  set_property(GLOBAL APPEND PROPERTY ${_prop} ${_header})
endforeach()

add_subdirectory(${NSCD_LAMMPS_TREE}/cmake ${CMAKE_BINARY_DIR}/lammps)

target_sources(lammps PRIVATE ${NSCD_PACKAGE_SOURCES})
# Our warning flags on our sources only: LAMMPS' files in the same target keep LAMMPS' flags.
# (TARGET_DIRECTORY: the targets live in LAMMPS' cmake/ directory; CMake 3.18 on.)
if(NOT CMAKE_VERSION VERSION_LESS 3.18)
  set_source_files_properties(${NSCD_PACKAGE_SOURCES} ${PROJECT_SOURCE_DIR}/src/main/lmp_main.cpp
                              TARGET_DIRECTORY lammps PROPERTIES COMPILE_OPTIONS "${NSCD_WARNINGS}")
endif()
target_include_directories(lammps PRIVATE ${PROJECT_SOURCE_DIR}/src)
if(BUILD_SHARED_LIBS)
  # liblammps.so holds nscd_core (static, position-independent) inside it: linked
  # privately, it stays out of the lammps target LAMMPS exports for installation.
  target_link_libraries(lammps PRIVATE nscd_core)
else()
  target_link_libraries(lammps PUBLIC nscd_core)
endif()
set_target_properties(lammps PROPERTIES CXX_STANDARD 17 CXX_STANDARD_REQUIRED ON)
set_target_properties(lmp PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR})

# Our own main(): flushes output before an abort (see src/main/lmp_main.cpp).
set_property(TARGET lmp PROPERTY SOURCES ${PROJECT_SOURCE_DIR}/src/main/lmp_main.cpp)
nscd_python_module()
