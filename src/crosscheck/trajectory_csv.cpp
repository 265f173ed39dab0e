// The trajectory CSV of scene-format.md: `step,time,body,x,y,angle,vx,vy,omega`, one row per
// non-static body per frame, bodies in scene order. Floats are written with 9 significant
// digits, enough to read back the identical float.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <istream>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "perpdot/crosscheck.hpp"
#include "perpdot/error.hpp"

namespace perpdot::crosscheck {
namespace {

constexpr std::string_view header = "step,time,body,x,y,angle,vx,vy,omega";

std::vector<std::string_view> splitFields(std::string_view line) {
    std::vector<std::string_view> fields;
    for (size_t start = 0;;) {
        const size_t comma = line.find(',', start);
        fields.push_back(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
        if (comma == std::string_view::npos) return fields;
        start = comma + 1;
    }
}

template <class T>
T parseNumber(std::string_view field, const char* column, int lineNumber) {
    T value{};
    const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
    if (ec != std::errc() || end != field.data() + field.size()) {
        throw Error("line " + std::to_string(lineNumber) + ": column " + column + ": '" + std::string(field) +
                    "' is not a number");
    }
    return value;
}

}  // namespace

void writeCsvHeader(std::ostream& out, bool engineColumn) { out << header << (engineColumn ? ",engine\n" : "\n"); }

void writeCsvRow(std::ostream& out, int step, float timestep, const std::string& body, const BodyState& s, const char* engine) {
    if (body.find_first_of(",\n\r") != std::string::npos) throw Error("body name '" + body + "' cannot go in a CSV field");
    char row[256];
    std::snprintf(row, sizeof row, "%d,%.9g,%s,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g", step, double(step) * double(timestep), body.c_str(),
                  double(s.position.x), double(s.position.y), double(s.angle), double(s.linearVelocity.x),
                  double(s.linearVelocity.y), double(s.angularVelocity));
    out << row;
    if (engine) out << ',' << engine;
    out << '\n';
}

void writeCsv(std::ostream& out, const Trajectory& t, const char* engine) {
    writeCsvHeader(out, engine != nullptr);
    for (int frame = 0; frame < t.frameCount(); ++frame)
        for (size_t body = 0; body < t.bodies.size(); ++body) writeCsvRow(out, frame, t.timestep, t.bodies[body], t.at(frame, int(body)), engine);
}

Trajectory readCsv(std::istream& in) {
    std::string line;
    if (!std::getline(in, line)) throw Error("line 1: empty file, expected the header '" + std::string(header) + "'");
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line != header) throw Error("line 1: expected the header '" + std::string(header) + "', found '" + line + "'");

    struct Row {
        int step;
        double time;
        std::string body;
        int line;
    };
    std::vector<Row> rows;
    Trajectory t;
    for (int lineNumber = 2; std::getline(in, line); ++lineNumber) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty()) continue;
        const auto f = splitFields(line);
        if (f.size() != 9) {
            throw Error("line " + std::to_string(lineNumber) + ": expected 9 fields, found " + std::to_string(f.size()));
        }
        rows.push_back({parseNumber<int>(f[0], "step", lineNumber), parseNumber<double>(f[1], "time", lineNumber),
                        std::string(f[2]), lineNumber});
        t.states.push_back({{parseNumber<float>(f[3], "x", lineNumber), parseNumber<float>(f[4], "y", lineNumber)},
                            parseNumber<float>(f[5], "angle", lineNumber),
                            {parseNumber<float>(f[6], "vx", lineNumber), parseNumber<float>(f[7], "vy", lineNumber)},
                            parseNumber<float>(f[8], "omega", lineNumber)});
    }
    for (const Row& r : rows) {
        if (r.step == 0) t.bodies.push_back(r.body);
    }
    if (t.bodies.empty()) throw Error("no rows for step 0");

    // Row r must be body r mod n of frame r / n, with one time per frame, frame k at k·h.
    const size_t n = t.bodies.size();
    const int frames = int((rows.size() + n - 1) / n);
    const double lastTime = rows.back().time;
    t.timestep = frames > 1 ? float(lastTime / (frames - 1)) : 0.0f;
    for (size_t r = 0; r < rows.size(); ++r) {
        const Row& row = rows[r];
        const int frame = int(r / n);
        const std::string& body = t.bodies[r % n];
        const std::string at = "line " + std::to_string(row.line) + ": ";
        if (row.step != frame) throw Error(at + "expected step " + std::to_string(frame) + ", found " + std::to_string(row.step));
        if (row.body != body) throw Error(at + "expected body '" + body + "' of step " + std::to_string(frame) + ", found '" + row.body + "'");
        const double expected = double(frame) * double(t.timestep);
        if (std::abs(row.time - expected) > 1.0e-6 + 1.0e-5 * std::abs(expected)) {
            throw Error(at + "time " + std::to_string(row.time) + " is not step × " + std::to_string(t.timestep));
        }
    }
    if (rows.size() % n != 0) throw Error("the last step lists " + std::to_string(rows.size() % n) + " of " + std::to_string(n) + " bodies");
    return t;
}

}  // namespace perpdot::crosscheck
