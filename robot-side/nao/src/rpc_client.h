// Minimal C++ client of the RPC and camera servers (DEALER, frames [requestId][""][payload]),
// used by the tests and the benchmark. The console's real client is Java (NaoLink).
#pragma once

#include <zmq.hpp>
#include <zmq_addon.hpp>

#include <chrono>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mixed_value.h"

namespace touchline::nao {

class DealerClient {
 public:
  DealerClient(zmq::context_t& context, const std::string& endpoint)
      : socket_(context, zmq::socket_type::dealer) {
    socket_.set(zmq::sockopt::linger, 0);
    socket_.connect(endpoint);
  }

  // Sends [requestId][""][payload]; returns the id.
  std::string send(const std::string& payload) {
    std::string id = std::to_string(++nextId_);
    sendFrames({id, "", payload});
    return id;
  }

  void sendFrames(const std::vector<std::string>& frames) {
    for (std::size_t i = 0; i < frames.size(); ++i) {
      socket_.send(zmq::buffer(frames[i]),
                   i + 1 < frames.size() ? zmq::send_flags::sndmore : zmq::send_flags::none);
    }
  }

  // Next reply as (requestId, payload), or nothing within timeout.
  std::optional<std::pair<std::string, std::string>> receive(std::chrono::milliseconds timeout) {
    zmq::pollitem_t items[] = {{socket_.handle(), 0, ZMQ_POLLIN, 0}};
    zmq::poll(items, 1, timeout);
    if (!(items[0].revents & ZMQ_POLLIN)) return std::nullopt;
    std::vector<zmq::message_t> frames;
    if (!zmq::recv_multipart(socket_, std::back_inserter(frames)) || frames.size() != 3)
      return std::nullopt;
    return std::make_pair(frames[0].to_string(), frames[2].to_string());
  }

  // Sends payload and waits for the reply with the same id (others are discarded).
  std::optional<std::string> roundTrip(const std::string& payload,
                                       std::chrono::milliseconds timeout) {
    std::string id = send(payload);
    auto deadline = std::chrono::steady_clock::now() + timeout;
    while (true) {
      auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
          deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0) return std::nullopt;
      auto reply = receive(left);
      if (!reply) return std::nullopt;
      if (reply->first == id) return reply->second;
    }
  }

  zmq::socket_t& socket() { return socket_; }

 private:
  zmq::socket_t socket_;
  std::uint64_t nextId_ = 0;
};

inline std::string encodeRequest(const std::string& module, const std::string& method,
                                 const Params& params = {}, std::uint64_t deadlineMillis = 0) {
  ::nao::HAWActorRPCRequest request;
  request.set_module(module);
  request.set_method(method);
  for (const auto& p : params) *request.add_params() = p;
  if (deadlineMillis) request.set_deadlinemillis(deadlineMillis);
  return request.SerializeAsString();
}

// Calls module.method over the client; nothing on timeout.
inline std::optional<::nao::HAWActorRPCResponse> rpcCall(DealerClient& client,
                                                         const std::string& module,
                                                         const std::string& method,
                                                         const Params& params = {},
                                                         std::chrono::milliseconds timeout =
                                                             std::chrono::milliseconds(5000)) {
  auto reply = client.roundTrip(encodeRequest(module, method, params), timeout);
  if (!reply) return std::nullopt;
  ::nao::HAWActorRPCResponse response;
  if (!response.ParseFromString(*reply)) return std::nullopt;
  return response;
}

inline std::string loopback(int port) { return "tcp://127.0.0.1:" + std::to_string(port); }

}  // namespace touchline::nao
