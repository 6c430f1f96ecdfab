// A raw libzmq ROUTER echo on its own context and thread: the baseline the RPC round trip is
// measured against (issue 6: "p50 <= 1.5x a raw echo of the same bytes"). It returns every
// message unchanged, frames included, so a DEALER sending [requestId][""][request] gets
// [requestId][""][request] back through the same path as an RPC reply: a separate process
// (or at least a separate ZeroMQ context, with its own I/O thread), TCP on loopback, one
// thread that polls the socket. Nothing else: no parsing, no validation.
#pragma once

#include <zmq.hpp>

#include <atomic>
#include <string>
#include <thread>

namespace touchline::nao {

class EchoServer {
 public:
  // Binds tcp://bind:port (0: chosen by the OS, see port()) and starts the thread.
  EchoServer(const std::string& bind, int port);
  ~EchoServer();
  EchoServer(const EchoServer&) = delete;
  EchoServer& operator=(const EchoServer&) = delete;

  int port() const { return port_; }
  void stop();

 private:
  void loop();

  zmq::context_t context_;
  zmq::socket_t socket_;
  int port_ = 0;
  std::atomic<bool> stopping_{false};
  std::thread thread_;
};

}  // namespace touchline::nao
