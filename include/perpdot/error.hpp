/// @file
/// The one exception type of the API: invalid definitions, stale ids, bad scene files.
#pragma once

#include <stdexcept>
#include <string>

namespace perpdot {

/// Thrown for invalid definitions, stale ids and bad scene files; what() names the problem
/// (for scenes, with the JSON path).
class Error : public std::runtime_error {
public:
    /// An error with the message `what`.
    explicit Error(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace perpdot
