// The torture suite of `perpdot stress`: the built-in scenes stress_<case>, each run
// in one engine and judged by one figure against a criterion written before the results (docs/stress.md).
#pragma once

#include <string>
#include <vector>

#include "perpdot/crosscheck.hpp"

namespace perpdot::crosscheck {

struct StressCase {
    const char* name;       // "stack30": runs the built-in scene "stress_stack30"
    const char* criterion;  // what perpdot must meet, in words
    int shortSteps;         // steps of a --short run; 0: the scene's own
};

// Every case, in the order `perpdot stress` runs them.
const std::vector<StressCase>& stressCases();
// The case of that name or scene name (stress_<name>); nullptr if none.
const StressCase* findStressCase(const std::string& name);

struct StressResult {
    int steps = 0;
    std::string figure;  // the measured figure with its unit, e.g. "top drift 0.012 m, fell 0.004 m"
    bool pass = false;   // the figure meets the case's criterion
};

// Runs the case's scene in `engine` (its full length, or shortSteps when shortRun) and judges it.
StressResult runStress(const StressCase& stressCase, Engine engine, bool shortRun);

}  // namespace perpdot::crosscheck
