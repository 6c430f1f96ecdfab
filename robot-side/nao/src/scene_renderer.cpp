#include "scene_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace touchline::nao {

namespace {
// Field lines in metres: X lateral (right +), Z forward from the camera.
bool onLine(double x, double z) {
  constexpr double half = 0.025;  // 5 cm lines
  auto near = [&](double a, double b) { return std::abs(a - b) < half; };
  bool inField = x > -3.0 - half && x < 3.0 + half && z > 0.5 && z < 9.5;
  if (!inField) return false;
  if (near(x, -3.0) || near(x, 3.0)) return true;                 // touch lines
  if (near(z, 4.5) || near(z, 9.0)) return true;                  // centre and goal line
  double r = std::hypot(x, z - 4.5);
  if (std::abs(r - 0.75) < half) return true;                     // centre circle
  if (near(z, 8.4) && std::abs(x) < 1.1) return true;             // goal area
  if ((near(x, -1.1) || near(x, 1.1)) && z > 8.4 && z < 9.0) return true;
  if (std::hypot(x, z - 7.7) < 0.05) return true;                 // penalty mark
  return false;
}
}  // namespace

SceneRenderer::Projection SceneRenderer::projection(int width, int height) const {
  return {0.9 * width, width / 2.0, 0.3 * height, 0.5};
}

void SceneRenderer::buildBackground(int width, int height) {
  width_ = width;
  height_ = height;
  background_.assign(static_cast<std::size_t>(width) * height * 3, 0);
  Projection p = projection(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* px = &background_[(static_cast<std::size_t>(y) * width + x) * 3];
      if (y <= p.horizon) {
        int shade = 60 + 40 * y / std::max(1, static_cast<int>(p.horizon));
        px[0] = static_cast<std::uint8_t>(shade);
        px[1] = static_cast<std::uint8_t>(shade + 10);
        px[2] = static_cast<std::uint8_t>(shade + 35);
        continue;
      }
      // Inverse perspective: which field point does this pixel see?
      double z = p.f * p.cameraHeight / (y - p.horizon);
      double fx = (x - p.cx) * z / p.f;
      if (onLine(fx, z)) {
        px[0] = px[1] = px[2] = 235;
      } else {
        bool stripe = static_cast<int>(std::floor(z / 0.75)) % 2 == 0;
        px[0] = stripe ? 40 : 34;
        px[1] = stripe ? 145 : 128;
        px[2] = stripe ? 55 : 48;
      }
    }
  }
}

void SceneRenderer::fillRect(int x0, int y0, int x1, int y1, std::uint8_t r, std::uint8_t g,
                             std::uint8_t b) {
  x0 = std::max(0, x0);
  y0 = std::max(0, y0);
  x1 = std::min(width_, x1);
  y1 = std::min(height_, y1);
  for (int y = y0; y < y1; ++y) {
    std::uint8_t* px = &frame_[(static_cast<std::size_t>(y) * width_ + x0) * 3];
    for (int x = x0; x < x1; ++x, px += 3) {
      px[0] = r;
      px[1] = g;
      px[2] = b;
    }
  }
}

void SceneRenderer::drawBall(const Projection& p, double x, double z) {
  constexpr double radius = 0.05;
  double sx = p.cx + p.f * x / z;
  double sy = p.horizon + p.f * (p.cameraHeight - radius) / z;
  double r = std::max(1.5, p.f * radius / z);
  int y0 = static_cast<int>(sy - r), y1 = static_cast<int>(sy + r) + 1;
  int x0 = static_cast<int>(sx - r), x1 = static_cast<int>(sx + r) + 1;
  for (int y = std::max(0, y0); y < std::min(height_, y1); ++y) {
    for (int xx = std::max(0, x0); xx < std::min(width_, x1); ++xx) {
      double dx = xx - sx, dy = y - sy, d2 = dx * dx + dy * dy;
      if (d2 > r * r) continue;
      std::uint8_t* px = &frame_[(static_cast<std::size_t>(y) * width_ + xx) * 3];
      // Lit from the top left: a cheap highlight gives the ball some volume.
      double light = 1.0 - 0.35 * ((dx + dy) / (2 * r) + 0.5);
      px[0] = static_cast<std::uint8_t>(std::clamp(255 * light, 0.0, 255.0));
      px[1] = static_cast<std::uint8_t>(std::clamp(120 * light, 0.0, 255.0));
      px[2] = static_cast<std::uint8_t>(std::clamp(10 * light, 0.0, 255.0));
    }
  }
}

void SceneRenderer::drawRobot(const Projection& p, double x, double z) {
  double s = p.f / z;  // pixels per metre at this distance
  int cx = static_cast<int>(p.cx + x * s);
  int feet = static_cast<int>(p.horizon + p.cameraHeight * s);
  auto px = [&](double metres) { return static_cast<int>(metres * s); };
  fillRect(cx - px(0.10), feet - px(0.30), cx - px(0.02), feet, 200, 200, 205);  // legs
  fillRect(cx + px(0.02), feet - px(0.30), cx + px(0.10), feet, 200, 200, 205);
  fillRect(cx - px(0.13), feet - px(0.50), cx + px(0.13), feet - px(0.28), 240, 240, 240);
  fillRect(cx - px(0.13), feet - px(0.42), cx + px(0.13), feet - px(0.36), 30, 60, 200);  // jersey
  fillRect(cx - px(0.20), feet - px(0.49), cx - px(0.13), feet - px(0.30), 220, 220, 225);  // arms
  fillRect(cx + px(0.13), feet - px(0.49), cx + px(0.20), feet - px(0.30), 220, 220, 225);
  fillRect(cx - px(0.08), feet - px(0.62), cx + px(0.08), feet - px(0.50), 245, 245, 245);  // head
  fillRect(cx - px(0.05), feet - px(0.58), cx - px(0.02), feet - px(0.56), 20, 20, 30);  // eyes
  fillRect(cx + px(0.02), feet - px(0.58), cx + px(0.05), feet - px(0.56), 20, 20, 30);
}

const std::vector<std::uint8_t>& SceneRenderer::render(int width, int height, double seconds) {
  if (width != width_ || height != height_) buildBackground(width, height);
  frame_.resize(background_.size());
  std::memcpy(frame_.data(), background_.data(), background_.size());
  Projection p = projection(width, height);
  double ballX = 1.2 * std::sin(0.7 * seconds), ballZ = 2.5 + 1.5 * std::sin(0.45 * seconds);
  double robotX = 1.5 * std::cos(0.3 * seconds), robotZ = 4.0 + 0.8 * std::sin(0.3 * seconds);
  // Painter's order: the farther object first.
  if (robotZ > ballZ) {
    drawRobot(p, robotX, robotZ);
    drawBall(p, ballX, ballZ);
  } else {
    drawBall(p, ballX, ballZ);
    drawRobot(p, robotX, robotZ);
  }
  return frame_;
}

}  // namespace touchline::nao
