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

/* Numbers from deck arguments, read as LAMMPS reads them (utils::is_double, is_integer) but
   refused with a message that names the command, the keyword and the value and says what
   is expected: LAMMPS' own parser answers 'nan' with "Expected floating point parameter
   instead of 'nan' in input script or data file" and '2.5' for a count with "Expected
   integer parameter", without naming the keyword. For the .cpp files of this package (not
   style headers: LAMMPS compiles those into its core). */

#ifndef LMP_NSCD_ARGS_H
#define LMP_NSCD_ARGS_H

#include "error.h"
#include "lammps.h"
#include "utils.h"

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace LAMMPS_NS {
namespace NSCD_NS {

// The value of `key` given as `text` to the command `where` (e.g. "fix nscd", "tolerance").
inline double number(LAMMPS *lmp, const std::string &where, const std::string &key, const std::string &text)
{
  std::string word = utils::lowercase(text);
  if (!word.empty() && (word[0] == '+' || word[0] == '-')) word.erase(0, 1);
  if (word == "nan" || word == "inf" || word == "infinity")
    lmp->error->all(FLERR, "{}: {} '{}' is not a finite number; give a decimal number such as 0.5 or 1e-4", where,
                    key, text);
  if (!utils::is_double(text))
    lmp->error->all(FLERR, "{}: {} '{}' is not a number; give a decimal number such as 0.5 or 1e-4", where, key,
                    text);
  errno = 0;
  const double x = std::strtod(text.c_str(), nullptr);
  if (errno == ERANGE || !std::isfinite(x))
    lmp->error->all(FLERR, "{}: {} {} is beyond the range of double precision "
                    "numbers; change the units or the value", where, key, text);
  return x;
}

// A whole number (a count, a type, a seed) within [lo, hi].
inline long long whole(LAMMPS *lmp, const std::string &where, const std::string &key, const std::string &text,
                       long long lo = LLONG_MIN, long long hi = LLONG_MAX)
{
  if (!utils::is_integer(text)) {
    if (utils::is_double(text))
      lmp->error->all(FLERR, "{}: {} {} must be a whole number", where, key, text);
    lmp->error->all(FLERR, "{}: {} '{}' is not a whole number", where, key, text);
  }
  errno = 0;
  const long long n = std::strtoll(text.c_str(), nullptr, 10);
  if (errno == ERANGE || n < lo || n > hi)
    lmp->error->all(FLERR, "{}: {} {} must be between {} and {}", where, key, text, lo, hi);
  return n;
}

// A yes|no value of `key`: true for yes; anything else stops naming it.
inline bool yes_or_no(LAMMPS *lmp, const std::string &where, const std::string &key, const std::string &text)
{
  if (text != "yes" && text != "no") lmp->error->all(FLERR, "{}: {} '{}' must be yes or no", where, key, text);
  return text == "yes";
}

// The value after the keyword arg[iarg] of `where` (e.g. "fix nscd/plate"), once the keyword
// is known to be one of `known`: a misspelled keyword is named as such, not as a value that
// is not a number. Stops naming the keyword and the list, or the keyword without a value.
inline std::string keyword_value(LAMMPS *lmp, const std::string &where, int narg, char **arg, int iarg,
                                 const std::vector<std::string> &known)
{
  const std::string key = arg[iarg];
  bool found = false;
  std::string list;
  for (const std::string &k : known) {
    found = found || k == key;
    list += (list.empty() ? "" : ", ") + k;
  }
  if (!found) lmp->error->all(FLERR, "{}: unknown keyword '{}' (expected {})", where, key, list);
  if (iarg + 1 >= narg) lmp->error->all(FLERR, "{}: keyword '{}' needs a value", where, key);
  return arg[iarg + 1];
}

}    // namespace NSCD_NS
}    // namespace LAMMPS_NS

#endif
