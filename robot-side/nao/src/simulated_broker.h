// The simulated NAOqi broker: ALMotion, ALRobotPosture, ALTextToSpeech, ALMemory,
// ALBattery, ALVideoDevice and Touchline's "Robot" info module over one RobotState.
#pragma once

#include <map>
#include <memory>

#include "call_log.h"
#include "naoqi_broker.h"
#include "robot_state.h"
#include "rpc_counters.h"
#include "sim_module.h"

namespace touchline::nao {

class SimulatedBroker : public NaoqiBroker {
 public:
  // timeScale < 1 makes blocking calls faster (tests); counters feed Robot.getRpcStats.
  explicit SimulatedBroker(double timeScale = 1.0, const RpcCounters* counters = nullptr);
  // The robot's body runs on clock (unit tests pass a ManualSimClock); the overload above
  // uses the steady clock.
  SimulatedBroker(double timeScale, const RpcCounters* counters, std::shared_ptr<SimClock> clock);
  ~SimulatedBroker() override;

  std::optional<Value> call(const std::string& module, const std::string& method,
                            const Params& params) override;
  std::vector<std::string> moduleNames() const override;
  bool isQuick(const std::string& module, const std::string& method) const override;
  void shutdown() override;

  RobotState& robot() { return robot_; }
  CallLog& callLog() { return log_; }

 private:
  RobotState robot_;
  CallLog log_;
  std::map<std::string, std::unique_ptr<SimModule>> modules_;
};

}  // namespace touchline::nao
