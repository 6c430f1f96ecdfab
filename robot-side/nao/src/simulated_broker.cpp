#include "simulated_broker.h"

#include "sim_modules.h"

namespace touchline::nao {

SimulatedBroker::SimulatedBroker(double timeScale, const RpcCounters* counters)
    : SimulatedBroker(timeScale, counters, std::make_shared<SteadySimClock>()) {}

SimulatedBroker::SimulatedBroker(double timeScale, const RpcCounters* counters,
                                 std::shared_ptr<SimClock> clock)
    : robot_(timeScale, std::move(clock)) {
  std::vector<std::unique_ptr<SimModule>> all;
  all.push_back(std::make_unique<SimMotion>(robot_));
  all.push_back(std::make_unique<SimPosture>(robot_));
  all.push_back(std::make_unique<SimSpeech>(robot_));
  all.push_back(std::make_unique<SimMemory>(robot_, log_));
  all.push_back(std::make_unique<SimBattery>(robot_));
  all.push_back(std::make_unique<SimVideo>());
  all.push_back(std::make_unique<SimRobotInfo>([this] { return moduleNames(); }, log_, counters));
  for (auto& m : all) {
    std::string name = m->name();
    modules_[name] = std::move(m);
  }
}

SimulatedBroker::~SimulatedBroker() { shutdown(); }

std::optional<Value> SimulatedBroker::call(const std::string& module, const std::string& method,
                                           const Params& params) {
  auto it = modules_.find(module);
  if (it == modules_.end()) {
    std::string list;
    for (const auto& [name, m] : modules_) list += (list.empty() ? "" : ", ") + name;
    throw CallError("unknown module '" + module + "' (modules: " + list + ")");
  }
  // Robot.* (call log, stats) is not logged, so reading the log does not change it.
  return it->second->call(method, params, module == "Robot" ? nullptr : &log_);
}

std::vector<std::string> SimulatedBroker::moduleNames() const {
  std::vector<std::string> names;
  for (const auto& [name, m] : modules_) names.push_back(name);
  return names;
}

bool SimulatedBroker::isQuick(const std::string& module, const std::string& method) const {
  auto it = modules_.find(module);
  return it == modules_.end() || it->second->isQuick(method);  // unknown module: fails at once
}

void SimulatedBroker::shutdown() { robot_.shutdown(); }

}  // namespace touchline::nao
