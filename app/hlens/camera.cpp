#include "camera.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace hlens::gui {

namespace {
constexpr float kDefaultYaw = -1.05f, kDefaultPitch = 0.62f;
constexpr float kPitchLimit = 1.55f;
}  // namespace

glm::vec3 Camera::eye_direction() const {
    float c = std::cos(pitch), s = std::sin(pitch);
    if (up_axis == 1) return {c * std::sin(yaw), s, c * std::cos(yaw)};
    return {c * std::cos(yaw), c * std::sin(yaw), s};
}

glm::mat4 Camera::view() const { return glm::lookAt(eye(), pivot, up()); }

glm::mat4 Camera::projection(float aspect) const {
    float n = std::max(distance * 0.01f, scene_radius * 1e-4f);
    float f = distance + 4 * scene_radius + n;
    return glm::perspective(fovy, std::max(aspect, 1e-3f), n, f);
}

void Camera::orbit(float dx, float dy) {
    yaw -= dx * 0.008f;
    pitch = std::clamp(pitch + dy * 0.008f, -kPitchLimit, kPitchLimit);
}

void Camera::pan(float dx, float dy, float view_height) {
    glm::vec3 back = eye_direction();
    glm::vec3 right = glm::normalize(glm::cross(up(), back));
    glm::vec3 cam_up = glm::cross(back, right);
    float units_per_pixel = 2 * distance * std::tan(fovy / 2) / std::max(view_height, 1.0f);
    pivot += (-dx * right + dy * cam_up) * units_per_pixel;
}

void Camera::zoom(float wheel_steps) {
    distance *= std::pow(0.88f, wheel_steps);
    distance = std::clamp(distance, scene_radius * 1e-4f, scene_radius * 1e3f);
}

void Camera::frame(const glm::vec3& lo, const glm::vec3& hi, float aspect, bool reset_angles) {
    if (reset_angles) {
        yaw = kDefaultYaw;
        pitch = kDefaultPitch;
    }
    pivot = 0.5f * (lo + hi);
    scene_radius = std::max(0.5f * glm::length(hi - lo), 1e-6f);
    // Camera axes at this yaw/pitch; for every corner c (relative to the pivot) with coordinates
    // (x, y, z) along (right, up, back), it is inside the view when |x| <= (d - z) tan(fovx/2)
    // and |y| <= (d - z) tan(fovy/2): the smallest d satisfying all, with a margin.
    glm::vec3 back = eye_direction();
    glm::vec3 right = glm::normalize(glm::cross(up(), back));
    glm::vec3 cam_up = glm::cross(back, right);
    const float margin = 0.9f;
    float ty = std::tan(fovy / 2) * margin, tx = ty * std::max(aspect, 1e-3f);
    float d = 0;
    for (int i = 0; i < 8; ++i) {
        glm::vec3 c((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
        c -= pivot;
        float x = glm::dot(c, right), y = glm::dot(c, cam_up), z = glm::dot(c, back);
        d = std::max({d, z + std::fabs(x) / tx, z + std::fabs(y) / ty});
    }
    distance = std::max(d, scene_radius * 0.05f);
}

int guess_up_axis(const glm::vec3& lo, const glm::vec3& hi) {
    glm::vec3 e = hi - lo;
    return e.z < 0.5f * std::min(e.x, e.y) ? 2 : 1;
}

}  // namespace hlens::gui
