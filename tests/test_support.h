// Helpers shared by the tests that run the project's programs (hlens-cli, hlens) as processes.
#pragma once
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

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

// Runs argv with stdout and stderr into files of `dir`; in `cwd` when given.
inline Outcome run(const std::vector<std::string>& argv, const fs::path& dir, const fs::path& cwd = {}) {
    std::string cmd = cwd.empty() ? "" : "cd " + quote(cwd.string()) + " && ";
    for (const std::string& a : argv) cmd += quote(a) + " ";
    const fs::path out = dir / "stdout.txt", err = dir / "stderr.txt";
    cmd += ">" + quote(out.string()) + " 2>" + quote(err.string()) + " </dev/null";
    int status = std::system(cmd.c_str());
    Outcome o;
    o.code = (status != -1 && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
    o.out = read_file(out);
    o.err = read_file(err);
    return o;
}

}  // namespace hlens_test
