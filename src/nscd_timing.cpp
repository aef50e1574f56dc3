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

#include "nscd_timing.h"

#include "fmt/format.h"

#include <algorithm>
#include <cmath>
#include <numeric>

using namespace LAMMPS_NS;
using namespace NSCD_NS;

NSCDPartTimes::NSCDPartTimes(std::vector<std::string> part_names) :
    names(std::move(part_names)), seconds(names.size(), 0.0)
{
}

void NSCDPartTimes::clear() { std::fill(seconds.begin(), seconds.end(), 0.0); }

double NSCDPartTimes::total() const { return std::accumulate(seconds.begin(), seconds.end(), 0.0); }

std::string NSCDPartTimes::table(MPI_Comm world, const std::string &title, double loop_seconds) const
{
  int nprocs = 1;
  MPI_Comm_size(world, &nprocs);
  std::vector<double> mine = seconds, squares(seconds.size() + 1);
  mine.push_back(total());
  const size_t rows = mine.size();
  for (size_t k = 0; k < rows; k++) squares[k] = mine[k] * mine[k];
  std::vector<double> low(rows), high(rows), sum(rows), sum_squares(rows);
  MPI_Allreduce(mine.data(), low.data(), (int) rows, MPI_DOUBLE, MPI_MIN, world);
  MPI_Allreduce(mine.data(), high.data(), (int) rows, MPI_DOUBLE, MPI_MAX, world);
  MPI_Allreduce(mine.data(), sum.data(), (int) rows, MPI_DOUBLE, MPI_SUM, world);
  MPI_Allreduce(squares.data(), sum_squares.data(), (int) rows, MPI_DOUBLE, MPI_SUM, world);

  std::string text = fmt::format("{} ({} rank{}, loop time {:.4g} s)\n", title, nprocs, nprocs > 1 ? "s" : "",
                                 loop_seconds);
  text += fmt::format("{:<26s}| {:>10s} | {:>10s} | {:>10s} |{:>7s} |{:>7s}\n", "part", "min time",
                      "avg time", "max time", "%varavg", "%total");
  text += std::string(83, '-') + "\n";
  for (size_t k = 0; k < rows; k++) {
    const double mean = sum[k] / nprocs;
    const double variance = std::max(0.0, sum_squares[k] / nprocs - mean * mean);
    // spread about the average in % of it: LAMMPS' measure of load imbalance
    const double spread = mean > 1e-12 ? 100.0 * std::sqrt(variance) / mean : 0.0;
    const double share = loop_seconds > 0.0 ? 100.0 * mean / loop_seconds : 0.0;
    text += fmt::format("{:<26s}| {:>10.4g} | {:>10.4g} | {:>10.4g} |{:>7.1f} |{:>7.2f}\n",
                        k + 1 < rows ? names[k] : std::string("total"), low[k], mean, high[k], spread, share);
  }
  return text;
}
