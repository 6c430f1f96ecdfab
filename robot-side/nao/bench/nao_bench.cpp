// touchline-nao-bench: robot-side performance figures, measured through real sockets on
// loopback against in-process servers (not run by ctest).
//   camera: delivered fps and bytes/frame at 640x480 and 1280x960 (client fetching as fast
//           as it can; frames are rendered at most at the configured 30 fps)
//   rpc:    round trip of a trivial call (ALMotion.ping) vs a raw libzmq ROUTER echo of the
//           same bytes, p50/p99: the echo on its own context (like the RPC server: its own
//           I/O thread) and, for reference, on the client's context (one I/O thread serves
//           both ends of the TCP connection, a shortcut no remote robot has)
//   load:   short-call p99 while long calls occupy half of the workers
// Usage: touchline-nao-bench [--seconds 3] [--workers 4]
#include <algorithm>
#include <chrono>
#include <fstream>
#include <cstdio>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "camera_server.h"
#include "echo_server.h"
#include "rpc_client.h"
#include "rpc_server.h"
#include "simulated_broker.h"
#include "zmq_envelope.h"

using namespace touchline::nao;
using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

namespace {

double ms(Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  auto index = static_cast<std::size_t>(p * (v.size() - 1) + 0.5);
  return v[std::min(index, v.size() - 1)];
}

void cameraBench(double seconds) {
  CameraServer server(CameraOptions{"127.0.0.1", 0});
  zmq::context_t context;
  DealerClient client(context, loopback(server.port()));
  std::printf("camera (fetch loop, configured 30 fps, kRGB, JPEG quality %d, 4:2:0):\n",
              JpegEncoder::kQuality);
  for (std::uint32_t resolution : {2u, 3u}) {
    auto [w, h] = *resolutionSize(resolution);
    ::nao::CamRequest configure;
    configure.set_resolution(resolution);
    configure.set_colorspace(11);
    configure.set_fps(30);
    client.roundTrip(configure.SerializeAsString(), 2000ms);
    std::string previous;
    std::size_t distinct = 0, bytes = 0, fetches = 0;
    auto start = Clock::now();
    while (Clock::now() - start < std::chrono::duration<double>(seconds)) {
      auto reply = client.roundTrip("", 2000ms);
      if (!reply) continue;
      ::nao::CamResponse response;
      response.ParseFromString(*reply);
      ++fetches;
      if (response.imagedata() != previous) {
        ++distinct;
        bytes += response.imagedata().size();
        previous = response.imagedata();
      }
    }
    double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    double perFrame = distinct ? static_cast<double>(bytes) / distinct : 0;
    double raw = static_cast<double>(w) * h * 3;
    std::printf("  %dx%d: %.1f distinct frames/s (%zu fetches), %.0f bytes/frame = 1/%.0f of raw RGB\n",
                w, h, distinct / elapsed, fetches, perFrame, perFrame > 0 ? raw / perFrame : 0.0);
  }
  // The server's own cost per frame, for headroom (render + JPEG, one core).
  SceneRenderer renderer;
  JpegEncoder encoder;
  for (std::uint32_t resolution : {2u, 3u}) {
    auto [w, h] = *resolutionSize(resolution);
    int n = 60;
    renderer.render(w, h, 0);  // the background is built once per resolution: not timed
    auto start = Clock::now();
    for (int i = 0; i < n; ++i) {
      const auto& rgb = renderer.render(w, h, i / 30.0);
      encoder.encode(rgb.data(), w, h, false);
    }
    std::printf("  render+encode %dx%d: %.2f ms/frame (capacity %.0f fps)\n", w, h,
                ms(Clock::now() - start) / n, n / std::chrono::duration<double>(Clock::now() - start).count());
  }
}

// A raw ROUTER echo with the RPC frame layout: the baseline for the RPC round trip.
void echoLoop(zmq::socket_t& socket, const std::atomic<bool>& stop) {
  while (!stop) {
    zmq::pollitem_t items[] = {{socket.handle(), 0, ZMQ_POLLIN, 0}};
    zmq::poll(items, 1, 50ms);
    if (!(items[0].revents & ZMQ_POLLIN)) continue;
    std::vector<zmq::message_t> frames;
    if (zmq::recv_multipart(socket, std::back_inserter(frames))) zmq::send_multipart(socket, frames);
  }
}

std::vector<double> roundTrips(DealerClient& client, const std::string& payload, int n) {
  std::vector<double> out;
  for (int i = 0; i < n; ++i) {
    auto start = Clock::now();
    if (client.roundTrip(payload, 2000ms)) out.push_back(ms(Clock::now() - start));
  }
  return out;
}

void rpcBench(int workers, double seconds) {
  RpcCounters counters;
  SimulatedBroker broker(1.0, &counters);
  RpcServer server(broker, counters, RpcOptions{"127.0.0.1", 0, workers});
  EchoServer ownEcho("127.0.0.1", 0);
  zmq::context_t context;
  zmq::socket_t echo(context, zmq::socket_type::router);
  echo.set(zmq::sockopt::linger, 0);
  echo.bind("tcp://127.0.0.1:*");
  int echoPort = boundPort(echo);
  std::atomic<bool> stop{false};
  std::thread echoThread([&] { echoLoop(echo, stop); });

  std::string ping = encodeRequest("ALMotion", "ping");
  DealerClient rpc(context, loopback(server.port()));
  DealerClient own(context, loopback(ownEcho.port()));
  DealerClient shared(context, loopback(echoPort));
  roundTrips(rpc, ping, 500);  // warm up
  roundTrips(own, ping, 500);
  roundTrips(shared, ping, 500);
  // Alternate call by call so machine noise hits all alike.
  std::vector<double> rpcTimes, ownTimes, sharedTimes;
  auto rttStart = Clock::now();
  while (Clock::now() - rttStart < std::chrono::duration<double>(seconds)) {
    for (auto [client, times] : {std::pair{&rpc, &rpcTimes}, std::pair{&own, &ownTimes},
                                 std::pair{&shared, &sharedTimes}}) {
      auto t = roundTrips(*client, ping, 1);
      times->insert(times->end(), t.begin(), t.end());
    }
  }
  double rpc50 = percentile(rpcTimes, 0.5), own50 = percentile(ownTimes, 0.5),
         shared50 = percentile(sharedTimes, 0.5);
  std::printf("rpc round trip, ALMotion.ping (%zu bytes), %zu calls each, alternating:\n", ping.size(),
              rpcTimes.size());
  std::printf("  rpc         p50 %.3f ms  p99 %.3f ms  (%llu of them run inline)\n", rpc50,
              percentile(rpcTimes, 0.99), static_cast<unsigned long long>(counters.inlineCalls.load()));
  std::printf("  echo        p50 %.3f ms  p99 %.3f ms  (raw libzmq ROUTER echo, own context)\n", own50,
              percentile(ownTimes, 0.99));
  std::printf("  echo shared p50 %.3f ms  p99 %.3f ms  (same, on the client's context)\n", shared50,
              percentile(sharedTimes, 0.99));
  std::printf("  ratio p50 rpc/echo = %.2f (vs the shared-context echo: %.2f)\n",
              own50 > 0 ? rpc50 / own50 : 0.0, shared50 > 0 ? rpc50 / shared50 : 0.0);

  // Long calls (30 s say) occupy half of the workers; short calls run meanwhile.
  DealerClient longCalls(context, loopback(server.port()));
  int busy = workers / 2;
  for (int i = 0; i < busy; ++i)
    longCalls.send(encodeRequest("ALTextToSpeech", "say", {stringValue(std::string(500, 'a'))}));
  // Wait until the workers are executing them (the call log records a call as it starts).
  auto saysRunning = [&] {
    auto log = broker.callLog().entries();
    return std::count_if(log.begin(), log.end(), [](const std::string& e) {
      return e.find("ALTextToSpeech.say") != std::string::npos;
    });
  };
  while (saysRunning() < busy) std::this_thread::sleep_for(1ms);
  std::vector<double> shortTimes;
  std::vector<std::string> shortCalls = {
      encodeRequest("ALMotion", "ping"), encodeRequest("ALRobotPosture", "getPosture"),
      encodeRequest("ALMotion", "getAngles", {stringValue("Head"), boolValue(true)}),
      encodeRequest("ALBattery", "getBatteryCharge")};
  auto start = Clock::now();
  for (std::size_t i = 0; Clock::now() - start < std::chrono::duration<double>(seconds); ++i) {
    auto t = Clock::now();
    if (rpc.roundTrip(shortCalls[i % shortCalls.size()], 2000ms)) shortTimes.push_back(ms(Clock::now() - t));
    else shortTimes.push_back(2000);
  }
  std::printf("short calls while %d of %d workers run a 30 s say: %zu calls, p50 %.3f ms, "
              "p99 %.3f ms, max %.3f ms\n",
              busy, workers, shortTimes.size(), percentile(shortTimes, 0.5),
              percentile(shortTimes, 0.99), percentile(shortTimes, 1.0));
  stop = true;
  echoThread.join();
  ownEcho.stop();
  server.stop();
}

}  // namespace

int main(int argc, char** argv) {
  double seconds = 3;
  int workers = 4;
  for (int i = 1; i + 1 < argc; i += 2) {
    std::string arg = argv[i];
    if (arg == "--seconds") seconds = std::stod(argv[i + 1]);
    else if (arg == "--workers") workers = std::stoi(argv[i + 1]);
  }
  std::string load;
  std::getline(std::ifstream("/proc/loadavg"), load);
  std::printf("touchline-nao-bench (robot side), %u hardware threads, load average %s\n",
              std::thread::hardware_concurrency(), load.c_str());
  cameraBench(seconds);
  rpcBench(workers, seconds);
  return 0;
}
