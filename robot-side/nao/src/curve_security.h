// CURVE security for the robot side's ZeroMQ servers (RPC and camera): the NAO's server key
// pair from nao-server.secret, the console public keys it accepts (console.public files, one
// per team laptop), and a ZAP handler (RFC 27) that lets in only those keys. The key files are
// the console's `touchline keys new` files (docs/security.md): UTF-8 text, '#' comments, blank
// lines, and `name = value` lines with 40-character Z85 CURVE keys.
#pragma once

#include <zmq.hpp>

#include <atomic>
#include <cstdint>
#include <memory>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace touchline::nao {

struct CurveServerKeys {
  std::string publicKey;  // Z85, 40 characters
  std::string secretKey;  // Z85, 40 characters
  // The 32-byte binary public keys of the consoles allowed in (as ZAP hands them over).
  std::set<std::string> allowedClients;
};

// Reads the server key pair from nao-server.secret and the allowed client keys from each path
// (a console.public file, or a directory whose *.public files are read, nao-server.public
// excepted). Throws std::runtime_error with a message naming the file and what is wrong with it.
CurveServerKeys loadCurveServerKeys(const std::string& secretFile, const std::vector<std::string>& clientPaths);

// The value of `name` in a key file's text; throws std::runtime_error naming `source` when it is
// missing, or when it is not a valid 40-character Z85 CURVE key. Returns the Z85 text.
std::string curveKeyValue(const std::string& text, const std::string& name, const std::string& source);

// True when this libzmq was built with CURVE (libsodium); the robot side refuses the options otherwise.
bool curveAvailable();

struct ZapCounters {
  std::atomic<std::uint64_t> accepted{0};
  std::atomic<std::uint64_t> refused{0};
};

// The ZAP handler of one ZeroMQ context: a REP socket on inproc://zeromq.zap.01 served by its
// own thread (zmq::poll, so stop() is noticed within 100 ms). Accepts a CURVE client whose
// public key is in the allowed set; refuses anything else with 400, logs the refusal with the
// peer's address ("rpc: refused a client without an allowed key from 127.0.0.1") and counts it.
// Must be constructed before the context's server sockets bind, and destroyed before the context.
class ZapHandler {
 public:
  ZapHandler(zmq::context_t& context, std::set<std::string> allowedClients, std::string server);
  ~ZapHandler();
  ZapHandler(const ZapHandler&) = delete;
  ZapHandler& operator=(const ZapHandler&) = delete;

  const ZapCounters& counters() const { return counters_; }
  void stop();

 private:
  void loop();
  void answer(std::vector<zmq::message_t>& request);

  std::set<std::string> allowed_;
  std::string server_;
  zmq::socket_t socket_;
  std::atomic<bool> stopping_{false};
  ZapCounters counters_;
  std::thread thread_;  // last: starts after everything above is constructed
};

// Makes `socket` a CURVE server with `keys` and the ZAP domain "touchline" (before bind).
void makeCurveServer(zmq::socket_t& socket, const CurveServerKeys& keys);

}  // namespace touchline::nao
