// unique_ptr owners for SDL objects, so every exit path frees them.
#pragma once

#include <SDL.h>

#include <memory>

namespace perpdot::demo {

struct SdlDeleter {
    void operator()(SDL_Window* p) const { SDL_DestroyWindow(p); }
    void operator()(SDL_Renderer* p) const { SDL_DestroyRenderer(p); }
    void operator()(SDL_Surface* p) const { SDL_FreeSurface(p); }
    void operator()(SDL_Texture* p) const { SDL_DestroyTexture(p); }
};
using WindowPtr = std::unique_ptr<SDL_Window, SdlDeleter>;
using RendererPtr = std::unique_ptr<SDL_Renderer, SdlDeleter>;
using SurfacePtr = std::unique_ptr<SDL_Surface, SdlDeleter>;

// SDL_Init / SDL_Quit for the lifetime of the object.
struct SdlLibrary {
    bool ok;
    explicit SdlLibrary(Uint32 flags) : ok(SDL_Init(flags) == 0) {}
    ~SdlLibrary() { SDL_Quit(); }
    SdlLibrary(const SdlLibrary&) = delete;
    SdlLibrary& operator=(const SdlLibrary&) = delete;
};

}  // namespace perpdot::demo
