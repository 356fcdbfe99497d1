// Turntable camera: orbits a pivot around a fixed up axis (+Y or +Z), pans in the view plane and
// zooms by distance. Works in the scene's local coordinates (world minus the scene origin, floats).
#pragma once
#include <glm/glm.hpp>

namespace hlens::gui {

struct Camera {
    glm::vec3 pivot{0.0f};
    float distance = 5;
    float yaw = 0.6f;      // radians, around the up axis
    float pitch = 0.55f;   // radians above the horizontal plane
    float fovy = 0.70f;    // vertical field of view, radians
    int up_axis = 2;       // 1: +Y up, 2: +Z up
    float scene_radius = 1;

    glm::vec3 up() const { return up_axis == 1 ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1); }
    glm::vec3 eye_direction() const;   // unit vector from the pivot towards the eye
    glm::vec3 eye() const { return pivot + distance * eye_direction(); }
    glm::mat4 view() const;
    glm::mat4 projection(float aspect) const;

    // Mouse deltas in pixels; view_height in pixels.
    void orbit(float dx, float dy);
    void pan(float dx, float dy, float view_height);
    void zoom(float wheel_steps);
    // Default view of a box (local coordinates): pivot at its centre, the distance that fits all
    // eight corners into the view with a margin, at the default yaw and pitch.
    void frame(const glm::vec3& lo, const glm::vec3& hi, float aspect, bool reset_angles = true);
    // Frames a small part of the scene (same angles), keeping the clip planes of the whole scene.
    void focus(const glm::vec3& lo, const glm::vec3& hi, float aspect) {
        const float whole = scene_radius;
        frame(lo, hi, aspect, false);
        scene_radius = std::max(whole, scene_radius);
    }
};

// Up axis guess: +Z when the box is flat in Z (a height field, like the demo), otherwise +Y.
int guess_up_axis(const glm::vec3& lo, const glm::vec3& hi);

}  // namespace hlens::gui
