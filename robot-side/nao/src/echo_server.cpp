#include "echo_server.h"

#include <chrono>
#include <vector>

#include "zmq_envelope.h"

namespace touchline::nao {

EchoServer::EchoServer(const std::string& bind, int port)
    : context_(1), socket_(context_, zmq::socket_type::router) {
  socket_.set(zmq::sockopt::linger, 0);
  socket_.bind(tcpEndpoint(bind, port));
  port_ = boundPort(socket_);
  thread_ = std::thread([this] { loop(); });
}

EchoServer::~EchoServer() { stop(); }

void EchoServer::stop() {
  if (stopping_.exchange(true)) return;
  if (thread_.joinable()) thread_.join();
}

void EchoServer::loop() {
  // The same wait as the RPC broker thread: a poll with a period, so stop() is noticed.
  while (!stopping_) {
    socketLoopStep("echo", [&] {
      zmq::pollitem_t items[] = {{socket_.handle(), 0, ZMQ_POLLIN, 0}};
      zmq::poll(items, 1, std::chrono::milliseconds(100));
      if (!(items[0].revents & ZMQ_POLLIN)) return;
      std::vector<zmq::message_t> frames;
      if (zmq::recv_multipart(socket_, std::back_inserter(frames))) zmq::send_multipart(socket_, frames);
    });
  }
}

}  // namespace touchline::nao
