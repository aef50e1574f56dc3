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

// Writes seed inputs for the fuzz targets of the restart blocks, the polyline reader and
// the grain records into DIR/<target>/ (tools/fuzz.sh; the same files are kept in
// tests/fuzz/regressions/): for each restart block a valid one as the styles write it, the
// previous format where one is recognised, and the damaged forms of
// tests/lammps/test_bad_input.cpp (a foreign mark, a count too large, a size that does not
// match, a value that cannot be); polyline files good and bad; grain records good and bad.
#include "nscd_restart_blocks.h"
#include "shape/grain_record.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

using namespace LAMMPS_NS::NSCD_NS;
namespace fs = std::filesystem;

namespace {

fs::path root;

void save(const std::string &target, const std::string &name, const std::string &bytes)
{
  fs::create_directories(root / target);
  std::ofstream(root / target / name, std::ios::binary) << bytes;
}

template <class T> std::string with(std::string bytes, std::size_t at, T value)
{
  std::memcpy(&bytes[at], &value, sizeof(T));
  return bytes;
}

void solver_seeds()
{
  SolverBlock b;
  b.dt = 0.005;
  for (int k = 0; k < 3; k++) {
    nscd::ImpulseRecord r;
    r.tag_i = k + 1;
    r.tag_j = k == 2 ? -123456789 : k + 2;    // the last one with a wall
    r.feature = 0x0102030405060708ull * (k + 1);
    r.impulse[0] = 0.5 * k, r.impulse[1] = -1e-3, r.impulse[2] = 2.0;
    b.records.push_back(r);
  }
  const std::string valid = solver_block(b);
  save("restart_solver", "valid", valid);
  save("restart_solver", "valid_empty", solver_block(SolverBlock{}));
  save("restart_solver", "foreign_mark", with<std::int32_t>(valid, 0, 0x12345678));
  save("restart_solver", "count_too_large", with<std::int64_t>(valid, 16, 1000000000));
  save("restart_solver", "size_larger", with<std::int64_t>(valid, 8, (std::int64_t) valid.size()));
  save("restart_solver", "nan_impulse", with<double>(valid, 32 + 24, NAN));
  std::string old = with<std::int32_t>(valid.substr(0, 8), 4, 2);    // format 2: {mark 2, int32 count, dt, records}
  const std::int32_t count = 3;
  old.append(reinterpret_cast<const char *>(&count), 4).append(valid, 24, std::string::npos);
  save("restart_solver", "format_2", old);
}

void wire_seeds()
{
  WireBlock b;
  b.dt = 1e-4;
  nscd::wire::StoredContact c{};
  c.key = {5, 6, 1, 0};
  c.memory.spring[0].xi[0] = 1e-4;
  c.memory.weight[0] = c.memory.weight[1] = 0.5;
  b.memories = {c};
  c.key = {7, 0, -99, 0};
  c.memory.spring[1].sliding = 1.0;
  b.memories.push_back(c);
  const std::string valid = wire_block(b);
  save("restart_wire", "valid", valid);
  save("restart_wire", "foreign_mark", with<std::int32_t>(valid, 0, 0));
  save("restart_wire", "count_too_large", with<std::int64_t>(valid, 24, 1ll << 40));
  save("restart_wire", "weight_7", with<double>(valid, 32 + 32 + 64, 7.0));
  const double old_header[3] = {-2.0, 1e-4, 2.0};    // format 2
  save("restart_wire", "format_2", std::string(reinterpret_cast<const char *>(old_header), 24) + valid.substr(32));
}

void wall_and_plate_seeds()
{
  WallBlock w;
  w.cylinder = true;
  w.point = {0.5, -1.0, 2.0};
  const std::string wall = wall_block(w);
  save("restart_wall", "valid", wall);
  save("restart_wall", "kind_2", with<double>(wall, 16, 2.0));
  save("restart_wall", "format_1", with<std::int32_t>(wall.substr(0, 8), 4, 1) + wall.substr(16));
  PlateBlock p;
  p.z = 3.0, p.vz = -0.01, p.elapsed = 2.5, p.z_start = 3.5;
  const std::string plate = plate_block(p);
  save("restart_plate", "valid", plate);
  save("restart_plate", "negative_time", with<double>(plate, 32, -1.0));
  save("restart_plate", "format_1", with<std::int32_t>(plate.substr(0, 8), 4, 1) + plate.substr(16));
}

void pair_seeds()
{
  // first byte: number of atom types - 1 (here 2 types: pairs 1-1, 1-2, 2-2)
  const std::string settings = pair_settings_bytes(PairSettings{});
  const std::string coefficients = pair_coefficient_bytes({1, 0.5, 0.0}) + pair_coefficient_bytes({0, 0.0, 0.0}) +
      pair_coefficient_bytes({1, 0.3, 1.0});
  const std::string valid = std::string(1, '\1') + settings + coefficients;
  save("restart_pair", "valid", valid);
  save("restart_pair", "foreign_mark", with<std::int32_t>(valid, 1, 7));
  save("restart_pair", "negative_friction", with<double>(valid, 1 + 40 + 4, -0.5));
  save("restart_pair", "cut_short", valid.substr(0, valid.size() - 5));
}

void polyline_seeds()
{
  // first byte: nodes - 2
  save("polyline", "valid", std::string(1, '\x10') + "# x y z\n0 0 1\n1 0 1   # corner\n\n1 1 1\n-2.5e-1 .5 +3.\n");
  save("polyline", "nan_line", std::string(1, '\x05') + "0 0 1\nnan 0 1\n1 1 1\n");
  save("polyline", "header", std::string(1, '\x05') + "x y z\n0 0 1\n1 1 1\n");
  save("polyline", "huge", std::string(1, '\xff') + "0 0 0\n1e300 0 0\n1e300 1e300 0\n");
  save("polyline", "coinciding", std::string(1, '\x03') + "0 0 0\n0 0 0\n1 0 0\n");
}

void grain_record_seeds()
{
  auto record = [](std::int32_t shape, double mass, std::array<double, 4> q, bool unit) {
    std::string bytes(reinterpret_cast<const char *>(&shape), 4);
    bytes.append(reinterpret_cast<const char *>(&mass), 8).append(reinterpret_cast<const char *>(q.data()), 32);
    return bytes + std::string(1, unit ? '\1' : '\0');
  };
  save("grain_record", "valid", record(1, 2.0, {2, 0, 0, 0}, false) + record(2, 0.5, {0.5, 0.5, 0.5, 0.5}, true) +
                                    record(0, 0.01, {1, 0, 0, 0}, true));
  save("grain_record", "bad", record(3, 1.0, {1, 0, 0, 0}, false) + record(1, -1.0, {1, 0, 0, 0}, false) +
                                  record(1, 1.0, {0, 0, 0, 0}, false) + record(1, 1e-320, {1, 0, 0, 0}, false) +
                                  record(1, 1.0, {2, 0, 0, 0}, true));
}

}    // namespace

int main(int argc, char **argv)
{
  if (argc != 2) {
    std::fprintf(stderr, "usage: fuzz_seeds DIR\n");
    return 2;
  }
  root = argv[1];
  solver_seeds();
  wire_seeds();
  wall_and_plate_seeds();
  pair_seeds();
  polyline_seeds();
  grain_record_seeds();
  return 0;
}
