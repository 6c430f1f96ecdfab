#include "curve_security.h"

#include <zmq_addon.hpp>

#include <dirent.h>
#include <sys/stat.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "log.h"

namespace touchline::nao {

namespace {

constexpr std::size_t kZ85KeyChars = 40;
constexpr std::size_t kKeyBytes = 32;
const char* kZapEndpoint = "inproc://zeromq.zap.01";

std::string trim(const std::string& s) {
  auto begin = s.find_first_not_of(" \t\r");
  if (begin == std::string::npos) return "";
  auto end = s.find_last_not_of(" \t\r");
  return s.substr(begin, end - begin + 1);
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot read the key file (missing, or no permission)");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

bool isDirectory(const std::string& path) {
  struct stat st {};
  return stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string binaryKey(const std::string& z85) {
  std::string key(kKeyBytes, '\0');
  zmq_z85_decode(reinterpret_cast<std::uint8_t*>(key.data()), z85.c_str());
  return key;
}

void addClientFile(const std::string& file, std::set<std::string>& out) {
  out.insert(binaryKey(curveKeyValue(readFile(file), "public-key", file)));
}

}  // namespace

std::string curveKeyValue(const std::string& text, const std::string& name, const std::string& source) {
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    auto eq = t.find('=');
    if (eq == std::string::npos) {
      throw std::runtime_error(source + " line " + std::to_string(number) +
                               ": not 'name = value' (a corrupted key file? make a new one with `touchline keys new`)");
    }
    if (trim(t.substr(0, eq)) != name) continue;
    std::string value = trim(t.substr(eq + 1));
    if (value.size() != kZ85KeyChars) {
      throw std::runtime_error(source + ": " + name + " has " + std::to_string(value.size()) +
                               " characters, a CURVE key has 40 (Z85)");
    }
    std::uint8_t key[kKeyBytes];
    if (zmq_z85_decode(key, value.c_str()) == nullptr) {
      throw std::runtime_error(source + ": " + name + " is not valid Z85 text");
    }
    return value;
  }
  throw std::runtime_error(source + ": no '" + name + " = ...' line (is this the right key file?)");
}

bool curveAvailable() { return zmq_has("curve") != 0; }

CurveServerKeys loadCurveServerKeys(const std::string& secretFile, const std::vector<std::string>& clientPaths) {
  CurveServerKeys keys;
  std::string text = readFile(secretFile);
  keys.publicKey = curveKeyValue(text, "public-key", secretFile);
  keys.secretKey = curveKeyValue(text, "secret-key", secretFile);
  for (const auto& path : clientPaths) {
    if (!isDirectory(path)) {
      addClientFile(path, keys.allowedClients);
      continue;
    }
    std::unique_ptr<DIR, int (*)(DIR*)> dir(opendir(path.c_str()), closedir);
    if (!dir) throw std::runtime_error(path + ": cannot list the directory");
    while (dirent* entry = readdir(dir.get())) {
      std::string name = entry->d_name;
      if (endsWith(name, ".public") && name != "nao-server.public") addClientFile(path + "/" + name, keys.allowedClients);
    }
  }
  if (keys.allowedClients.empty()) {
    throw std::runtime_error("no console public key found in --curve-clients (give console.public files or a "
                             "directory holding them)");
  }
  return keys;
}

void makeCurveServer(zmq::socket_t& socket, const CurveServerKeys& keys) {
  socket.set(zmq::sockopt::zap_domain, "touchline");
  socket.set(zmq::sockopt::curve_server, true);
  socket.set(zmq::sockopt::curve_secretkey, keys.secretKey);
  socket.set(zmq::sockopt::curve_publickey, keys.publicKey);
}

ZapHandler::ZapHandler(zmq::context_t& context, std::set<std::string> allowedClients, std::string server)
    : allowed_(std::move(allowedClients)), server_(std::move(server)), socket_(context, zmq::socket_type::rep) {
  socket_.set(zmq::sockopt::linger, 0);
  socket_.bind(kZapEndpoint);
  thread_ = std::thread([this] { loop(); });
}

ZapHandler::~ZapHandler() { stop(); }

void ZapHandler::stop() {
  stopping_ = true;
  if (thread_.joinable()) thread_.join();
  socket_.close();
}

void ZapHandler::loop() {
  while (!stopping_) {
    try {
      zmq::pollitem_t items[] = {{socket_.handle(), 0, ZMQ_POLLIN, 0}};
      zmq::poll(items, 1, std::chrono::milliseconds(100));
      if (!(items[0].revents & ZMQ_POLLIN)) continue;
      std::vector<zmq::message_t> request;
      if (!zmq::recv_multipart(socket_, std::back_inserter(request))) continue;
      answer(request);
    } catch (const zmq::error_t& e) {
      if (e.num() == ETERM) return;
      if (e.num() != EINTR) logLine(server_ + ": ZAP handler: " + e.what());
    }
  }
}

// Request (RFC 27): version, request id, domain, address, identity, mechanism, credentials...
// Reply: version, request id, status code, status text, user id, metadata.
void ZapHandler::answer(std::vector<zmq::message_t>& request) {
  std::string version = request.size() > 0 ? request[0].to_string() : "";
  std::string requestId = request.size() > 1 ? request[1].to_string() : "";
  std::string address = request.size() > 3 ? request[3].to_string() : "?";
  std::string mechanism = request.size() > 5 ? request[5].to_string() : "";
  bool ok = version == "1.0" && mechanism == "CURVE" && request.size() == 7 &&
            allowed_.count(request[6].to_string()) > 0;
  if (ok) {
    ++counters_.accepted;
  } else {
    std::uint64_t n = ++counters_.refused;
    // A refused client retries about once a second: the first refusals and then every 60th are logged.
    if (n <= 3 || n % 60 == 0) {
      logLine(server_ + ": refused a client without an allowed key from " + address + " (" + std::to_string(n) +
              " refused so far)");
    }
  }
  std::vector<std::string> reply = {"1.0", requestId, ok ? "200" : "400",
                                    ok ? "OK" : "key not allowed", ok ? "console" : "", ""};
  for (std::size_t i = 0; i < reply.size(); ++i) {
    socket_.send(zmq::buffer(reply[i]), i + 1 < reply.size() ? zmq::send_flags::sndmore : zmq::send_flags::none);
  }
}

}  // namespace touchline::nao
