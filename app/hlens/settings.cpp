#include "settings.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace hlens::gui {

std::string config_file(const char* name) {
    const char* xdg = std::getenv("XDG_CONFIG_HOME");
    const char* home = std::getenv("HOME");
    fs::path dir = xdg && *xdg ? fs::path(xdg) / "hlens" : home && *home ? fs::path(home) / ".config" / "hlens" : fs::path();
    if (dir.empty()) return "";
    std::error_code ec;
    fs::create_directories(dir, ec);
    return ec ? "" : (dir / name).string();
}

std::vector<std::string> load_recent(const std::string& file) {
    std::vector<std::string> r;
    std::ifstream in(file);
    for (std::string line; std::getline(in, line) && r.size() < 12;)
        if (!line.empty()) r.push_back(line);
    return r;
}

void remember(std::vector<std::string>& recent, const std::string& path, const std::string& file) {
    std::error_code ec;
    fs::path abs = fs::absolute(path, ec);
    const std::string p = ec ? path : abs.lexically_normal().string();
    recent.erase(std::remove(recent.begin(), recent.end(), p), recent.end());
    recent.insert(recent.begin(), p);
    if (recent.size() > 12) recent.resize(12);
    if (file.empty()) return;
    std::ofstream out(file);
    for (const std::string& r : recent) out << r << "\n";
}

}  // namespace hlens::gui
