#include "rpc_server.h"

#include <chrono>
#include <deque>

#include "log.h"
#include "zmq_envelope.h"

namespace touchline::nao {

namespace {
const char* kWorkersEndpoint = "inproc://nao-rpc-workers";
const std::string kReady = "READY";
constexpr auto kPollPeriod = std::chrono::milliseconds(100);

std::uint64_t nowMillis() {
  return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::milliseconds>(
      std::chrono::system_clock::now().time_since_epoch()).count());
}
}  // namespace

RpcServer::RpcServer(NaoqiBroker& broker, RpcCounters& counters, RpcOptions options)
    : broker_(broker),
      counters_(counters),
      options_(std::move(options)),
      context_(1),
      frontend_(context_, zmq::socket_type::router),
      backend_(context_, zmq::socket_type::router) {
  frontend_.set(zmq::sockopt::linger, 0);
  frontend_.set(zmq::sockopt::maxmsgsize, options_.maxMessageBytes);
  // Server-side heartbeats notice dead clients; clients run their own for dead servers.
  frontend_.set(zmq::sockopt::heartbeat_ivl, 1000);
  frontend_.set(zmq::sockopt::heartbeat_timeout, 3000);
  if (options_.curve) {
    zap_ = std::make_unique<ZapHandler>(context_, options_.curve->allowedClients, "rpc");
    makeCurveServer(frontend_, *options_.curve);
  }
  frontend_.bind(tcpEndpoint(options_.bind, options_.port));
  port_ = boundPort(frontend_);
  backend_.set(zmq::sockopt::linger, 0);
  backend_.bind(kWorkersEndpoint);
  int workers = options_.workers < 1 ? 1 : options_.workers;
  for (int i = 0; i < workers; ++i) workerThreads_.emplace_back([this] { workerLoop(); });
  // The server takes calls only once every worker has announced itself: a call that arrived
  // before a worker's READY would wait for no reason and count as queued (a flaky test saw
  // two queued calls where one was expected). The broker thread takes the sockets over after.
  std::deque<zmq::message_t> freeWorkers;
  while (static_cast<int>(freeWorkers.size()) < workers) {
    std::vector<zmq::message_t> frames;
    if (!zmq::recv_multipart(backend_, std::back_inserter(frames)) || frames.empty()) continue;
    freeWorkers.push_back(std::move(frames.front()));
  }
  brokerThread_ = std::thread([this, ready = std::move(freeWorkers)]() mutable { brokerLoop(std::move(ready)); });
}

RpcServer::~RpcServer() { stop(); }

void RpcServer::stop() {
  if (stopping_.exchange(true)) return;
  broker_.shutdown();  // blocking NAOqi calls return so workers can see the flag
  if (brokerThread_.joinable()) brokerThread_.join();
  for (auto& t : workerThreads_) if (t.joinable()) t.join();
}

void RpcServer::brokerLoop(std::deque<zmq::message_t> freeWorkers) {  // worker identities
  std::deque<std::vector<zmq::message_t>> waiting;    // calls for a worker while none is free
  std::size_t waitingBytes = 0;
  while (!stopping_) {
    socketLoopStep("rpc broker", [&] {
      zmq::pollitem_t items[] = {{backend_.handle(), 0, ZMQ_POLLIN, 0},
                                 {frontend_.handle(), 0, ZMQ_POLLIN, 0}};
      // The frontend is read whenever the waiting queue has room, so a quick call is answered
      // even while every worker is busy; a full queue pushes back into the socket.
      bool room = waiting.size() < kMaxWaitingCalls && waitingBytes < kMaxWaitingBytes;
      zmq::poll(items, room ? 2 : 1, kPollPeriod);

      if (items[0].revents & ZMQ_POLLIN) {
        std::vector<zmq::message_t> frames;
        if (!zmq::recv_multipart(backend_, std::back_inserter(frames))) return;
        zmq::message_t worker = std::move(frames.front());
        freeWorkers.push_back(std::move(worker));
        if (!(frames.size() == 2 && frames[1].to_string() == kReady)) {
          // A reply: [worker][client envelope...][reply] -> frontend without the worker id.
          for (std::size_t i = 1; i < frames.size(); ++i) {
            frontend_.send(frames[i], i + 1 < frames.size() ? zmq::send_flags::sndmore
                                                            : zmq::send_flags::none);
          }
        }
      }

      if (items[1].revents & ZMQ_POLLIN) {
        std::vector<zmq::message_t> frames;
        if (!zmq::recv_multipart(frontend_, std::back_inserter(frames))) return;
        if (admit(frames) && !answerInline(frames)) {
          waitingBytes += frames.back().size();
          waiting.push_back(std::move(frames));
          if (freeWorkers.empty()) ++counters_.queuedCalls;
        }
      }

      // Work pulling: a call goes only to a worker that announced itself free.
      while (!freeWorkers.empty() && !waiting.empty()) {
        std::vector<zmq::message_t>& frames = waiting.front();
        waitingBytes -= frames.back().size();
        backend_.send(freeWorkers.front(), zmq::send_flags::sndmore);
        freeWorkers.pop_front();
        for (std::size_t i = 0; i < frames.size(); ++i) {
          backend_.send(frames[i], i + 1 < frames.size() ? zmq::send_flags::sndmore
                                                         : zmq::send_flags::none);
        }
        waiting.pop_front();
      }
    });
  }
}

