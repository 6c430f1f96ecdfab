// Frame layouts accepted on a ROUTER socket and the endpoint helpers shared by the RPC and
// camera servers.
//   DEALER client: [identity][requestId][""][payload]  (what NaoLink sends)
//   REQ client:    [identity][""][payload]
// Anything else is malformed. A reply repeats every frame before the payload.
#pragma once

#include <zmq.hpp>
#include <zmq_addon.hpp>

#include <string>
#include <vector>

namespace touchline::nao {

inline bool validEnvelope(const std::vector<zmq::message_t>& frames) {
  if (frames.size() == 4) return frames[2].size() == 0;
  if (frames.size() == 3) return frames[1].size() == 0;
  return false;
}

// Sends frames[0..n-2] followed by reply on socket (ROUTER).
inline void sendReply(zmq::socket_t& socket, std::vector<zmq::message_t>& frames,
                      const std::string& reply) {
  for (std::size_t i = 0; i + 1 < frames.size(); ++i) {
    socket.send(frames[i], zmq::send_flags::sndmore);
  }
  socket.send(zmq::buffer(reply), zmq::send_flags::none);
}

// "tcp://<bind>:<port>", with port 0 meaning "let the OS choose".
inline std::string tcpEndpoint(const std::string& bind, int port) {
  return "tcp://" + bind + ":" + (port == 0 ? std::string("*") : std::to_string(port));
}

inline int boundPort(zmq::socket_t& socket) {
  std::string endpoint = socket.get(zmq::sockopt::last_endpoint);
  return std::stoi(endpoint.substr(endpoint.rfind(':') + 1));
}

}  // namespace touchline::nao
