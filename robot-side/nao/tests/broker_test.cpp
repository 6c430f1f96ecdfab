#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <thread>

#include "simulated_broker.h"

using namespace touchline::nao;

namespace {
// Blocking durations run at 1/20 of robot time: a 3 s posture change takes 150 ms.
constexpr double kScale = 0.05;
// Tests that time the robot run it on a manual clock: a blocking call advances the clock by
// exactly its simulated duration and takes no real time, so load cannot change the result.
constexpr double kNanosecond = 1e-9;

// A blocking call must not hang: a blocking say/posture is made longer than the ctest
// TIMEOUT (CMakeLists.txt), so a call that is not interrupted fails the test by timing out.
const std::string kLongerThanTheTestTimeout(5000, 'a');  // 5000 x 60 ms = 300 s

std::string errorOf(SimulatedBroker& broker, const std::string& module, const std::string& method,
                    const Params& params = {}) {
  try {
    broker.call(module, method, params);
  } catch (const CallError& e) {
    return e.what();
  }
  return "";
}

std::vector<double> floats(const Value& v) {
  std::vector<double> out;
  for (const auto& item : v.array()) out.push_back(item.float_());
  return out;
}

std::vector<std::string> strings(const Value& v) {
  std::vector<std::string> out;
  for (const auto& item : v.array()) out.push_back(item.string());
  return out;
}

bool contains(const std::vector<std::string>& list, const std::string& item) {
  return std::find(list.begin(), list.end(), item) != list.end();
}
}  // namespace

TEST(Broker, UnknownModuleAndMethodAreErrors) {
  SimulatedBroker broker(kScale);
  EXPECT_NE(errorOf(broker, "ALNope", "ping").find("unknown module 'ALNope'"), std::string::npos);
  EXPECT_NE(errorOf(broker, "ALMotion", "fly").find("unknown method 'fly'"), std::string::npos);
}

TEST(Broker, WrongParameterTypesAndCountsAreErrors) {
  SimulatedBroker broker(kScale);
  std::string wrongType = errorOf(broker, "ALTextToSpeech", "setVolume", {stringValue("loud")});
  EXPECT_NE(wrongType.find("parameter 1 (volume) must be float, got string"), std::string::npos)
      << wrongType;
  std::string wrongCount = errorOf(broker, "ALTextToSpeech", "setVolume", {});
  EXPECT_NE(wrongCount.find("expected 1 parameters, got 0"), std::string::npos) << wrongCount;
  std::string badNames = errorOf(broker, "ALMotion", "setStiffnesses",
                                 {stringValue("Tail"), floatValue(1.0f)});
  EXPECT_NE(badNames.find("unknown joint or chain 'Tail'"), std::string::npos);
}

TEST(Broker, VoidValueAndErrorReturns) {
  SimulatedBroker broker(kScale);
  EXPECT_FALSE(broker.call("ALTextToSpeech", "setVolume", {floatValue(0.25f)}).has_value());
  auto volume = broker.call("ALTextToSpeech", "getVolume", {});
  ASSERT_TRUE(volume);
  EXPECT_FLOAT_EQ(volume->float_(), 0.25f);
  EXPECT_NE(errorOf(broker, "ALTextToSpeech", "setVolume", {floatValue(2.0f)}).find("0..1"),
            std::string::npos);
  // An int is accepted where a float is expected (MixedValue has no signed int anyway).
  EXPECT_FALSE(broker.call("ALTextToSpeech", "setVolume", {intValue(1)}).has_value());
}

