// Helpers shared by the tests that run the project's programs (hlens-cli, hlens) as processes.
#pragma once
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace hlens_test {

namespace fs = std::filesystem;

// What a process printed and how it ended.
struct Outcome {
    int code = -1;  // exit code; -1 if the process did not exit normally (killed by a signal)
    std::string out, err;
};

inline std::string read_file(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

inline void write_file(const fs::path& p, const std::string& text) {
    std::ofstream f(p, std::ios::binary);
    f << text;
}

// Single-quoted for /bin/sh: safe for any path or argument.
inline std::string quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

}  // namespace hlens_test
