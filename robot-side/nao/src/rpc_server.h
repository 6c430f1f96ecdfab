// The robot-side RPC module: a ZeroMQ ROUTER frontend and the ZeroMQ guide's
// load-balancing broker in front of N worker threads. Quick calls (NaoqiBroker::isQuick:
// getters, non-blocking setters, stop commands, unknown names) run on the broker thread
// itself, answered without any thread hand-off. Every other call goes to a free worker: a
// worker announces READY, the broker keeps a queue of free workers, and calls that find
// none wait in a bounded FIFO. So a short call never waits behind a long one, even while
// every worker is blocked (round robin to N workers would queue it behind a long call).
// Both paths parse HAWActorRPCRequest, drop late requests, and dispatch
// module.method(params) into a NaoqiBroker.
#pragma once

#include <zmq.hpp>

#include <atomic>
#include <cstddef>
#include <string>
#include <deque>
#include <memory>
#include <thread>
#include <vector>

#include "curve_security.h"
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
  // CURVE server keys and the allowed consoles; null: insecure (any client may call).
  std::shared_ptr<const CurveServerKeys> curve;
};

// Requests above this size are not parsed on the broker thread, whatever the method.
constexpr std::size_t kMaxInlineRequestBytes = 64u << 10;
// Bounds of the FIFO of calls waiting for a free worker; when full, the broker stops reading
// the frontend until a worker is free (requests then wait in the socket).
constexpr std::size_t kMaxWaitingCalls = 256;
constexpr std::size_t kMaxWaitingBytes = 64u << 20;

class RpcServer {
 public:
  // Binds and starts the threads; throws zmq::error_t if the port cannot be bound.
  RpcServer(NaoqiBroker& broker, RpcCounters& counters, RpcOptions options);
  ~RpcServer();
  RpcServer(const RpcServer&) = delete;
  RpcServer& operator=(const RpcServer&) = delete;

  int port() const { return port_; }
  // The ZAP handler's counts (accepted, refused clients); null when insecure.
  const ZapCounters* zapCounters() const { return zap_ ? &zap_->counters() : nullptr; }
  // Stops the broker thread and the workers (waking blocking calls) and joins them.
  void stop();

  // Turns one request payload into reply bytes (exposed for tests).
  std::string handle(const std::string& payload);

 private:
  void brokerLoop(std::deque<zmq::message_t> freeWorkers);
  void workerLoop();
  // Counts and checks a frontend message; answers an oversize one. False: nothing to run.
  bool admit(std::vector<zmq::message_t>& frames);
  // Runs a quick call (or answers a bad request) on the broker thread; false: needs a worker.
  bool answerInline(std::vector<zmq::message_t>& frames);
  std::string execute(::nao::HAWActorRPCRequest& request);
  std::string badRequest(const std::string& error);
  std::string errorReply(const std::string& message);

  NaoqiBroker& broker_;
  RpcCounters& counters_;
  RpcOptions options_;
  zmq::context_t context_;
  std::unique_ptr<ZapHandler> zap_;  // before the sockets: destroyed after them, before the context
  zmq::socket_t frontend_;
  zmq::socket_t backend_;
  int port_ = 0;
  std::atomic<bool> stopping_{false};
  std::thread brokerThread_;
  std::vector<std::thread> workerThreads_;
};

}  // namespace touchline::nao
