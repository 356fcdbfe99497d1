// Built-in degenerate configurations for the "Cases" menu and --case NAME [--epsilon E]: small
// pairs (A, B) made in code, each with h(A,B) known by hand (see cases.cpp for the derivations).
#pragma once
#include <string>
#include <vector>

#include <hlens/mesh.h>

namespace hlens::gui {

struct BuiltinCase {
    const char* name;         // for --case and the menu
    const char* description;
};
const std::vector<BuiltinCase>& builtin_cases();

// Builds case `name` with near-degeneracy `eps` (0: exactly degenerate). Returns false for an
// unknown name. `hand_ab` receives the hand-derived h(A,B).
bool make_case(const std::string& name, double eps, TriangleMesh& a, TriangleMesh& b, double& hand_ab);

}  // namespace hlens::gui
