#pragma once

#include <map>
#include <string>
#include <vector>

namespace semnav::mapping::bench {

// Per-iteration samples (milliseconds) and single figures collected by the benchmarks.
struct Figures {
  std::map<std::string, std::vector<double>> samples_ms;
  std::map<std::string, double> values;
};

Figures& Collected();

double Median(std::vector<double> v);
double Percentile(std::vector<double> v, double q);

// Resident set size of this process, MiB (VmRSS).
double ResidentMiB();

}  // namespace semnav::mapping::bench
