/* ----------------------------------------------------------------------
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

// nscd_to_body: writes grains of atom_style spheropolyhedron as a LAMMPS data file for
// atom_style body rounded/polyhedron (BODY package), with the same hulls, masses, inertia,
// positions, orientations and velocities, so that pair_style body/rounded/polyhedron can
// run the same pile (benchmarks/peer).
//
//   nscd_to_body SHAPES DATA OUT
//
// SHAPES: the shape library (`shapes write`); DATA: a data file of atom_style
// spheropolyhedron (`write_data`); OUT: the BODY data file. Its first line names the
// `atom_style body rounded/polyhedron 1 NMAX` it needs: NMAX = the largest count of
// vertices, edges or faces of any grain, not of vertices as BODY's doc says, because BODY
// sizes its per-body storage as if a body had at most NMAX edges and NMAX faces, and
// read_data crashes (segmentation fault, no message) when one has more.
#include "shape/body_export.h"
#include "shape/shape_library.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Grain {
  long long id = 0;
  int type = 0, shape = 0;
  double mass = 0;
  nscd::Vec3 x = nscd::Vec3::Zero(), v = nscd::Vec3::Zero(), omega = nscd::Vec3::Zero();
  nscd::Quat q = nscd::Quat::Identity();
  std::string image;    // image flags as written, if any
};

struct DataFile {
  long long natoms = 0;
  int ntypes = 0;
  std::string box[3];    // "lo hi xlo xhi" lines as written
  std::vector<Grain> grains;
};

[[noreturn]] void fail(const std::string &message)
{
  throw std::runtime_error(message);
}

std::string section_name(const std::string &line)
{
  std::istringstream words(line);
  std::string word;
  words >> word;
  return word;
}

// Reads the header and the Atoms and Velocities sections of write_data's output for
// atom_style spheropolyhedron ("id type shape mass x y z qw qx qy qz [ix iy iz]").
DataFile read_data_file(const std::string &path)
{
  std::ifstream in(path);
  if (!in) fail("cannot open data file '" + path + "'; give the file written by write_data");
  DataFile data;
  std::string line;
  std::getline(in, line);    // title
  std::map<long long, size_t> index_of;
  while (std::getline(in, line)) {
    if (line.find("atoms") != std::string::npos && data.natoms == 0) data.natoms = std::atoll(line.c_str());
    else if (line.find("atom types") != std::string::npos) data.ntypes = std::atoi(line.c_str());
    else if (line.find("xlo xhi") != std::string::npos) data.box[0] = line;
    else if (line.find("ylo yhi") != std::string::npos) data.box[1] = line;
    else if (line.find("zlo zhi") != std::string::npos) data.box[2] = line;
    else if (line.find("xy xz yz") != std::string::npos) fail(path + ": triclinic boxes are not supported; use an orthogonal box");
    else if (section_name(line) == "Atoms") {
      if (line.find("spheropolyhedron") == std::string::npos)
        fail(path + ": the Atoms section is not of atom_style spheropolyhedron ('" + line + "')");
      for (long long n = 0; n < data.natoms && std::getline(in, line);) {
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        std::istringstream f(line);
        Grain g;
        double qw, qx, qy, qz;
        f >> g.id >> g.type >> g.shape >> g.mass >> g.x.x() >> g.x.y() >> g.x.z() >> qw >> qx >> qy >> qz;
        if (f.fail()) fail(path + ": cannot read Atoms line '" + line + "'; expected 'id type shape mass x y z qw qx qy qz'");
        std::getline(f, g.image);
        g.q = nscd::Quat(qw, qx, qy, qz).normalized();
        index_of[g.id] = data.grains.size();
        data.grains.push_back(g);
        ++n;
      }
    } else if (section_name(line) == "Velocities") {
      for (long long n = 0; n < data.natoms && std::getline(in, line);) {
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        std::istringstream f(line);
        long long id;
        nscd::Vec3 v, w;
        f >> id >> v.x() >> v.y() >> v.z() >> w.x() >> w.y() >> w.z();
        if (f.fail() || !index_of.count(id)) fail(path + ": bad Velocities line '" + line + "'");
        data.grains[index_of[id]].v = v;
        data.grains[index_of[id]].omega = w;
        ++n;
      }
    }
  }
  if (data.grains.size() != static_cast<size_t>(data.natoms) || data.natoms == 0)
    fail(path + ": found " + std::to_string(data.grains.size()) + " Atoms lines for " + std::to_string(data.natoms) + " atoms");
  for (const auto &b : data.box)
    if (b.empty()) fail(path + ": box bounds (xlo xhi, ylo yhi, zlo zhi) missing");
  return data;
}

void write_body_data(const DataFile &data, const nscd::ShapeLibrary &library, const std::string &path)
{
  size_t nmax = 1;
  for (const Grain &g : data.grains) {
    if (g.shape < 1 || g.shape > library.size())
      fail("atom " + std::to_string(g.id) + " has shape " + std::to_string(g.shape) + ", not a grain of the library (1.." +
           std::to_string(library.size()) + "); BODY needs a shape for every atom");
    const nscd::Spheropolyhedron &shape = library.shape(g.shape);
    const size_t body_faces = nscd::body_entry(shape, g.q, g.mass).faces.size();
    nmax = std::max({nmax, shape.vertices.size(), shape.edges.size(), body_faces});
  }
  std::ofstream out(path);
  if (!out) fail("cannot write '" + path + "'");
  out.precision(17);
  out << "LAMMPS data file for atom_style body rounded/polyhedron 1 " << nmax << ", written by nscd_to_body\n\n"
      << data.natoms << " atoms\n" << data.natoms << " bodies\n" << data.ntypes << " atom types\n\n"
      << data.box[0] << '\n' << data.box[1] << '\n' << data.box[2] << "\n\nAtoms # body\n\n";
  for (const Grain &g : data.grains)
    out << g.id << ' ' << g.type << " 1 " << g.mass << ' ' << g.x.x() << ' ' << g.x.y() << ' ' << g.x.z() << g.image << '\n';
  // BODY's Velocities give the angular momentum (box frame), ours the angular velocity.
  out << "\nVelocities\n\n";
  std::vector<nscd::BodyEntry> entries;
  for (const Grain &g : data.grains) {
    entries.push_back(nscd::body_entry(library.shape(g.shape), g.q, g.mass));
    const nscd::Vec3 L = entries.back().inertia * g.omega;
    out << g.id << ' ' << g.v.x() << ' ' << g.v.y() << ' ' << g.v.z() << ' ' << L.x() << ' ' << L.y() << ' ' << L.z() << '\n';
  }
  out << "\nBodies\n\n";
  for (size_t k = 0; k < entries.size(); ++k) nscd::write_body_entry(out, data.grains[k].id, entries[k]);
  if (!out) fail("writing '" + path + "' failed");
}

}    // namespace

int main(int argc, char **argv)
{
  if (argc != 4) {
    std::cerr << "usage: nscd_to_body SHAPES DATA OUT\n"
                 "  SHAPES: shape library (shapes write), DATA: data file of atom_style spheropolyhedron\n"
                 "  (write_data), OUT: data file for atom_style body rounded/polyhedron\n";
    return 2;
  }
  try {
    nscd::ShapeLibrary library;
    library.read_file(argv[1]);
    write_body_data(read_data_file(argv[2]), library, argv[3]);
  } catch (const std::exception &e) {
    std::cerr << "nscd_to_body: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
