// The touchline-nao-sim binary as the Java console uses it: ports chosen by the OS are read
// from stdout, both servers answer, SIGTERM ends it cleanly.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <regex>
#include <thread>

#include "rpc_client.h"

using namespace touchline::nao;
using namespace std::chrono_literals;

#ifndef TOUCHLINE_NAO_SIM_BINARY
#error "TOUCHLINE_NAO_SIM_BINARY must name the touchline-nao-sim binary"
#endif

namespace {

struct SimProcess {
  pid_t pid = -1;
  FILE* out = nullptr;

  SimProcess() {
    int fds[2];
    if (pipe(fds) != 0) return;
    pid = fork();
    if (pid == 0) {
      dup2(fds[1], STDOUT_FILENO);
      close(fds[0]);
      close(fds[1]);
      execl(TOUCHLINE_NAO_SIM_BINARY, TOUCHLINE_NAO_SIM_BINARY, "--rpc-port", "0", "--cam-port", "0",
            "--workers", "3", static_cast<char*>(nullptr));
      _exit(127);
    }
    close(fds[1]);
    out = fdopen(fds[0], "r");
  }

  ~SimProcess() {
    if (pid > 0 && waitpid(pid, nullptr, WNOHANG) == 0) {
      kill(pid, SIGKILL);
      waitpid(pid, nullptr, 0);
    }
    if (out) fclose(out);
  }

  int readPort(const std::string& prefix) {
    char line[256];
    if (!out || !fgets(line, sizeof line, out)) return -1;
    std::smatch m;
    std::string s(line);
    if (!std::regex_search(s, m, std::regex("^" + prefix + " listening on port (\\d+)\\n$"))) return -1;
    return std::stoi(m[1]);
  }

  // Exit status after SIGTERM, or -1 if it did not exit within the timeout.
  int terminate(std::chrono::milliseconds timeout) {
    kill(pid, SIGTERM);
    auto deadline = std::chrono::steady_clock::now() + timeout;
    int status = 0;
    while (std::chrono::steady_clock::now() < deadline) {
      if (waitpid(pid, &status, WNOHANG) == pid) {
        pid = -1;
        return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      }
      std::this_thread::sleep_for(10ms);
    }
    return -1;
  }
};

}  // namespace

TEST(SimProcess, PrintsPortsServesAndStopsOnSigterm) {
  SimProcess sim;
  ASSERT_GT(sim.pid, 0);
  int rpcPort = sim.readPort("rpc");
  int camPort = sim.readPort("camera");
  ASSERT_GT(rpcPort, 0);
  ASSERT_GT(camPort, 0);

  zmq::context_t context;
  DealerClient rpc(context, loopback(rpcPort));
  auto modules = rpcCall(rpc, "Robot", "getModuleList");
  ASSERT_TRUE(modules);
  EXPECT_EQ(modules->returnval().array_size(), 7);

  DealerClient cam(context, loopback(camPort));
  ::nao::CamRequest configure;
  configure.set_resolution(1);
  ASSERT_TRUE(cam.roundTrip(configure.SerializeAsString(), 30000ms));
  auto frame = cam.roundTrip("", 30000ms);
  ASSERT_TRUE(frame);
  ::nao::CamResponse response;
  ASSERT_TRUE(response.ParseFromString(*frame));
  EXPECT_EQ(response.imagedata().substr(0, 2), "\xff\xd8");

  // A long call (a 300 s say) is running while the process is told to stop: it must still
  // exit, well before the say would have ended (30 s: a generous "did not hang" bound).
  rpc.send(encodeRequest("ALTextToSpeech", "say", {stringValue(std::string(5000, 'a'))}));
  EXPECT_EQ(sim.terminate(30000ms), 0) << "the simulator did not exit on SIGTERM (-1: still running)";
}
