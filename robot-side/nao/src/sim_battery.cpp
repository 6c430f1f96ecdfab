#include "sim_modules.h"

namespace touchline::nao {

SimBattery::SimBattery(RobotState& robot)
    : SimModule("ALBattery", "Battery charge (simulated drain: 1 %/2 min idle, 1 %/20 s walking)."),
      robot_(robot) {
  add({"getBatteryCharge", {}, "int", "Charge in percent (0..100).", [this](const Params&) {
         return std::optional<Value>(intValue(static_cast<std::uint32_t>(robot_.batteryPercent())));
       }});
  add({"enablePowerMonitoring", {{"enable", ParamType::Bool}}, "void", "Flag only.",
       [this](const Params& p) {
         monitoring_ = boolArg(p, 0);
         return none();
       }});
  markQuick({"getBatteryCharge", "enablePowerMonitoring"});
}

}  // namespace touchline::nao
