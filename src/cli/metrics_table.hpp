// The per-body error table and verdict shared by `perpdot crosscheck` and `perpdot compare`.
#pragma once

#include <cstdio>
#include <vector>

#include "perpdot/crosscheck.hpp"

namespace perpdot::cli {

// Worst bodies first (diverged earliest, then largest position error), at most `maxRows` rows.
void printMetrics(std::FILE* out, const std::vector<crosscheck::BodyMetrics>& bodies, size_t maxRows = 20);

// "verdict: ..." line; returns the exit status (0 within tolerance, 1 diverged).
int printVerdict(std::FILE* out, const std::vector<crosscheck::BodyMetrics>& bodies, const crosscheck::Options& options,
                 float timestep);

}  // namespace perpdot::cli
