#include <algorithm>
#include <sstream>

#include "sim_modules.h"

namespace touchline::nao {

namespace {
void checkPosture(const std::string& name) {
  auto all = RobotState::postures();
  if (std::find(all.begin(), all.end(), name) == all.end()) {
    std::string list;
    for (const auto& p : all) list += (list.empty() ? "" : ", ") + p;
    throw CallError("unknown posture '" + name + "' (postures: " + list + ")");
  }
}

void checkSpeed(double speed) {
  if (!(speed > 0.0 && speed <= 1.0)) {
    std::ostringstream msg;
    msg << "maxSpeedFraction must be in (0, 1], got " << speed;
    throw CallError(msg.str());
  }
}
}  // namespace

SimPosture::SimPosture(RobotState& robot)
    : SimModule("ALRobotPosture", "Predefined postures (simulated transition times)."),
      robot_(robot) {
  add({"goToPosture", {{"postureName", ParamType::String}, {"maxSpeedFraction", ParamType::Float}},
       "bool",
       "Goes to a predefined posture; blocks base time / speed (Sit->Stand 3 s at 1.0, from "
       "lying 5 s); stiffens the body. False if interrupted by stopMove.",
       [this](const Params& p) {
         std::string name = stringArg(p, 0);
         checkPosture(name);
         checkSpeed(numberArg(p, 1));
         return std::optional<Value>(boolValue(robot_.goToPosture(name, numberArg(p, 1))));
       }});
  add({"applyPosture", {{"postureName", ParamType::String}, {"maxSpeedFraction", ParamType::Float}},
       "bool", "Sets the joints of a posture directly (1 s / speed).",
       [this](const Params& p) {
         std::string name = stringArg(p, 0);
         checkPosture(name);
         checkSpeed(numberArg(p, 1));
         if (!robot_.sleepFor(1.0 / numberArg(p, 1))) return std::optional<Value>(boolValue(false));
         return std::optional<Value>(boolValue(robot_.goToPosture(name, 1e9)));
       }});
  add({"getPosture", {}, "str", "Current posture name.",
       [this](const Params&) { return std::optional<Value>(stringValue(robot_.posture())); }});
  add({"getPostureList", {}, "Vec<str>", "Predefined postures.",
       [](const Params&) { return std::optional<Value>(stringList(RobotState::postures())); }});
  add({"getPostureFamily", {}, "str", "Family of the current posture.",
       [this](const Params&) {
         return std::optional<Value>(stringValue(RobotState::familyOf(robot_.posture())));
       }});
  add({"getPostureFamilyList", {}, "Vec<str>", "Families of the predefined postures.",
       [](const Params&) {
         return std::optional<Value>(
             stringList({"Standing", "Sitting", "Crouching", "LyingBack", "LyingBelly"}));
       }});
  add({"stopMove", {}, "void", "Interrupts a running goToPosture (it returns false).",
       [this](const Params&) {
         robot_.stopPosture();
         return none();
       }});
  add({"setMaxTryNumber", {{"maxTryNumber", ParamType::Int}}, "void", "Retries (flag only).",
       [this](const Params& p) {
         maxTries_ = intArg(p, 0);
         return none();
       }});
  markQuick({"getPosture", "getPostureList", "getPostureFamily", "getPostureFamilyList",
             "stopMove", "setMaxTryNumber"});
}

}  // namespace touchline::nao
