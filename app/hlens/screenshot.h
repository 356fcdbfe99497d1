// Reading the framebuffer into a PNG. Call after rendering and BEFORE swapping buffers (the back
// buffer is what was just drawn; after the swap its content is undefined).
#pragma once
#include <string>

namespace hlens::gui {

// Reads the whole default framebuffer (RGB) and writes it to `path`. False on failure.
bool save_framebuffer_png(const std::string& path, int fb_width, int fb_height);
// "hlens-YYYYMMDD-HHMMSS.png" (local time).
std::string timestamped_png_name();

}  // namespace hlens::gui
