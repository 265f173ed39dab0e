// Command-line flags of the subcommands: positional arguments and `--name VALUE` pairs.
// Anything malformed is a UsageError (exit status 2).
#pragma once

#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "perpdot/crosscheck.hpp"

namespace perpdot::cli {

class Flags {
public:
    // `names`: the flags this command accepts, each taking one value (e.g. "--steps").
    Flags(Args args, std::initializer_list<const char*> names);

    const std::vector<std::string>& positional() const { return positional_; }
    std::optional<std::string> text(const std::string& name) const;
    // Parsed numbers; the default when absent, UsageError when malformed or below `min`.
    int integer(const std::string& name, int fallback, int min) const;
    float number(const std::string& name, float fallback, float min) const;

private:
    std::vector<std::string> positional_;
    std::map<std::string, std::string> values_;
};

// `--engine perpdot|box2d`; UsageError for anything else.
crosscheck::Engine parseEngine(const std::string& name);

}  // namespace perpdot::cli
