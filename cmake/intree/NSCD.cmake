# ----------------------------------------------------------------------
# NSCD package for LAMMPS: Non-Smooth Contact Dynamics of rigid
# spheropolyhedra coupled to elastic wires.
#
# Copyright (2026) the NSCD package developers. This software is
# distributed under the GNU General Public License, version 2, the
# licence of LAMMPS. See the LICENSE file in the top-level directory
# of the package.
# ----------------------------------------------------------------------
# Contributing author: the NSCD package developers
# ----------------------------------------------------------------------

# cmake/Modules/Packages/NSCD.cmake of a LAMMPS tree holding the package in src/NSCD and its
# physics core (no LAMMPS, no MPI) in lib/nscd; LAMMPS' cmake/CMakeLists.txt includes it when
# PKG_NSCD is on (tools/build_intree.sh puts it there). Builds lib/nscd as a static library, as
# LAMMPS does for lib/poems, and links it into lammps.
#
# External libraries, both system libraries found through the CMake package files Debian
# installs (no download: the package builds offline):
#   Eigen 3.3+  find_package(Eigen3 CONFIG)  libeigen3-dev   (header-only; lib/nscd's headers)
#   qhull       find_package(Qhull CONFIG)   libqhull-dev    (reentrant libqhull_r; the hulls
#                                                             of lib/nscd/shape)

if(CMAKE_CXX_STANDARD LESS 17)
  message(FATAL_ERROR "The NSCD package's core (lib/nscd) is C++17, CMAKE_CXX_STANDARD is "
                      "${CMAKE_CXX_STANDARD}: configure without -DCMAKE_CXX_STANDARD or with 17")
endif()

find_package(Eigen3 3.3 CONFIG QUIET)
if(NOT TARGET Eigen3::Eigen)
  message(FATAL_ERROR "The NSCD package needs Eigen 3.3 or newer: install it (Debian: "
                      "libeigen3-dev) or point Eigen3_DIR at its share/eigen3/cmake")
endif()
find_package(Qhull CONFIG QUIET)
if(NOT TARGET Qhull::qhull_r)
  message(FATAL_ERROR "The NSCD package needs the reentrant qhull library (libqhull_r): install "
                      "it (Debian: libqhull-dev) or point Qhull_DIR at its lib/cmake/Qhull")
endif()

file(GLOB_RECURSE NSCD_LIB_SOURCES CONFIGURE_DEPENDS ${LAMMPS_LIB_SOURCE_DIR}/nscd/[^.]*.cpp)
if(NOT NSCD_LIB_SOURCES)
  message(FATAL_ERROR "PKG_NSCD is on but ${LAMMPS_LIB_SOURCE_DIR}/nscd has no sources: copy "
                      "the package's lib/ there (tools/build_intree.sh does)")
endif()
add_library(nscd STATIC ${NSCD_LIB_SOURCES})
set_target_properties(nscd PROPERTIES OUTPUT_NAME lammps_nscd${LAMMPS_MACHINE}
                                      POSITION_INDEPENDENT_CODE ON)
target_include_directories(nscd PUBLIC ${LAMMPS_LIB_SOURCE_DIR}/nscd)
target_link_libraries(nscd PUBLIC Eigen3::Eigen PRIVATE Qhull::qhull_r)
target_link_libraries(lammps PRIVATE nscd)
