// Synthetic NAO head camera: a perspective view of a green field with white lines, an
// orange ball and a robot, both moving with time. The background (field and lines) is
// rendered once per resolution; a frame copies it and draws only ball and robot, so a
// 1280x960 frame costs a memcpy plus a few thousand pixels.
#pragma once

#include <cstdint>
#include <vector>

namespace touchline::nao {

class SceneRenderer {
 public:
  // RGB, width*height*3 bytes; the reference stays valid until the next render().
  const std::vector<std::uint8_t>& render(int width, int height, double seconds);

 private:
  struct Projection {
    double f, cx, horizon, cameraHeight;
  };
  Projection projection(int width, int height) const;
  void buildBackground(int width, int height);
  void drawBall(const Projection& p, double x, double z);
  void drawRobot(const Projection& p, double x, double z);
  void fillRect(int x0, int y0, int x1, int y1, std::uint8_t r, std::uint8_t g, std::uint8_t b);

  int width_ = 0;
  int height_ = 0;
  std::vector<std::uint8_t> background_;
  std::vector<std::uint8_t> frame_;
};

}  // namespace touchline::nao