TEST(Broker, EveryModuleAnswersDiscovery) {
  SimulatedBroker broker(kScale);
  auto modules = strings(*broker.call("Robot", "getModuleList", {}));
  for (const char* m : {"ALMotion", "ALRobotPosture", "ALTextToSpeech", "ALMemory", "ALBattery",
                        "ALVideoDevice", "Robot"}) {
    ASSERT_TRUE(contains(modules, m)) << m;
    auto methods = strings(*broker.call(m, "getMethodList", {}));
    for (const char* common : {"getMethodList", "getMethodHelp", "getModuleHelp", "ping", "version"})
      EXPECT_TRUE(contains(methods, common)) << m << "." << common;
    EXPECT_TRUE(broker.call(m, "ping", {})->bool_());
    EXPECT_EQ(broker.call(m, "getModuleHelp", {})->array(0).string(), m);
  }
  Value help = *broker.call("ALMotion", "getMethodHelp", {stringValue("setAngles")});
  ASSERT_EQ(help.array_size(), 4);
  EXPECT_EQ(help.array(0).string(), "setAngles");
  EXPECT_EQ(help.array(2).array_size(), 3);  // names, angles, fractionMaxSpeed
  EXPECT_EQ(help.array(2).array(0).array(0).string(), "names");
  EXPECT_EQ(help.array(3).string(), "void");
  EXPECT_NE(errorOf(broker, "ALMotion", "getMethodHelp", {stringValue("fly")}), "");
}

TEST(Broker, AngleCommandsOnLimpJointsAreIgnoredAndAnglesAreClamped) {
  SimulatedBroker broker(kScale);
  broker.call("ALMotion", "setAngles", {stringValue("HeadYaw"), floatValue(1.0f), floatValue(1.0f)});
  auto angle = floats(*broker.call("ALMotion", "getAngles", {stringValue("HeadYaw"), boolValue(false)}));
  EXPECT_FLOAT_EQ(angle.at(0), 0.0f) << "stiffness 0: the command must not move the joint";

  broker.call("ALMotion", "setStiffnesses", {stringValue("Head"), floatValue(1.0f)});
  broker.call("ALMotion", "setAngles", {stringValue("HeadYaw"), floatValue(5.0f), floatValue(1.0f)});
  angle = floats(*broker.call("ALMotion", "getAngles", {stringValue("HeadYaw"), boolValue(false)}));
  EXPECT_NEAR(angle.at(0), 2.0857, 1e-4) << "clamped to the HeadYaw limit";
  auto stiff = floats(*broker.call("ALMotion", "getStiffnesses", {stringValue("Head")}));
  EXPECT_EQ(stiff, (std::vector<double>{1.0, 1.0}));
  // The memory keys follow the actuator.
  auto key = broker.call("ALMemory", "getData",
                         {stringValue("Device/SubDeviceList/HeadYaw/Position/Actuator/Value")});
  EXPECT_NEAR(key->float_(), 2.0857, 1e-4);
}

TEST(Broker, PostureChangeBlocksForBaseTimeOverSpeed) {
  auto clock = std::make_shared<ManualSimClock>();
  SimulatedBroker broker(kScale, nullptr, clock);
  EXPECT_EQ(broker.call("ALRobotPosture", "getPosture", {})->string(), "Crouch");
  EXPECT_TRUE(broker.call("ALRobotPosture", "goToPosture", {stringValue("Stand"), floatValue(1.0f)})
                  ->bool_());
  EXPECT_NEAR(clock->elapsedSeconds(), 3.0 * kScale, kNanosecond);  // Crouch -> Stand: 3 s at 1.0
  EXPECT_EQ(broker.call("ALRobotPosture", "getPosture", {})->string(), "Stand");
  broker.call("ALRobotPosture", "goToPosture", {stringValue("Sit"), floatValue(0.5f)});
  EXPECT_NEAR(clock->elapsedSeconds(), (3.0 + 6.0) * kScale, kNanosecond);  // Stand -> Sit at 0.5: 6 s
  EXPECT_EQ(broker.call("ALRobotPosture", "getPostureFamily", {})->string(), "Sitting");
  EXPECT_NE(errorOf(broker, "ALRobotPosture", "goToPosture", {stringValue("Handstand"), floatValue(1.0f)})
                .find("unknown posture"),
            std::string::npos);
  EXPECT_NE(errorOf(broker, "ALRobotPosture", "goToPosture", {stringValue("Stand"), floatValue(0.0f)}),
            "");
}

