// The `perpdot` subcommands. Each returns the process exit status:
// 0 success, 1 a check failed (e.g. cross-check diverged), 2 bad input or usage.
#pragma once

#include <span>
#include <string>

namespace perpdot::cli {

using Args = std::span<const std::string>;  // arguments after the subcommand name

struct Command {
    const char* name;
    const char* usage;  // one line, shown by `perpdot help`
    int (*run)(Args args);
};

// Thrown for bad command-line usage; main prints it and exits 2.
struct UsageError {
    std::string message;
};

int listCommand(Args args);
int runCommand(Args args);
int exportCommand(Args args);
int crosscheckCommand(Args args);  // cmd_crosscheck.cpp
int recordCommand(Args args);      // cmd_golden.cpp
int compareCommand(Args args);     // cmd_golden.cpp
int benchCommand(Args args);       // cmd_bench.cpp
int stressCommand(Args args);      // cmd_stress.cpp

}  // namespace perpdot::cli
