#include "camera_server.h"

#include <cmath>

#include "log.h"
#include "nao.pb.h"
#include "zmq_envelope.h"

namespace touchline::nao {

CameraServer::CameraServer(CameraOptions options)
    : options_(std::move(options)),
      context_(1),
      socket_(context_, zmq::socket_type::router),
      start_(std::chrono::steady_clock::now()) {
  socket_.set(zmq::sockopt::linger, 0);
  socket_.set(zmq::sockopt::maxmsgsize, std::int64_t{1} << 20);  // requests are a few bytes
  socket_.set(zmq::sockopt::heartbeat_ivl, 1000);
  socket_.set(zmq::sockopt::heartbeat_timeout, 3000);
  if (options_.curve) {
    zap_ = std::make_unique<ZapHandler>(context_, options_.curve->allowedClients, "camera");
    makeCurveServer(socket_, *options_.curve);
  }
  socket_.bind(tcpEndpoint(options_.bind, options_.port));
  port_ = boundPort(socket_);
  thread_ = std::thread([this] { loop(); });
}

CameraServer::~CameraServer() { stop(); }

void CameraServer::stop() {
  stopping_ = true;
  if (thread_.joinable()) thread_.join();
}

void CameraServer::loop() {
  while (!stopping_) {
    socketLoopStep("camera", [this] {
      zmq::pollitem_t items[] = {{socket_.handle(), 0, ZMQ_POLLIN, 0}};
      zmq::poll(items, 1, std::chrono::milliseconds(100));
      if (!(items[0].revents & ZMQ_POLLIN)) return;
      std::vector<zmq::message_t> frames;
      if (!zmq::recv_multipart(socket_, std::back_inserter(frames))) return;
      if (!validEnvelope(frames)) {
        ++counters_.malformedEnvelopes;
        logLine("camera: dropped message with " + std::to_string(frames.size()) + " frames");
        return;
      }
      std::string reply;
      try {
        reply = handle(frames.back().to_string());
      } catch (const std::exception& e) {
        reply = error(std::string("camera failure: ") + e.what());
      }
      sendReply(socket_, frames, reply);
    });
  }
}

std::string CameraServer::error(const std::string& message) {
  ++counters_.errors;
  ::nao::CamResponse response;
  response.set_error(message);
  return response.SerializeAsString();
}

std::string CameraServer::handle(const std::string& payload) {
  ++counters_.requests;
  ::nao::CamRequest request;
  if (!payload.empty() && !request.ParseFromString(payload)) {
    logLine("camera: payload of " + std::to_string(payload.size()) + " bytes is not a CamRequest");
    return error("payload is not a CamRequest (" + std::to_string(payload.size()) + " bytes)");
  }
  if (request.has_resolution() || request.has_colorspace() || request.has_fps()) {
    CameraConfig next = config_.value_or(CameraConfig{});
    if (request.has_resolution()) next.resolution = request.resolution();
    if (request.has_colorspace()) next.colorSpace = request.colorspace();
    if (request.has_fps()) next.fps = request.fps();
    if (auto message = validateCamera(next)) return error(*message);
    config_ = next;
    frameIndex_ = -1;
    return ::nao::CamResponse().SerializeAsString();  // empty: configured
  }
  if (!config_) {
    return error("camera not configured: send a CamRequest with resolution, colorSpace or fps "
                 "before fetching frames");
  }
  ::nao::CamResponse response;
  response.set_imagedata(currentFrame());
  return response.SerializeAsString();
}

const std::string& CameraServer::currentFrame() {
  double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  auto index = static_cast<std::int64_t>(std::floor(elapsed * config_->fps));
  if (index != frameIndex_) {
    auto [w, h] = *resolutionSize(config_->resolution);
    // The picture is always rendered in RGB; single-channel spaces give a grey JPEG, all
    // others the same colour JPEG (a JPEG viewer cannot show raw YUV422 or HSY anyway).
    const auto& rgb = renderer_.render(w, h, static_cast<double>(index) / config_->fps);
    jpeg_ = encoder_.encode(rgb.data(), w, h, singleChannel(config_->colorSpace));
    frameIndex_ = index;
    ++counters_.framesRendered;
  }
  return jpeg_;
}

}  // namespace touchline::nao
