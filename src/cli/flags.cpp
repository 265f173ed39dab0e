#include "cli/flags.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace perpdot::cli {
namespace {

template <class T>
T parse(const std::string& name, const std::string& text) {
    T value{};
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size()) throw UsageError{name + ": '" + text + "' is not a number"};
    return value;
}

}  // namespace

Flags::Flags(Args args, std::initializer_list<const char*> names, std::initializer_list<const char*> switches) {
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg.size() < 2 || arg.compare(0, 2, "--") != 0) {
            positional_.push_back(arg);
            continue;
        }
        if (std::any_of(switches.begin(), switches.end(), [&](const char* n) { return arg == n; })) {
            switches_.insert(arg);
            continue;
        }
        if (std::none_of(names.begin(), names.end(), [&](const char* n) { return arg == n; })) {
            throw UsageError{"unknown option " + arg};
        }
        if (i + 1 >= args.size()) throw UsageError{arg + " needs a value"};
        values_[arg] = args[++i];
    }
}

std::optional<std::string> Flags::text(const std::string& name) const {
    const auto it = values_.find(name);
    return it == values_.end() ? std::nullopt : std::optional(it->second);
}

int Flags::integer(const std::string& name, int fallback, int min) const {
    const auto t = text(name);
    if (!t) return fallback;
    const int value = parse<int>(name, *t);
    if (value < min) throw UsageError{name + " must be at least " + std::to_string(min)};
    return value;
}

float Flags::number(const std::string& name, float fallback, float min) const {
    const auto t = text(name);
    if (!t) return fallback;
    const float value = parse<float>(name, *t);
    if (!std::isfinite(value) || value < min) throw UsageError{name + " must be a finite number of at least " + std::to_string(min)};
    return value;
}

crosscheck::Engine parseEngine(const std::string& name) {
    if (name == "perpdot") return crosscheck::Engine::Perpdot;
    if (name == "box2d") return crosscheck::Engine::Box2D;
    throw UsageError{"--engine: expected perpdot or box2d, got '" + name + "'"};
}

}  // namespace perpdot::cli
