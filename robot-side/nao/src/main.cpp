// touchline-nao-sim: the NAO robot side (RPC module + camera server) against the
// simulated NAOqi broker. Prints "rpc listening on port <p>" and "camera listening on
// port <p>" on stdout once both are bound; stops cleanly on SIGTERM/SIGINT. With
// --echo-port it also serves a raw ROUTER echo (the round-trip benchmark's baseline) and
// prints "echo listening on port <p>" first.
#include <csignal>
#include <cstring>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "camera_server.h"
#include "curve_security.h"
#include "echo_server.h"
#include "log.h"
#include "rpc_server.h"
#include "simulated_broker.h"

namespace {

void usage(std::ostream& out) {
  out << "usage: touchline-nao-sim [--rpc-port 5555] [--cam-port 5556] [--workers 4]\n"
         "                         [--bind 127.0.0.1] [--echo-port P]\n"
         "                         [--curve-secret nao-server.secret --curve-clients FILE|DIR...]\n"
         "  port 0 lets the OS choose; the chosen ports are printed on stdout.\n"
         "  --echo-port also serves a raw ROUTER echo (benchmark baseline); off by default.\n"
         "  --curve-secret: CURVE encryption with this server key pair (from `touchline keys new`);\n"
         "  --curve-clients: the console.public files (or directories of *.public files) of the\n"
         "  consoles allowed in; others are refused and logged. Without both: insecure.\n";
}

bool parseInt(const std::string& text, int min, int max, int& out) {
  try {
    std::size_t used = 0;
    int v = std::stoi(text, &used);
    if (used != text.size() || v < min || v > max) return false;
    out = v;
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace

int main(int argc, char** argv) {
  using namespace touchline::nao;
  RpcOptions rpc;
  CameraOptions cam;
  int echoPort = -1;  // off
  std::string curveSecret;
  std::vector<std::string> curveClients;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      usage(std::cout);
      return 0;
    }
    if (arg == "--curve-clients") {  // one or more values, up to the next option
      while (i + 1 < argc && std::string(argv[i + 1]).rfind("--", 0) != 0) curveClients.emplace_back(argv[++i]);
      if (curveClients.empty()) {
        std::cerr << "missing value for --curve-clients\n";
        return 2;
      }
      continue;
    }
    if (i + 1 >= argc) {
      std::cerr << "missing value for " << arg << "\n";
      usage(std::cerr);
      return 2;
    }
    std::string value = argv[++i];
    bool ok = true;
    if (arg == "--rpc-port") ok = parseInt(value, 0, 65535, rpc.port);
    else if (arg == "--cam-port") ok = parseInt(value, 0, 65535, cam.port);
    else if (arg == "--echo-port") ok = parseInt(value, 0, 65535, echoPort);
    else if (arg == "--workers") ok = parseInt(value, 1, 256, rpc.workers);
    else if (arg == "--bind") rpc.bind = cam.bind = value;
    else if (arg == "--curve-secret") curveSecret = value;
    else {
      std::cerr << "unknown option " << arg << "\n";
      usage(std::cerr);
      return 2;
    }
    if (!ok) {
      std::cerr << "bad value '" << value << "' for " << arg << "\n";
      return 2;
    }
  }

  // Block the stop signals in every thread (threads inherit the mask); main waits for them.
  sigset_t stopSignals;
  sigemptyset(&stopSignals);
  sigaddset(&stopSignals, SIGINT);
  sigaddset(&stopSignals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stopSignals, nullptr);

  if (curveSecret.empty() != curveClients.empty()) {
    std::cerr << "--curve-secret and --curve-clients go together: the server's key pair and the consoles it "
                 "lets in\n";
    return 2;
  }
  if (!curveSecret.empty()) {
    if (!curveAvailable()) {
      std::cerr << "touchline-nao-sim: this libzmq has no CURVE support (built without libsodium)\n";
      return 1;
    }
    try {
      rpc.curve = cam.curve = std::make_shared<const CurveServerKeys>(loadCurveServerKeys(curveSecret, curveClients));
    } catch (const std::exception& e) {
      std::cerr << "touchline-nao-sim: " << e.what() << "\n";
      return 2;
    }
  }
  // Logged after the "listening" lines: readers of the merged output take the ports from its first lines.
  std::string security = rpc.curve ? "CURVE on: " + std::to_string(rpc.curve->allowedClients.size()) +
                                         " console key(s) allowed, others refused"
                                   : "insecure: no --curve-secret, any client on the network may call and fetch "
                                     "frames (docs/security.md)";

  try {
    std::unique_ptr<EchoServer> echo;
    if (echoPort >= 0) {
      echo = std::make_unique<EchoServer>(rpc.bind, echoPort);
      std::cout << "echo listening on port " << echo->port() << "\n";
    }
    RpcCounters counters;
    SimulatedBroker broker(1.0, &counters);
    RpcServer rpcServer(broker, counters, rpc);
    CameraServer cameraServer(cam);
    std::cout << "rpc listening on port " << rpcServer.port() << "\n"
              << "camera listening on port " << cameraServer.port() << std::endl;
    logLine(security);
    int signal = 0;
    sigwait(&stopSignals, &signal);
    logLine(std::string("stopping on ") + strsignal(signal));
    rpcServer.stop();
    cameraServer.stop();
    for (auto [name, zap] : {std::pair{"rpc", rpcServer.zapCounters()}, std::pair{"camera", cameraServer.zapCounters()}}) {
      if (zap) logLine(std::string(name) + ": " + std::to_string(zap->refused.load()) + " client handshake(s) refused");
    }
    if (echo) echo->stop();
  } catch (const std::exception& e) {
    std::cerr << "touchline-nao-sim: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
