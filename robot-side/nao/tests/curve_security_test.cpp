// The robot side's CURVE pieces: the key-file reader's errors, and the ZAP handler letting in
// only an allowed client key (libzmq CURVE on both ends, loopback, OS-chosen port).
#include <gtest/gtest.h>

#include <zmq.hpp>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>

#include "curve_security.h"

using namespace touchline::nao;
using namespace std::chrono_literals;

namespace {

struct KeyPair {
  std::string publicKey, secretKey;
  KeyPair() {
    char pub[41], sec[41];
    zmq_curve_keypair(pub, sec);
    publicKey = pub;
    secretKey = sec;
  }
};

std::string tempFile(const std::string& name, const std::string& text) {
  std::string path = ::testing::TempDir() + "curve-test-" + name;
  std::ofstream(path) << text;
  return path;
}

std::string errorOf(const std::string& text, const std::string& name) {
  try {
    curveKeyValue(text, name, "f");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(CurveKeyFile, ReadsTheKeyAndExplainsEveryError) {
  KeyPair k;
  std::string file = "# the NAO's key pair\n\npublic-key = " + k.publicKey + "\nsecret-key = " + k.secretKey + "\n";
  EXPECT_EQ(curveKeyValue(file, "secret-key", "f"), k.secretKey);
  EXPECT_NE(errorOf("public-key = " + k.publicKey.substr(1) + "\n", "public-key").find("39 characters"),
            std::string::npos);
  std::string badZ85 = "\"" + k.publicKey.substr(1);
  EXPECT_NE(errorOf("public-key = " + badZ85 + "\n", "public-key").find("not valid Z85"), std::string::npos);
  EXPECT_NE(errorOf("# only a comment\n", "secret-key").find("no 'secret-key = ...' line"), std::string::npos);
  EXPECT_NE(errorOf("garbage\n", "secret-key").find("line 1: not 'name = value'"), std::string::npos);
}

TEST(CurveKeyFile, LoadsServerKeysAndClientFilesOrSaysWhichFileIsWrong) {
  KeyPair server, client;
  std::string secret = tempFile("server.secret", "public-key = " + server.publicKey + "\nsecret-key = " +
                                                     server.secretKey + "\n");
  std::string allowed = tempFile("console.public", "public-key = " + client.publicKey + "\n");
  CurveServerKeys keys = loadCurveServerKeys(secret, {allowed});
  EXPECT_EQ(keys.secretKey, server.secretKey);
  EXPECT_EQ(keys.allowedClients.size(), 1u);
  try {
    loadCurveServerKeys(::testing::TempDir() + "no-such.secret", {allowed});
    FAIL() << "a missing file must throw";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("no-such.secret: cannot read"), std::string::npos) << e.what();
  }
}

TEST(ZapHandler, LetsInOnlyAnAllowedClientKeyAndCountsRefusals) {
  KeyPair server, allowed, stranger;
  CurveServerKeys keys{server.publicKey, server.secretKey, {}};
  std::string binary(32, '\0');
  zmq_z85_decode(reinterpret_cast<std::uint8_t*>(binary.data()), allowed.publicKey.c_str());
  keys.allowedClients.insert(binary);

  zmq::context_t serverContext;
  ZapHandler zap(serverContext, keys.allowedClients, "test");
  zmq::socket_t router(serverContext, zmq::socket_type::router);
  router.set(zmq::sockopt::linger, 0);
  makeCurveServer(router, keys);
  router.bind("tcp://127.0.0.1:*");
  std::string endpoint = router.get(zmq::sockopt::last_endpoint);

  auto exchange = [&](const KeyPair& client) {
    zmq::context_t context;
    zmq::socket_t dealer(context, zmq::socket_type::dealer);
    dealer.set(zmq::sockopt::linger, 0);
    dealer.set(zmq::sockopt::curve_serverkey, server.publicKey);
    dealer.set(zmq::sockopt::curve_publickey, client.publicKey);
    dealer.set(zmq::sockopt::curve_secretkey, client.secretKey);
    dealer.connect(endpoint);
    dealer.send(zmq::str_buffer("hello"), zmq::send_flags::none);
    zmq::pollitem_t items[] = {{router.handle(), 0, ZMQ_POLLIN, 0}};
    zmq::poll(items, 1, 3000ms);
    if (!(items[0].revents & ZMQ_POLLIN)) return std::string();
    zmq::message_t identity, body;
    (void)router.recv(identity);
    (void)router.recv(body);
    return body.to_string();
  };
  EXPECT_EQ(exchange(stranger), "");
  EXPECT_GE(zap.counters().refused.load(), 1u);
  EXPECT_EQ(exchange(allowed), "hello");
  EXPECT_EQ(zap.counters().accepted.load(), 1u);
}