bool RpcServer::admit(std::vector<zmq::message_t>& frames) {
  if (!validEnvelope(frames)) {
    ++counters_.malformedEnvelopes;
    logLine("rpc: dropped message with " + std::to_string(frames.size()) +
            " frames (expected [requestId][\"\"][payload])");
    return false;
  }
  ++counters_.requests;
  if (frames.back().size() > options_.maxRequestBytes) {
    ++counters_.oversize;
    logLine("rpc: request of " + std::to_string(frames.back().size()) + " bytes rejected");
    sendReply(frontend_, frames,
              errorReply("request of " + std::to_string(frames.back().size()) +
                         " bytes exceeds the limit of " + std::to_string(options_.maxRequestBytes) +
                         " bytes"));
    return false;
  }
  return true;
}

bool RpcServer::answerInline(std::vector<zmq::message_t>& frames) {
  // Large requests are not even parsed here: parsing megabytes would hold up quick calls.
  if (frames.back().size() > kMaxInlineRequestBytes) return false;
  ::nao::HAWActorRPCRequest request;
  if (auto error = parseRequest(frames.back().to_string(), request)) {
    sendReply(frontend_, frames, badRequest(*error));
    return true;
  }
  if (!broker_.isQuick(request.module(), request.method())) return false;
  ++counters_.inlineCalls;
  sendReply(frontend_, frames, execute(request));
  return true;
}

void RpcServer::workerLoop() {
  zmq::socket_t socket(context_, zmq::socket_type::dealer);
  socket.set(zmq::sockopt::linger, 0);
  socket.connect(kWorkersEndpoint);
  // A receive timeout (not a poll) keeps the hot path to one call; it bounds shutdown time.
  socket.set(zmq::sockopt::rcvtimeo, static_cast<int>(kPollPeriod.count()));
  socket.send(zmq::buffer(kReady), zmq::send_flags::none);
  while (!stopping_) {
    socketLoopStep("rpc worker", [&] {
      std::vector<zmq::message_t> frames;
      if (!zmq::recv_multipart(socket, std::back_inserter(frames)) || frames.empty()) return;
      std::string reply = handle(frames.back().to_string());
      sendReply(socket, frames, reply);
    });
  }
}

std::string RpcServer::errorReply(const std::string& message) {
  ++counters_.errors;
  ++counters_.replies;
  ::nao::HAWActorRPCResponse response;
  response.set_error(message);
  return response.SerializeAsString();
}

std::string RpcServer::badRequest(const std::string& error) {
  ++counters_.malformedPayloads;
  logLine("rpc: bad request: " + error);
  return errorReply("bad request: " + error);
}

std::string RpcServer::handle(const std::string& payload) {
  ::nao::HAWActorRPCRequest request;
  if (auto error = parseRequest(payload, request)) return badRequest(*error);
  return execute(request);
}

std::string RpcServer::execute(::nao::HAWActorRPCRequest& request) {
  std::string name = request.module() + "." + request.method();
  if (request.has_deadlinemillis() && nowMillis() > request.deadlinemillis()) {
    // Late calls are answered with an error, never executed: a walk command that arrives
    // after the client gave up must not move the robot.
    ++counters_.deadlinePassed;
    logLine("rpc: " + name + " not executed: deadline passed " +
            std::to_string(nowMillis() - request.deadlinemillis()) + " ms ago");
    return errorReply("deadline passed: " + name + " was not executed");
  }
  Params params;
  params.reserve(static_cast<std::size_t>(request.params_size()));
  for (auto& p : *request.mutable_params()) params.push_back(std::move(p));
  ::nao::HAWActorRPCResponse response;
  try {
    if (auto value = broker_.call(request.module(), request.method(), params)) {
      *response.mutable_returnval() = std::move(*value);
    }
  } catch (const CallError& e) {
    return errorReply(e.what());
  } catch (const std::exception& e) {
    return errorReply("exception in " + name + ": " + e.what());
  }
  ++counters_.replies;
  return response.SerializeAsString();
}

}  // namespace touchline::nao
