#include "options.hpp"

#include <algorithm>
#include <charconv>

namespace perpdot::demo {
namespace {

int parsePositive(const std::string& flag, const std::string& text) {
    int value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc{} || end != text.data() + text.size() || value <= 0) {
        throw UsageError{flag + ": expected a positive integer, got '" + text + "'"};
    }
    return value;
}

void parseSize(const std::string& text, Options& o) {
    const size_t x = text.find('x');
    if (x == std::string::npos) throw UsageError{"--size: expected WxH (e.g. 640x480), got '" + text + "'"};
    o.width = parsePositive("--size", text.substr(0, x));
    o.height = parsePositive("--size", text.substr(x + 1));
    if (o.width < 16 || o.height < 16 || o.width > 8192 || o.height > 8192) {
        throw UsageError{"--size: each side must be between 16 and 8192 pixels, got '" + text + "'"};
    }
}

DebugDrawOptions parseLayers(const std::string& text) {
    DebugDrawOptions d;
    d.shapes = d.joints = false;
    size_t start = 0;
    while (start <= text.size()) {
        const size_t comma = std::min(text.find(',', start), text.size());
        const std::string layer = text.substr(start, comma - start);
        if (layer == "shapes") d.shapes = true;
        else if (layer == "com") d.centerOfMass = true;
        else if (layer == "velocities") d.velocities = true;
        else if (layer == "aabbs") d.aabbs = true;
        else if (layer == "contacts") d.contacts = true;
        else if (layer == "impulses") d.contactImpulses = true;
        else if (layer == "joints") d.joints = true;
        else throw UsageError{"--show: unknown layer '" + layer + "'"};
        start = comma + 1;
    }
    return d;
}

}  // namespace

Options parseOptions(const std::vector<std::string>& args) {
    Options o;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        const auto value = [&]() -> const std::string& {
            if (i + 1 >= args.size()) throw UsageError{a + ": missing value"};
            return args[++i];
        };
        if (a == "--headless") o.headless = true;
        else if (a == "--list") o.list = true;
        else if (a == "--help" || a == "-h") o.help = true;
        else if (a == "--frames") o.frames = parsePositive(a, value());
        else if (a == "--every") o.every = parsePositive(a, value());
        else if (a == "--out") o.outDir = value();
        else if (a == "--size") parseSize(value(), o);
        else if (a == "--exit-after") o.exitAfter = parsePositive(a, value());
        else if (a == "--no-crosscheck") o.crosscheck = false;
        else if (a == "--show") o.draw = parseLayers(value());
        else if (a.starts_with("--")) throw UsageError{"unknown option '" + a + "'"};
        else if (o.scene.empty()) o.scene = a;
        else throw UsageError{"more than one scene given ('" + o.scene + "' and '" + a + "')"};
    }
    if (o.headless) {
        if (o.scene.empty()) throw UsageError{"--headless needs a SCENE or FILE"};
        if (o.frames == 0) throw UsageError{"--headless needs --frames N"};
        if (o.outDir.empty()) throw UsageError{"--headless needs --out DIR"};
        if (o.exitAfter != 0) throw UsageError{"--exit-after is for the window; use --frames"};
    } else if (o.frames != 0 || !o.outDir.empty() || o.every != 1) {
        throw UsageError{"--frames, --out and --every need --headless"};
    }
    return o;
}

}  // namespace perpdot::demo