TEST(Broker, WalkingNeedsStandingAndMovesTheRobot) {
  auto clock = std::make_shared<ManualSimClock>();
  SimulatedBroker broker(kScale, nullptr, clock);
  EXPECT_NE(errorOf(broker, "ALMotion", "moveTo", {floatValue(0.2f), intValue(0), intValue(0)})
                .find("not standing"),
            std::string::npos);
  broker.call("ALRobotPosture", "goToPosture", {stringValue("Stand"), floatValue(1.0f)});
  broker.call("ALMotion", "moveInit", {});
  double before = clock->elapsedSeconds();
  broker.call("ALMotion", "moveTo", {floatValue(0.2f), intValue(0), intValue(0)});
  EXPECT_NEAR(clock->elapsedSeconds() - before, 0.2 / RobotState::kMaxWalkX * kScale, 1e-6);
  auto pos = floats(*broker.call("ALMotion", "getRobotPosition", {boolValue(true)}));
  EXPECT_NEAR(pos.at(0), 0.2, 1e-6);
  EXPECT_NEAR(pos.at(1), 0.0, 1e-6);
  broker.call("ALMotion", "move", {floatValue(0.05f), intValue(0), intValue(0)});
  EXPECT_TRUE(broker.call("ALMotion", "moveIsActive", {})->bool_());
  clock->advance(std::chrono::seconds(1));  // 1 s of clock time = 20 robot seconds at 0.05 m/s
  pos = floats(*broker.call("ALMotion", "getRobotPosition", {boolValue(true)}));
  EXPECT_NEAR(pos.at(0), 0.2 + 1.0, 1e-6) << "move is open-ended: it walks until stopped";
  broker.call("ALMotion", "stopMove", {});
  EXPECT_FALSE(broker.call("ALMotion", "moveIsActive", {})->bool_());
}

// Issue #11 item 6: a thread woken late (a loaded machine) walked further than commanded,
// because the position integrated the walk velocity until the thread set it back to 0.
TEST(Broker, ABoundedWalkEndsWherePlannedEvenIfItsThreadWakesLate) {
  // Every wait wakes 1 s of clock time (20 robot seconds at kScale) after its deadline.
  struct LateWakingClock : ManualSimClock {
    bool waitUntil(std::condition_variable& cv, std::unique_lock<std::mutex>& lock, time_point deadline,
                   const std::function<bool()>& woken) override {
      bool result = ManualSimClock::waitUntil(cv, lock, deadline, woken);
      advance(std::chrono::seconds(1));
      return result;
    }
  };
  auto clock = std::make_shared<LateWakingClock>();
  RobotState robot(kScale, clock);
  EXPECT_TRUE(robot.moveBy(0.2, 0, 0));
  EXPECT_NEAR(robot.position()[0], 0.2, 1e-6) << "not 0.2 + 20 s x 0.1 m/s";
  EXPECT_FALSE(robot.moving());
  // An open-ended walk (move) still walks for as long as the clock runs.
  robot.setVelocity(0.1, 0, 0);
  clock->advance(std::chrono::seconds(1));
  EXPECT_NEAR(robot.position()[0], 0.2 + 2.0, 1e-6);
}

TEST(Broker, MemoryStoresValuesAndListsKeys) {
  SimulatedBroker broker(kScale);
  broker.call("ALMemory", "insertData", {stringValue("Team/Role"), stringValue("striker")});
  EXPECT_EQ(broker.call("ALMemory", "getData", {stringValue("Team/Role")})->string(), "striker");
  auto keys = strings(*broker.call("ALMemory", "getDataList", {stringValue("Team/")}));
  EXPECT_EQ(keys, std::vector<std::string>{"Team/Role"});
  EXPECT_NE(errorOf(broker, "ALMemory", "getData", {stringValue("Nope")}).find("no key"),
            std::string::npos);
  EXPECT_NE(errorOf(broker, "ALMemory", "insertData",
                    {stringValue("Device/SubDeviceList/HeadYaw/Position/Sensor/Value"), intValue(1)})
                .find("read-only"),
            std::string::npos);
  auto charge = broker.call("ALBattery", "getBatteryCharge", {});
  EXPECT_LE(charge->int_(), 100u);
  EXPECT_GT(charge->int_(), 90u);
}

