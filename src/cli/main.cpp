// perpdot: run, cross-check, benchmark and export scenes.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "perpdot/error.hpp"

namespace perpdot::cli {
namespace {

const Command commands[] = {
    {"list", "perpdot list", listCommand},
    {"run", "perpdot run SCENE|FILE [--steps N] [--csv FILE] [--every K] [--save-at K FILE] [--load FILE] [--workers N]", runCommand},
    {"export", "perpdot export SCENE FILE", exportCommand},
    {"crosscheck", "perpdot crosscheck SCENE|FILE [--steps N] [--tolerance METRES] [--angle-tolerance RAD] [--report DIR]", crosscheckCommand},
    {"record", "perpdot record SCENE|FILE --out FILE.csv [--engine perpdot|box2d] [--steps N]", recordCommand},
    {"compare", "perpdot compare SCENE|FILE --against FILE.csv [--tolerance METRES] [--angle-tolerance RAD]", compareCommand},
    {"bench", "perpdot bench [SCENE...] [--steps N] [--repeat R] [--engine perpdot|box2d] [--workers N]", benchCommand},
    {"stress", "perpdot stress [CASE...] [--short]", stressCommand},
};

void printUsage(std::FILE* out) {
    std::fprintf(out, "usage:\n");
    for (const Command& c : commands) std::fprintf(out, "  %s\n", c.usage);
}

}  // namespace
}  // namespace perpdot::cli

int main(int argc, char** argv) {
    using namespace perpdot::cli;
    if (argc < 2) {
        printUsage(stderr);
        return 2;
    }
    const std::string name = argv[1];
    if (name == "help" || name == "--help" || name == "-h") {
        printUsage(stdout);
        return 0;
    }
    const std::vector<std::string> args(argv + 2, argv + argc);
    for (const Command& c : commands) {
        if (name != c.name) continue;
        try {
            return c.run(args);
        } catch (const UsageError& e) {
            std::fprintf(stderr, "perpdot %s: %s\nusage: %s\n", c.name, e.message.c_str(), c.usage);
        } catch (const perpdot::Error& e) {
            std::fprintf(stderr, "perpdot %s: %s\n", c.name, e.what());
        } catch (const std::exception& e) {
            std::fprintf(stderr, "perpdot %s: unexpected error: %s\n", c.name, e.what());
        }
        return 2;
    }
    std::fprintf(stderr, "perpdot: unknown command '%s'\n", name.c_str());
    printUsage(stderr);
    return 2;
}
