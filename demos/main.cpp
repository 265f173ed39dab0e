// perpdot-demo: the SDL2 viewer of perpdot scenes, interactive or headless (PNG frames).
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "headless.hpp"
#include "options.hpp"
#include "perpdot/error.hpp"
#include "perpdot/scene.hpp"
#include "viewer.hpp"

int main(int argc, char** argv) {
    using namespace perpdot::demo;
    try {
        const Options options = parseOptions(std::vector<std::string>(argv + 1, argv + argc));
        if (options.help) {
            std::fputs(usage, stdout);
            return 0;
        }
        if (options.list) {
            for (const perpdot::BuiltinScene& s : perpdot::builtinScenes()) {
                std::printf("%-18s %s\n", s.name.c_str(), s.description.c_str());
            }
            return 0;
        }
        return options.headless ? runHeadless(options) : runViewer(options);
    } catch (const UsageError& e) {
        std::fprintf(stderr, "perpdot-demo: %s\n%s", e.message.c_str(), usage);
        return 2;
    } catch (const perpdot::Error& e) {
        std::fprintf(stderr, "perpdot-demo: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "perpdot-demo: unexpected error: %s\n", e.what());
        return 1;
    }
}