TEST(Broker, SayBlocksForTheLengthOfTheText) {
  auto clock = std::make_shared<ManualSimClock>();
  SimulatedBroker broker(1.0, nullptr, clock);
  broker.call("ALTextToSpeech", "say", {stringValue("hello")});  // 5 chars x 60 ms
  EXPECT_NEAR(clock->elapsedSeconds(), 5 * 0.060, kNanosecond);
}

TEST(Broker, CallLogRecordsExecutedCallsButNotRobotInfo) {
  SimulatedBroker broker(kScale);
  broker.call("ALTextToSpeech", "say", {stringValue("marker")});
  broker.call("Robot", "getModuleList", {});
  auto log = strings(*broker.call("Robot", "getCallLog", {}));
  ASSERT_EQ(log.size(), 1u);
  EXPECT_EQ(log[0], "1 ALTextToSpeech.say(\"marker\")");
  EXPECT_EQ(strings(*broker.call("ALMemory", "getData", {stringValue("Touchline/CallLog")})).size(), 2u);  // getData logs itself
}

TEST(Broker, VideoDeviceDeliversRawImages) {
  SimulatedBroker broker(kScale);
  std::string id = broker.call("ALVideoDevice", "subscribeCamera",
                               {stringValue("test"), intValue(0), intValue(0), intValue(11), intValue(5)})
                       ->string();
  Value image = *broker.call("ALVideoDevice", "getImageRemote", {stringValue(id)});
  EXPECT_EQ(image.array(0).int_(), 160u);
  EXPECT_EQ(image.array(1).int_(), 120u);
  EXPECT_EQ(image.array(2).int_(), 3u);
  EXPECT_EQ(image.array(6).binary().size(), 160u * 120u * 3u);
  EXPECT_NE(errorOf(broker, "ALVideoDevice", "subscribe",
                    {stringValue("x"), intValue(9), intValue(11), intValue(5)})
                .find("unknown resolution"),
            std::string::npos);
}

// Real clock: a real thread blocks and must be woken. The say outlasts the ctest TIMEOUT, so
// if shutdown did not cut it short, join() would hang and the test fail by timing out.
TEST(Broker, ShutdownWakesBlockingCalls) {
  SimulatedBroker broker(1.0);
  std::optional<Value> said;
  std::thread caller([&] { said = broker.call("ALTextToSpeech", "say", {stringValue(kLongerThanTheTestTimeout)}); });
  while (broker.callLog().total() < 1) std::this_thread::yield();  // the say is running
  broker.shutdown();
  caller.join();
  EXPECT_FALSE(said.has_value());  // say is void
}

TEST(Broker, MemoryIsBounded) {
  SimulatedBroker broker(kScale);
  std::string chunk(15u << 20, 'x');
  for (int i = 0; i < 4; ++i)
    broker.call("ALMemory", "insertData", {stringValue("blob" + std::to_string(i)), binaryValue(chunk)});
  EXPECT_NE(errorOf(broker, "ALMemory", "insertData", {stringValue("blob4"), binaryValue(chunk)})
                .find("storage limit"),
            std::string::npos);
  // Replacing or removing frees room again.
  broker.call("ALMemory", "removeData", {stringValue("blob0")});
  broker.call("ALMemory", "insertData", {stringValue("blob4"), binaryValue(chunk)});
  broker.call("ALMemory", "insertData", {stringValue("blob4"), binaryValue("small")});
  EXPECT_EQ(broker.call("ALMemory", "getData", {stringValue("blob4")})->binary(), "small");
}

