// RAII wrapper around a libjpeg-turbo compressor with a reusable output buffer.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace touchline::nao {

class JpegEncoder {
 public:
  static constexpr int kQuality = 75;

  JpegEncoder();
  // Encodes packed RGB. gray: luminance-only JPEG (for single-channel colour spaces),
  // otherwise 4:2:0 chroma subsampling. Throws std::runtime_error on a libjpeg error.
  std::string encode(const std::uint8_t* rgb, int width, int height, bool gray);

 private:
  struct Destroy {
    void operator()(void* handle) const;
  };
  std::unique_ptr<void, Destroy> handle_;
  std::vector<unsigned char> buffer_;
};

}  // namespace touchline::nao
