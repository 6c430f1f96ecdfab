// NAOqi camera parameters (alvisiondefinitions.h ids) and their validation, shared by the
// camera server and the simulated ALVideoDevice.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>

namespace touchline::nao {

struct CameraConfig {
  std::uint32_t resolution = 2;   // kVGA
  std::uint32_t colorSpace = 11;  // kRGB
  std::uint32_t fps = 30;
};

// 0 kQQVGA 160x120, 1 kQVGA 320x240, 2 kVGA 640x480, 3 k4VGA 1280x960 (the NAO V4 set).
inline std::optional<std::pair<int, int>> resolutionSize(std::uint32_t resolution) {
  switch (resolution) {
    case 0: return std::make_pair(160, 120);
    case 1: return std::make_pair(320, 240);
    case 2: return std::make_pair(640, 480);
    case 3: return std::make_pair(1280, 960);
    default: return std::nullopt;
  }
}

// Colour spaces 0..16 exist in the NAOqi 1.x header; 0..8 are single-channel.
inline bool knownColorSpace(std::uint32_t cs) { return cs <= 16; }
inline bool singleChannel(std::uint32_t cs) { return cs <= 8; }

inline std::optional<std::string> validateCamera(const CameraConfig& c) {
  if (!resolutionSize(c.resolution))
    return "unknown resolution " + std::to_string(c.resolution) +
           " (0 kQQVGA 160x120, 1 kQVGA 320x240, 2 kVGA 640x480, 3 k4VGA 1280x960)";
  if (!knownColorSpace(c.colorSpace))
    return "unknown colour space " + std::to_string(c.colorSpace) +
           " (0..16, e.g. 9 kYUV422, 10 kYUV, 11 kRGB, 12 kHSY, 13 kBGR)";
  if (c.fps < 1 || c.fps > 30) return "fps " + std::to_string(c.fps) + " outside 1..30";
  return std::nullopt;
}

}  // namespace touchline::nao
