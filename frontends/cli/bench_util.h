// What the benchmarks (`svgmotion bench ...`) measure with besides the wall clock: the process's
// CPU time and peak memory, and the median they report over repetitions.
#pragma once

#include <sys/resource.h>

#include <algorithm>
#include <vector>

namespace svgm::cli {

// User + sys seconds of every thread so far (PoCL's workers included).
inline double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

inline double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss / 1024.0;  // Linux reports kilobytes
}

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n == 0 ? 0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace svgm::cli
