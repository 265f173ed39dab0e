// Command-line flags of the subcommands: positional arguments and `--name VALUE` pairs.
// Anything malformed is a UsageError (exit status 2).
#pragma once

#include <initializer_list>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "perpdot/crosscheck.hpp"

namespace perpdot::cli {

class Flags {
public:
    // `names`: the flags this command accepts, each taking one value (e.g. "--steps"); `switches`:
    // those it accepts without a value (e.g. "--box2d-skin").
    Flags(Args args, std::initializer_list<const char*> names, std::initializer_list<const char*> switches = {});

    const std::vector<std::string>& positional() const { return positional_; }
    std::optional<std::string> text(const std::string& name) const;
    // Parsed numbers; the default when absent, UsageError when malformed or below `min`.
    int integer(const std::string& name, int fallback, int min) const;
    float number(const std::string& name, float fallback, float min) const;
    // Whether switch `name` was given.
    bool has(const std::string& name) const { return switches_.count(name) > 0; }

private:
    std::vector<std::string> positional_;
    std::map<std::string, std::string> values_;
    std::set<std::string> switches_;
};

// `--engine perpdot|box2d`; UsageError for anything else.
crosscheck::Engine parseEngine(const std::string& name);

}  // namespace perpdot::cli
