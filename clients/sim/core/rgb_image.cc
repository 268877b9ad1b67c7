#include "clients/sim/core/rgb_image.h"

#include "clients/sim/core/ray_caster.h"

namespace semnav::sim {
namespace {

Rgb SurfaceColour(const Scene& scene, int32_t surface) {
  if (surface == kFloorSurface) return scene.floor_colour();
  if (surface == kCeilingSurface) return scene.ceiling_colour();
  if (surface >= 0) return scene.solids()[surface].colour;
  return Rgb{200, 220, 245};  // sky / out of range
}

}  // namespace

cv::Mat RenderRgb(const RenderedView& view, const Scene& scene) {
  const int w = view.intrinsics.width, h = view.intrinsics.height;
  cv::Mat image(h, w, CV_8UC3);
  for (int v = 0; v < h; ++v) {
    auto* row = image.ptr<cv::Vec3b>(v);
    for (int u = 0; u < w; ++u) {
      const size_t i = static_cast<size_t>(v) * w + u;
      const Rgb c = SurfaceColour(scene, view.surface[i]);
      const float s = view.surface[i] == kNoSurface ? 1.0f : view.shade[i];
      row[u] = cv::Vec3b(cv::saturate_cast<uint8_t>(c.b * s), cv::saturate_cast<uint8_t>(c.g * s),
                         cv::saturate_cast<uint8_t>(c.r * s));
    }
  }
  // Outlines where the visible surface changes between neighbouring pixels.
  cv::Mat edges = cv::Mat::zeros(h, w, CV_8UC1);
  for (int v = 0; v + 1 < h; ++v) {
    for (int u = 0; u + 1 < w; ++u) {
      const size_t i = static_cast<size_t>(v) * w + u;
      const int32_t s = view.surface[i];
      if (s != view.surface[i + 1] || s != view.surface[i + w]) {
        edges.at<uint8_t>(v, u) = 255;
      }
    }
  }
  image.setTo(cv::Scalar(40, 40, 40), edges);
  return image;
}

}  // namespace semnav::sim
