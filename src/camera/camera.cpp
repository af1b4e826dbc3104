#include "camera/camera.h"

namespace relt {

Camera::Camera(const PerspectiveCamera& desc, int width, int height) : width_(width), height_(height) {
  position_ = desc.position;
  right_ = glm::normalize(desc.toWorld[0]);
  up_ = glm::normalize(desc.toWorld[1]);
  forward_ = -glm::normalize(desc.toWorld[2]);
  tanHalfY_ = std::tan(0.5f * desc.yfov);
  // The render resolution sets the aspect ratio; yfov is kept (glTF semantics).
  tanHalfX_ = tanHalfY_ * static_cast<float>(width) / static_cast<float>(height);
  area_ = 4.0f * tanHalfX_ * tanHalfY_;
}

Vec3 Camera::direction(const Vec2& film) const {
  const float x = (2.0f * film.x / width_ - 1.0f) * tanHalfX_;
  const float y = (1.0f - 2.0f * film.y / height_) * tanHalfY_;
  return glm::normalize(forward_ + x * right_ + y * up_);
}

std::optional<Vec2> Camera::filmPosition(const Vec3& w) const {
  const float c = glm::dot(w, forward_);
  if (c <= 0.0f) return std::nullopt;
  const float x = glm::dot(w, right_) / c, y = glm::dot(w, up_) / c;
  const Vec2 film((x / tanHalfX_ + 1.0f) * 0.5f * width_, (1.0f - y / tanHalfY_) * 0.5f * height_);
  if (!(film.x >= 0.0f && film.x < width_ && film.y >= 0.0f && film.y < height_)) return std::nullopt;
  return film;
}

float Camera::importance(const Vec3& w) const {
  const float c = glm::dot(w, forward_);
  if (c <= 0.0f) return 0.0f;
  return 1.0f / (area_ * c * c * c * c);
}

float Camera::pdfDirection(const Vec3& w) const {
  const float c = glm::dot(w, forward_);
  if (c <= 0.0f) return 0.0f;
  return 1.0f / (area_ * c * c * c);
}

}  // namespace relt