TEST(Broker, RejectedCallsAreNotLoggedAsRun) {
  SimulatedBroker broker(kScale);
  errorOf(broker, "ALMotion", "fly");
  errorOf(broker, "ALTextToSpeech", "say", {intValue(3)});
  errorOf(broker, "ALNope", "say");
  EXPECT_TRUE(strings(*broker.call("Robot", "getCallLog", {})).empty());
}

TEST(Broker, RemovingStiffnessStopsTheJointButKeepsTheCommand) {
  auto clock = std::make_shared<ManualSimClock>();
  SimulatedBroker broker(1.0, nullptr, clock);
  auto sensedHeadYaw = [&] {
    return floats(*broker.call("ALMotion", "getAngles", {stringValue("HeadYaw"), boolValue(true)})).at(0);
  };
  broker.call("ALMotion", "setStiffnesses", {stringValue("HeadYaw"), floatValue(1.0f)});
  // 2 rad at 0.1 x 6 rad/s takes 10/3 s; after 1 s the joint is at 0.6 rad.
  broker.call("ALMotion", "setAngles", {stringValue("HeadYaw"), floatValue(2.0f), floatValue(0.1f)});
  clock->advance(std::chrono::seconds(1));
  EXPECT_NEAR(sensedHeadYaw(), 0.6, 1e-6);
  broker.call("ALMotion", "setStiffnesses", {stringValue("HeadYaw"), floatValue(0.0f)});
  double commanded = floats(*broker.call("ALMotion", "getAngles", {stringValue("HeadYaw"), boolValue(false)})).at(0);
  EXPECT_NEAR(commanded, 2.0, 1e-6);
  clock->advance(std::chrono::seconds(10));  // a limp joint does not move on
  EXPECT_NEAR(sensedHeadYaw(), 0.6, 1e-6);
}

// Quick calls run on the RPC module's frontend thread, so a blocking method marked quick
// would stall every other call: no method whose help says it blocks may be quick (and
// every one documented as non-blocking is).
TEST(Broker, BlockingMethodsAreNeverQuick) {
  SimulatedBroker broker(kScale);
  int quick = 0;
  for (const auto& module : broker.moduleNames()) {
    for (const auto& method : strings(*broker.call(module, "getMethodList", {}))) {
      std::string help = broker.call(module, "getMethodHelp", {stringValue(method)})->array(1).string();
      std::transform(help.begin(), help.end(), help.begin(), ::tolower);
      if (help.find("non-blocking") != std::string::npos) {
        EXPECT_TRUE(broker.isQuick(module, method)) << module << "." << method << ": " << help;
      } else if (help.find("block") != std::string::npos) {
        EXPECT_FALSE(broker.isQuick(module, method)) << module << "." << method << ": " << help;
      }
      quick += broker.isQuick(module, method);
    }
  }
  for (auto [module, method] : {std::pair{"ALRobotPosture", "applyPosture"},
                                {"ALVideoDevice", "getImageRemote"}, {"ALTextToSpeech", "say"},
                                {"ALMotion", "moveTo"}, {"ALMotion", "wakeUp"}}) {
    EXPECT_FALSE(broker.isQuick(module, method)) << module << "." << method;
  }
  for (auto [module, method] : {std::pair{"ALMotion", "ping"}, {"ALMotion", "getAngles"},
                                {"ALMotion", "setStiffnesses"}, {"ALMotion", "stopMove"},
                                {"ALTextToSpeech", "stopAll"}, {"ALMemory", "getData"},
                                {"Robot", "getRpcStats"}}) {
    EXPECT_TRUE(broker.isQuick(module, method)) << module << "." << method;
  }
  // Unknown names fail at once, so they are quick too.
  EXPECT_TRUE(broker.isQuick("ALNope", "ping"));
  EXPECT_TRUE(broker.isQuick("ALMotion", "fly"));
  EXPECT_GT(quick, 50);
}

TEST(Broker, MarkingAnUnknownMethodQuickIsAProgrammingError) {
  struct Misspelt : SimModule {
    Misspelt() : SimModule("X", "test") { markQuick({"pnig"}); }
  };
  EXPECT_THROW(Misspelt(), std::logic_error);
}
