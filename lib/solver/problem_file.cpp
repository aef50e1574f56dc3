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

#include "solver/problem_file.h"

#include <iomanip>
#include <istream>
#include <ostream>
#include <string>

namespace nscd {
namespace {

constexpr const char *kMagic = "nscd-contact-problem";
constexpr int kVersion = 1;

void put(std::ostream &out, const Vec3 &v) { out << ' ' << v[0] << ' ' << v[1] << ' ' << v[2]; }

class Reader {
 public:
  explicit Reader(std::istream &in) : in_(in) {}
  template <typename T> T get(const char *what)
  {
    T value;
    if (!(in_ >> value)) throw SolverError(std::string("problem file: cannot read ") + what + where());
    return value;
  }
  Vec3 vec(const char *what)
  {
    Vec3 v;
    for (int d = 0; d < 3; ++d) v[d] = get<double>(what);
    return v;
  }
  void at(const char *item, std::size_t index) { item_ = item, index_ = index; }

 private:
  std::string where() const
  {
    return item_ ? std::string(" of ") + item_ + " " + std::to_string(index_) + " (truncated or damaged file)"
                 : std::string(" in the header");
  }
  std::istream &in_;
  const char *item_ = nullptr;
  std::size_t index_ = 0;
};

}    // namespace

void write_problem(std::ostream &out, const ContactProblem &problem, double dt, double theta)
{
  out << std::setprecision(17);
  out << kMagic << ' ' << kVersion << '\n';
  out << problem.bodies.size() << ' ' << problem.contacts.size() << ' ' << dt << ' ' << theta << '\n';
  for (const SolverBody &b : problem.bodies) {
    put(out, b.position);
    put(out, b.velocity);
    put(out, b.angular_velocity);
    put(out, b.external_impulse);
    put(out, b.external_angular_impulse);
    out << ' ' << b.inv_mass;
    put(out, b.inv_mass_axes);
    for (int r = 0; r < 3; ++r) put(out, b.inv_inertia.row(r).transpose());
    out << ' ' << b.share << '\n';
  }
  for (const Contact &c : problem.contacts) {
    out << c.body_i << ' ' << c.body_j;
    put(out, c.point);
    put(out, c.normal);
    out << ' ' << c.gap << ' ' << c.friction << ' ' << c.restitution;
    put(out, c.wall_velocity);
    out << ' ' << c.key.tag_i << ' ' << c.key.tag_j << ' ' << c.key.feature;
    put(out, c.impulse);
    out << '\n';
  }
}

ProblemFile read_problem(std::istream &in)
{
  Reader read(in);
  if (read.get<std::string>("the file type") != kMagic)
    throw SolverError("problem file: not a contact problem (it must start with nscd-contact-problem)");
  const int version = read.get<int>("the version");
  if (version != kVersion)
    throw SolverError("problem file: version " + std::to_string(version) + ", this build reads version " +
                      std::to_string(kVersion));
  ProblemFile file;
  const auto bodies = read.get<std::size_t>("the number of bodies");
  const auto contacts = read.get<std::size_t>("the number of contacts");
  file.dt = read.get<double>("dt");
  file.theta = read.get<double>("theta");
  file.problem.bodies.resize(bodies);
  file.problem.contacts.resize(contacts);
  for (std::size_t k = 0; k < bodies; ++k) {
    read.at("body", k);
    SolverBody &b = file.problem.bodies[k];
    b.position = read.vec("position");
    b.velocity = read.vec("velocity");
    b.angular_velocity = read.vec("angular velocity");
    b.external_impulse = read.vec("external impulse");
    b.external_angular_impulse = read.vec("external angular impulse");
    b.inv_mass = read.get<double>("inverse mass");
    b.inv_mass_axes = read.vec("axis factors");
    for (int r = 0; r < 3; ++r) b.inv_inertia.row(r) = read.vec("inverse inertia").transpose();
    b.share = read.get<double>("share");
  }
  for (std::size_t k = 0; k < contacts; ++k) {
    read.at("contact", k);
    Contact &c = file.problem.contacts[k];
    c.body_i = read.get<int>("body i");
    c.body_j = read.get<int>("body j");
    c.point = read.vec("point");
    c.normal = read.vec("normal");
    c.gap = read.get<double>("gap");
    c.friction = read.get<double>("friction");
    c.restitution = read.get<double>("restitution");
    c.wall_velocity = read.vec("wall velocity");
    c.key.tag_i = read.get<std::int64_t>("tag i");
    c.key.tag_j = read.get<std::int64_t>("tag j");
    c.key.feature = read.get<std::uint64_t>("feature");
    c.impulse = read.vec("impulse");
  }
  return file;
}

}    // namespace nscd
