// The robot-side RPC module: a ZeroMQ ROUTER frontend and the ZeroMQ guide's
// load-balancing broker in front of N worker threads. A worker announces READY, the broker
// keeps a queue of free workers and reads the frontend only while one is free, so a short
// call never waits behind a long one while any worker is idle (round robin would queue it).
// Workers parse HAWActorRPCRequest, drop late requests, and dispatch module.method(params)
// into a NaoqiBroker.
#pragma once

#include <zmq.hpp>

#include <atomic>
#include <cstddef>
#include <string>
#include <thread>
#include <vector>

#include "naoqi_broker.h"
#include "rpc_counters.h"

namespace touchline::nao {

struct RpcOptions {
  std::string bind = "127.0.0.1";
  int port = 5555;  // 0: chosen by the OS, see port()
  int workers = 4;
  // Requests above this get an error reply without being parsed.
  std::size_t maxRequestBytes = 16u << 20;
  // Transport hard limit (ZMQ_MAXMSGSIZE): libzmq drops a peer that sends more.
  std::int64_t maxMessageBytes = 64ll << 20;
};

class RpcServer {
 public:
  // Binds and starts the threads; throws zmq::error_t if the port cannot be bound.
  RpcServer(NaoqiBroker& broker, RpcCounters& counters, RpcOptions options);
  ~RpcServer();
  RpcServer(const RpcServer&) = delete;
  RpcServer& operator=(const RpcServer&) = delete;

  int port() const { return port_; }
  // Stops the broker thread and the workers (waking blocking calls) and joins them.
  void stop();

  // Turns one request payload into reply bytes (exposed for tests).
  std::string handle(const std::string& payload);

 private:
  void brokerLoop();
  void workerLoop();
  std::string errorReply(const std::string& message);

  NaoqiBroker& broker_;
  RpcCounters& counters_;
  RpcOptions options_;
  zmq::context_t context_;
  zmq::socket_t frontend_;
  zmq::socket_t backend_;
  int port_ = 0;
  std::atomic<bool> stopping_{false};
  std::thread brokerThread_;
  std::vector<std::thread> workerThreads_;
};

}  // namespace touchline::nao
