// Shared by the fuzz targets: a violated property aborts (libFuzzer keeps the input; the
// replay test fails).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>

namespace nscd_fuzz {

[[noreturn]] inline void violated(const std::string &what)
{
  std::fprintf(stderr, "property violated: %s\n", what.c_str());
  std::abort();
}

}    // namespace nscd_fuzz
