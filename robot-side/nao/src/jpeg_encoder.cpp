#include "jpeg_encoder.h"

#include <turbojpeg.h>

#include <stdexcept>

namespace touchline::nao {

void JpegEncoder::Destroy::operator()(void* handle) const { tjDestroy(handle); }

JpegEncoder::JpegEncoder() : handle_(tjInitCompress()) {
  if (!handle_) throw std::runtime_error("tjInitCompress failed");
}

std::string JpegEncoder::encode(const std::uint8_t* rgb, int width, int height, bool gray) {
  int subsampling = gray ? TJSAMP_GRAY : TJSAMP_420;
  unsigned long capacity = tjBufSize(width, height, subsampling);
  if (buffer_.size() < capacity) buffer_.resize(capacity);
  unsigned char* out = buffer_.data();
  unsigned long size = capacity;
  // NOREALLOC: write into our buffer, sized by tjBufSize for the worst case.
  if (tjCompress2(handle_.get(), rgb, width, 0, height, TJPF_RGB, &out, &size, subsampling,
                  kQuality, TJFLAG_NOREALLOC | TJFLAG_FASTDCT) != 0) {
    throw std::runtime_error(std::string("JPEG encoding failed: ") + tjGetErrorStr2(handle_.get()));
  }
  return std::string(reinterpret_cast<const char*>(out), size);
}

}  // namespace touchline::nao
