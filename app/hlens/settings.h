// Settings of interactive runs: ~/.config/hlens/ ($XDG_CONFIG_HOME/hlens/), never the current
// directory. Headless runs keep none.
#pragma once
#include <string>
#include <vector>

namespace hlens::gui {

// The path of `name` in that directory (created if missing); "" if there is none.
std::string config_file(const char* name);
// Recently opened files: one path a line, newest first (at most 12).
std::vector<std::string> load_recent(const std::string& file);
// Puts `path` (made absolute) first in `recent` and writes the list to `file` (unless "").
void remember(std::vector<std::string>& recent, const std::string& path, const std::string& file);

}  // namespace hlens::gui
