#pragma once
// Pinhole camera with the importance function needed by light tracing (t = 1 strategies).
// Film coordinates: x in [0, width) to the right, y in [0, height) downwards.
#include <optional>

#include "core/math.h"
#include "scene/scene.h"

namespace relt {

class Camera {
 public:
  Camera(const PerspectiveCamera& desc, int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }
  const Vec3& position() const { return position_; }
  const Vec3& forward() const { return forward_; }

  // Direction through a film position.
  Vec3 direction(const Vec2& film) const;
  // Film position seen in world direction w from the camera, if inside the frame.
  std::optional<Vec2> filmPosition(const Vec3& w) const;

  // Importance We for direction w, normalised over the whole film: the film plane at distance 1
  // has area A, and We = 1 / (A cos^4 theta) (pbrt-v3 16.1.1). Splats add film-wide estimates;
  // dividing by samples per pixel gives pixel values.
  float importance(const Vec3& w) const;
  // Solid-angle density of the camera's ray direction w: 1 / (A cos^3 theta).
  float pdfDirection(const Vec3& w) const;

 private:
  Vec3 position_, right_, up_, forward_;
  float tanHalfX_, tanHalfY_, area_;
  int width_, height_;
};

}  // namespace relt
