// perpdot stress [CASE...] [--short]
// The torture suite (crosscheck/stress.hpp): each case's scene in perpdot and in Box2D 2.4.1's
// b2World, one line per case with each engine's figure and whether perpdot meets the case's
// criterion. Exit 0 when perpdot meets every criterion, 1 when it misses one, 2 on bad usage.
// --short runs the long cases (stacks, pyramid, chain) for fewer steps: what ctest runs.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/flags.hpp"
#include "crosscheck/stress.hpp"

namespace perpdot::cli {

int stressCommand(Args args) {
    std::vector<std::string> rest(args.begin(), args.end());
    const auto shortFlag = std::find(rest.begin(), rest.end(), "--short");
    const bool shortRun = shortFlag != rest.end();
    if (shortRun) rest.erase(shortFlag);
    const Flags flags(rest, {});

    std::vector<const crosscheck::StressCase*> cases;
    for (const std::string& name : flags.positional()) {
        const crosscheck::StressCase* c = crosscheck::findStressCase(name);
        if (!c) throw UsageError{"no stress case '" + name + "' (run `perpdot stress` for all of them)"};
        cases.push_back(c);
    }
    if (cases.empty())
        for (const crosscheck::StressCase& c : crosscheck::stressCases()) cases.push_back(&c);

    int passed = 0;
    for (const crosscheck::StressCase* c : cases) {
        const crosscheck::StressResult p = crosscheck::runStress(*c, crosscheck::Engine::Perpdot, shortRun);
        const crosscheck::StressResult b = crosscheck::runStress(*c, crosscheck::Engine::Box2D, shortRun);
        passed += p.pass;
        std::printf("%-10s %s  %d steps\n", c->name, p.pass ? "PASS" : "FAIL", p.steps);
        std::printf("  criterion: %s\n", c->criterion);
        std::printf("  perpdot:   %s\n", p.figure.c_str());
        std::printf("  box2d:     %s%s\n", b.figure.c_str(), b.pass ? " (meets it too)" : "");
        std::fflush(stdout);
    }
    std::printf("perpdot meets %d of %d criteria%s\n", passed, int(cases.size()), shortRun ? " (short runs)" : "");
    return passed == int(cases.size()) ? 0 : 1;
}

}  // namespace perpdot::cli
