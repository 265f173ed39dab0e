// The one exception type of the API: invalid definitions, stale ids, bad scene files.
#pragma once

#include <stdexcept>
#include <string>

namespace perpdot {

class Error : public std::runtime_error {
public:
    explicit Error(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace perpdot
