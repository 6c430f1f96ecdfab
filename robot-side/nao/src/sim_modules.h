// The simulated NAOqi modules (subsets of the NAOqi 1.x/2.x APIs listed in README.md).
// Each is a method table over the shared RobotState; blocking methods sleep robot time.
#pragma once

#include <atomic>
#include <functional>
#include <map>
#include <mutex>
#include <set>
#include <string>

#include "call_log.h"
#include "robot_state.h"
#include "rpc_counters.h"
#include "scene_renderer.h"
#include "sim_module.h"

namespace touchline::nao {

class SimMotion : public SimModule {
 public:
  explicit SimMotion(RobotState& robot);

 private:
  void requireStanding(const char* method) const;
  void setAngles(const std::vector<std::string>& joints, const std::vector<double>& targets,
                 double fraction, bool relative);
  RobotState& robot_;
  std::atomic<bool> fallManager_{true};
  std::atomic<bool> leftArmSwing_{true};
  std::atomic<bool> rightArmSwing_{true};
};

class SimPosture : public SimModule {
 public:
  explicit SimPosture(RobotState& robot);

 private:
  RobotState& robot_;
  std::atomic<std::uint32_t> maxTries_{3};
};

class SimSpeech : public SimModule {
 public:
  static constexpr double kSecondsPerChar = 0.060;
  explicit SimSpeech(RobotState& robot);

 private:
  RobotState& robot_;
  std::mutex mutex_;
  double volume_ = 0.8;
  std::string language_ = "English";
  std::string voice_ = "naoenu";
  std::map<std::string, double> parameters_{{"pitchShift", 1.0}, {"doubleVoice", 0.0},
                                            {"doubleVoiceLevel", 0.0},
                                            {"doubleVoiceTimeShift", 0.0}, {"speed", 100.0}};
  std::atomic<std::uint64_t> stopGeneration_{0};
};

class SimMemory : public SimModule {
 public:
  SimMemory(RobotState& robot, CallLog& log);

 private:
  // Device keys computed from the robot state; nothing if key is not one.
  std::optional<Value> deviceKey(const std::string& key) const;
  std::vector<std::string> deviceKeys() const;
  Value get(const std::string& key) const;
  void insert(const std::string& key, const Value& value);

  RobotState& robot_;
  CallLog& log_;
  mutable std::mutex mutex_;
  static constexpr std::size_t kMaxKeys = 10000;
  static constexpr std::size_t kMaxBytes = 64u << 20;
  std::map<std::string, Value> data_;
  std::size_t storedBytes_ = 0;
  std::set<std::string> events_;
};

class SimBattery : public SimModule {
 public:
  explicit SimBattery(RobotState& robot);

 private:
  RobotState& robot_;
  std::atomic<bool> monitoring_{false};
};

class SimVideo : public SimModule {
 public:
  SimVideo();

 private:
  struct Subscriber {
    std::uint32_t camera, resolution, colorSpace, fps;
  };
  Value image(const Subscriber& s);
  std::string subscribe(const std::string& name, Subscriber s);

  std::mutex mutex_;
  std::map<std::string, Subscriber> subscribers_;
  std::uint32_t activeCamera_ = 0;
  SceneRenderer renderer_;
};

// "Robot": not a NAOqi module; Touchline's view of the robot side itself.
class SimRobotInfo : public SimModule {
 public:
  SimRobotInfo(std::function<std::vector<std::string>()> modules, CallLog& log,
               const RpcCounters* counters);
};

}  // namespace touchline::nao
