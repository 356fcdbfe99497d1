// The independent overlay of the domain view: every pixel of T' coloured by the source feature
// nearest there (which inserted source triangle, and its face, an edge or a vertex), computed
// directly from the inserted sources' corners (a point-triangle region test per source, in double
// precision on the CPU), without the domain mesh; then compared against the domain mesh's labels.
#pragma once

namespace hlens::gui {

struct Stepper;
// Rebuilds the overlay texture and the comparison when the stepper's state changed.
// Needs a GL context (uploads the texture).
void update_overlay(Stepper& st);

}  // namespace hlens::gui
