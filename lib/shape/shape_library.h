// A numbered collection of grain shapes (ids 1..N, as LAMMPS types), with optional names,
// a text file format (doc/shape_library_format.md) and an exact serialisation for restarts.
#pragma once

#include "shape/spheropolyhedron.h"

#include <iosfwd>
#include <string>
#include <vector>

namespace nscd {

class ShapeLibrary {
 public:
  // Appends a shape; returns its id (1-based). The name may be empty.
  int add(Spheropolyhedron shape, std::string name = "");
  // Appends all shapes of `other`; their ids continue after the existing ones.
  void append(const ShapeLibrary &other);

  int size() const { return static_cast<int>(shapes_.size()); }
  bool empty() const { return shapes_.empty(); }
  // Throws ShapeError for an id outside 1..size().
  const Spheropolyhedron &shape(int id) const;
  const std::string &name(int id) const;
  // Id of the first shape with this name, 0 if there is none.
  int find(const std::string &name) const;
  // Largest bounding radius over the shapes (0 for an empty library): sets ghost cutoffs.
  double max_bounding_radius() const;

  // Parses the text format and appends the shapes it defines. On any error nothing is
  // appended and ShapeError says "<source_name>:<line>: <problem>; <way out>".
  void read(std::istream &in, const std::string &source_name);
  void read_file(const std::string &path);
  // Writes the text format: body-frame core vertices at full precision, so that reading
  // it back rebuilds the same shapes (to ~1e-15 relative).
  void write(std::ostream &out) const;

  // Every field of every shape, bit for bit, as one line of printable characters without
  // white space (fit for a LAMMPS restart string). deserialize() restores it exactly,
  // without recomputing anything, and throws ShapeError on damaged text.
  std::string serialize() const;
  static ShapeLibrary deserialize(const std::string &text);

 private:
  std::vector<Spheropolyhedron> shapes_;
  std::vector<std::string> names_;
};

}    // namespace nscd
