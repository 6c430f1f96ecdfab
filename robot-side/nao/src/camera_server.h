// Camera server (HAWCamServer contract): a ZeroMQ ROUTER on its own port. A CamRequest
// with any field set (re)configures; an empty request fetches the current frame of the
// synthetic camera as JPEG. Frames are rendered at most once per 1/fps period and shared
// by all clients in that period, like a real camera producing fps frames.
#pragma once

#include <zmq.hpp>

#include <atomic>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "camera_config.h"
#include "curve_security.h"
#include "jpeg_encoder.h"
#include "scene_renderer.h"

namespace touchline::nao {

struct CameraOptions {
  std::string bind = "127.0.0.1";
  int port = 5556;  // 0: chosen by the OS, see port()
  // CURVE server keys and the allowed consoles; null: insecure (any client may fetch frames).
  std::shared_ptr<const CurveServerKeys> curve;
};

struct CameraCounters {
  std::atomic<std::uint64_t> requests{0};
  std::atomic<std::uint64_t> framesRendered{0};
  std::atomic<std::uint64_t> errors{0};
  std::atomic<std::uint64_t> malformedEnvelopes{0};
};

class CameraServer {
 public:
  explicit CameraServer(CameraOptions options);
  ~CameraServer();
  CameraServer(const CameraServer&) = delete;
  CameraServer& operator=(const CameraServer&) = delete;

  int port() const { return port_; }
  void stop();
  const CameraCounters& counters() const { return counters_; }
  // The ZAP handler's counts (accepted, refused clients); null when insecure.
  const ZapCounters* zapCounters() const { return zap_ ? &zap_->counters() : nullptr; }

  // Turns one request payload into reply bytes (server thread only; exposed for tests).
  std::string handle(const std::string& payload);

 private:
  void loop();
  std::string error(const std::string& message);
  const std::string& currentFrame();

  CameraOptions options_;
  zmq::context_t context_;
  std::unique_ptr<ZapHandler> zap_;  // before the socket: destroyed after it, before the context
  zmq::socket_t socket_;
  int port_ = 0;
  std::atomic<bool> stopping_{false};
  CameraCounters counters_;

  std::optional<CameraConfig> config_;
  SceneRenderer renderer_;
  JpegEncoder encoder_;
  std::chrono::steady_clock::time_point start_;
  std::int64_t frameIndex_ = -1;  // index of the cached frame since start_, in 1/fps units
  std::string jpeg_;
  std::thread thread_;  // last: starts after everything above is constructed
};

}  // namespace touchline::nao
