#include "screenshot.h"

#include <ctime>
#include <vector>

#include "gl.h"

// The one place stb_image_write's implementation is compiled. STATIC keeps its functions local to
// this file: Debian's libstb (linked for Dear ImGui's font code) exports the same names.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_image_write.h>
#pragma GCC diagnostic pop

namespace hlens::gui {

bool save_framebuffer_png(const std::string& path, int w, int h) {
    if (w <= 0 || h <= 0) return false;
    std::vector<unsigned char> pixels((size_t)w * h * 3);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
    stbi_flip_vertically_on_write(1);   // GL rows go bottom-up, PNG rows top-down
    return stbi_write_png(path.c_str(), w, h, 3, pixels.data(), w * 3) != 0;
}

std::string timestamped_png_name() {
    std::time_t now = std::time(nullptr);
    std::tm tm{};
    localtime_r(&now, &tm);
    char buf[64];
    std::strftime(buf, sizeof buf, "hlens-%Y%m%d-%H%M%S.png", &tm);
    return buf;
}

}  // namespace hlens::gui
