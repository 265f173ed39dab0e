// Plots of a cross-check Report, drawn by gnuplot run as a child process.
#pragma once

#include <string>
#include <vector>

#include "perpdot/crosscheck.hpp"

namespace perpdot::crosscheck {

// Writes DIR/series.csv and DIR/plots.gp, then runs `gnuplot plots.gp` in DIR (its messages go
// to DIR/gnuplot.log). Appends the paths it wrote to `written`; returns "" or why there are no PNGs.
std::string writePlots(const Report& report, const std::string& directory, std::vector<std::string>& written);

}  // namespace perpdot::crosscheck
