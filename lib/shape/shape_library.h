/* -*- c++ -*- ----------------------------------------------------------
   NSCD package for LAMMPS: Non-Smooth Contact Dynamics of rigid
   spheropolyhedra coupled to elastic wires.

   Copyright (2026) the NSCD package developers. This software is
   distributed under the GNU General Public License, version 2, the
   licence of LAMMPS. See the LICENSE file in the top-level directory
   of the package.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   Contributing author: the NSCD package developers
------------------------------------------------------------------------- */

// A numbered collection of grain shapes (ids 1..N, as LAMMPS types), with optional names,
// a text file format (doc/Howto_nscd_shape_library_format.rst) and an exact serialisation
// for restarts.
#pragma once

#include "shape/spheropolyhedron.h"

#include <iosfwd>
#include <string>
#include <unordered_map>
#include <vector>

namespace nscd {

class ShapeLibrary {
 public:
  // Most shapes one library holds (a restart stores them all as one string, and every
  // MPI rank keeps a copy): reuse a shape for many grains instead.
  static constexpr int kMaxShapes = 100000;

  // Appends a shape; returns its id (1-based). The name may be empty; a non-empty name
  // must not be in the library yet. Throws ShapeError for a taken name or a full library.
  int add(Spheropolyhedron shape, std::string name = "");
  // Appends all shapes of `other`; their ids continue after the existing ones. Throws
  // ShapeError (and appends nothing) if a name of `other` is taken or the sum is too large.
  void append(const ShapeLibrary &other);

  int size() const { return static_cast<int>(shapes_.size()); }
  bool empty() const { return shapes_.empty(); }
  // Throws ShapeError for an id outside 1..size().
  const Spheropolyhedron &shape(int id) const;
  const std::string &name(int id) const;
  // Id of the shape with this (non-empty) name, 0 if there is none. O(1).
  int find(const std::string &name) const;
  // Largest bounding radius over the shapes (0 for an empty library): sets ghost cutoffs.
  double max_bounding_radius() const;

  // Parses the text format and appends the shapes it defines. On any error nothing is
  // appended and ShapeError says "<source_name>:<line>: <problem>; <way out>".
  void read(std::istream &in, const std::string &source_name);
  void read_file(const std::string &path);
  // Writes the text format: body-frame core vertices at full precision, so that reading
  // it back rebuilds the same shapes (to ~1e-15 relative). Throws ShapeError for an empty
  // library (read() would refuse the file).
  void write(std::ostream &out) const;

  // Every field of every shape, bit for bit, as one line of printable characters without
  // white space (fit for a LAMMPS restart string). deserialize() restores it exactly,
  // without recomputing anything, and throws ShapeError on damaged text (also on text
  // that is well formed but describes an impossible shape: non-finite or non-positive
  // mass properties, inconsistent vertex/face/edge counts, repeated names).
  std::string serialize() const;
  static ShapeLibrary deserialize(const std::string &text);

 private:
  std::vector<Spheropolyhedron> shapes_;
  std::vector<std::string> names_;
  std::unordered_map<std::string, int> ids_by_name_;    // non-empty names only
};

}    // namespace nscd
