#include <algorithm>
#include <cmath>
#include <sstream>

#include "sim_modules.h"

namespace touchline::nao {

namespace {
using P = ParamType;

// One value per joint: a single number applies to all joints, else a list of equal length.
std::vector<double> perJoint(const std::vector<double>& values, std::size_t joints,
                             const char* what) {
  if (values.size() == 1) return std::vector<double>(joints, values[0]);
  if (values.size() != joints) {
    throw CallError(std::string(what) + ": got " + std::to_string(values.size()) +
                    " values for " + std::to_string(joints) + " joints");
  }
  return values;
}

// angleInterpolation-style lists: per joint a number or a list of numbers (keyframes).
std::vector<std::vector<double>> perJointSeries(const Value& v, std::size_t joints,
                                                const char* what) {
  auto numbers = [&](const Value& item) {
    if (isNumber(item)) return std::vector<double>{numberOf(item)};
    std::vector<double> out;
    if (kindOf(item) != Kind::Array || item.array_size() == 0)
      throw CallError(std::string(what) + ": expected numbers");
    for (const auto& x : item.array()) {
      if (!isNumber(x)) throw CallError(std::string(what) + ": expected numbers");
      out.push_back(numberOf(x));
    }
    return out;
  };
  if (joints == 1) {
    // One joint: a number, a keyframe list, or a list holding one keyframe list.
    if (kindOf(v) == Kind::Array && v.array_size() == 1 && kindOf(v.array(0)) == Kind::Array)
      return {numbers(v.array(0))};
    return {numbers(v)};
  }
  if (kindOf(v) != Kind::Array || static_cast<std::size_t>(v.array_size()) != joints) {
    throw CallError(std::string(what) + ": expected one entry per joint (" +
                    std::to_string(joints) + ")");
  }
  std::vector<std::vector<double>> out;
  for (const auto& item : v.array()) out.push_back(numbers(item));
  return out;
}

void checkFraction(double f, const char* what) {
  if (!(f > 0.0 && f <= 1.0)) {
    std::ostringstream msg;
    msg << what << " must be in (0, 1], got " << f;
    throw CallError(msg.str());
  }
}
}  // namespace

SimMotion::SimMotion(RobotState& robot)
    : SimModule("ALMotion", "Joint stiffness and angles, walking (simulated)."), robot_(robot) {
  add({"wakeUp", {}, "void", "Stiffens the body and goes to StandInit if not standing. Blocking.",
       [this](const Params&) {
         if (RobotState::familyOf(robot_.posture()) != "Standing") robot_.goToPosture("StandInit", 1.0);
         for (const auto& j : RobotState::joints()) robot_.setStiffness(j.name, 1.0);
         return none();
       }});
  add({"rest", {}, "void", "Goes to Crouch and removes stiffness. Blocking.",
       [this](const Params&) {
         robot_.setVelocity(0, 0, 0);
         robot_.goToPosture("Crouch", 1.0);
         for (const auto& j : RobotState::joints()) robot_.setStiffness(j.name, 0.0);
         return none();
       }});
  add({"robotIsWakeUp", {}, "bool", "True if any joint is stiff.",
       [this](const Params&) { return std::optional<Value>(boolValue(robot_.anyStiffness())); }});
  add({"setStiffnesses", {{"names", P::Names}, {"stiffnesses", P::Numbers}}, "void",
       "Sets stiffness 0..1 (clamped) of joints/chains/Body. Non-blocking.",
       [this](const Params& p) {
         auto joints = robot_.expandNames(namesArg(p, 0));
         auto values = perJoint(numbersArg(p, 1), joints.size(), "stiffnesses");
         for (std::size_t i = 0; i < joints.size(); ++i) robot_.setStiffness(joints[i], values[i]);
         return none();
       }});
  add({"getStiffnesses", {{"jointName", P::Names}}, "Vec<float>", "Stiffness per joint.",
       [this](const Params& p) {
         std::vector<double> out;
         for (const auto& j : robot_.expandNames(namesArg(p, 0))) out.push_back(robot_.stiffness(j));
         return std::optional<Value>(floatList(out));
       }});
  add({"stiffnessInterpolation",
       {{"names", P::Names}, {"stiffnessLists", P::Any}, {"timeLists", P::Any}}, "void",
       "Interpolates stiffness over the given times (s). Blocking.",
       [this](const Params& p) {
         auto joints = robot_.expandNames(namesArg(p, 0));
         auto values = perJointSeries(p[1], joints.size(), "stiffnessLists");
         auto times = perJointSeries(p[2], joints.size(), "timeLists");
         double longest = 0;
         for (const auto& t : times) longest = std::max(longest, t.back());
         if (!robot_.sleepFor(longest)) return none();
         for (std::size_t i = 0; i < joints.size(); ++i) robot_.setStiffness(joints[i], values[i].back());
         return none();
       }});
  add({"setAngles", {{"names", P::Names}, {"angles", P::Numbers}, {"fractionMaxSpeed", P::Float}},
       "void", "Moves joints towards angles (rad, clamped to limits); joints with stiffness 0 "
       "ignore it. Non-blocking.",
       [this](const Params& p) {
         auto joints = robot_.expandNames(namesArg(p, 0));
         setAngles(joints, perJoint(numbersArg(p, 1), joints.size(), "angles"), numberArg(p, 2), false);
         return none();
       }});
  add({"changeAngles", {{"names", P::Names}, {"changes", P::Numbers}, {"fractionMaxSpeed", P::Float}},
       "void", "Like setAngles, relative to the current command. Non-blocking.",
       [this](const Params& p) {
         auto joints = robot_.expandNames(namesArg(p, 0));
         setAngles(joints, perJoint(numbersArg(p, 1), joints.size(), "changes"), numberArg(p, 2), true);
         return none();
       }});
  add({"getAngles", {{"names", P::Names}, {"useSensors", P::Bool}}, "Vec<float>",
       "Joint angles (rad): sensed position, or the last command.",
       [this](const Params& p) {
         std::vector<double> out;
         for (const auto& j : robot_.expandNames(namesArg(p, 0)))
           out.push_back(boolArg(p, 1) ? robot_.sensedAngle(j) : robot_.commandedAngle(j));
         return std::optional<Value>(floatList(out));
       }});
  add({"angleInterpolation",
       {{"names", P::Names}, {"angleLists", P::Any}, {"timeLists", P::Any}, {"isAbsolute", P::Bool}},
       "void", "Keyframe motion; blocks until the last time (s).",
       [this](const Params& p) {
         auto joints = robot_.expandNames(namesArg(p, 0));
         auto angles = perJointSeries(p[1], joints.size(), "angleLists");
         auto times = perJointSeries(p[2], joints.size(), "timeLists");
         double longest = 0;
         for (std::size_t i = 0; i < joints.size(); ++i) {
           if (angles[i].size() != times[i].size())
             throw CallError("angleInterpolation: angle and time lists differ in length for " + joints[i]);
           for (std::size_t k = 1; k < times[i].size(); ++k)
             if (times[i][k] <= times[i][k - 1]) throw CallError("angleInterpolation: times must increase");
           if (times[i].front() <= 0) throw CallError("angleInterpolation: times must be > 0");
           double target = angles[i].back();
           if (!boolArg(p, 3)) target += robot_.commandedAngle(joints[i]);
           robot_.commandAngle(joints[i], target, times[i].back());
           longest = std::max(longest, times[i].back());
         }
         robot_.sleepFor(longest);
         return none();
       }});
  add({"angleInterpolationWithSpeed",
       {{"names", P::Names}, {"targetAngles", P::Numbers}, {"maxSpeedFraction", P::Float}}, "void",
       "Moves joints to the targets at a fraction of max speed; blocks until reached.",
       [this](const Params& p) {
         auto joints = robot_.expandNames(namesArg(p, 0));
         auto targets = perJoint(numbersArg(p, 1), joints.size(), "targetAngles");
         double fraction = numberArg(p, 2);
         checkFraction(fraction, "maxSpeedFraction");
         double longest = 0;
         for (std::size_t i = 0; i < joints.size(); ++i) {
           double seconds = std::abs(targets[i] - robot_.sensedAngle(joints[i])) /
                            (fraction * RobotState::kJointMaxSpeed);
           if (robot_.commandAngle(joints[i], targets[i], seconds)) longest = std::max(longest, seconds);
         }
         robot_.sleepFor(longest);
         return none();
       }});
  for (const char* verb : {"openHand", "closeHand"}) {
    bool open = std::string(verb) == "openHand";
    add({verb, {{"handName", P::String}}, "void", "LHand or RHand. Blocking (~0.5 s).",
         [this, open](const Params& p) {
           std::string hand = stringArg(p, 0);
           if (hand != "LHand" && hand != "RHand") throw CallError("handName must be LHand or RHand");
           if (robot_.commandAngle(hand, open ? 1.0 : 0.0, 0.5)) robot_.sleepFor(0.5);
           return none();
         }});
  }
  add({"moveInit", {}, "void", "Puts a standing robot into its walk pose. Blocking.",
       [this](const Params&) {
         requireStanding("moveInit");
         if (robot_.posture() != "StandInit") robot_.goToPosture("StandInit", 1.0);
         return none();
       }});
  for (const char* verb : {"moveTo", "walkTo"}) {
    add({verb, {{"x", P::Float}, {"y", P::Float}, {"theta", P::Float}}, "void",
         "Walks x, y (m) and turns theta (rad) in FRAME_ROBOT. Blocking until arrived "
         "(or stopMove).",
         [this, verb](const Params& p) {
           requireStanding(verb);
           robot_.moveBy(numberArg(p, 0), numberArg(p, 1), numberArg(p, 2));
           return none();
         }});
  }
  add({"move", {{"x", P::Float}, {"y", P::Float}, {"theta", P::Float}}, "void",
       "Walks at a velocity (m/s, rad/s; clamped to 0.10, 0.07, 0.5). Non-blocking.",
       [this](const Params& p) {
         double x = numberArg(p, 0), y = numberArg(p, 1), t = numberArg(p, 2);
         if (x != 0 || y != 0 || t != 0) requireStanding("move");
         robot_.setVelocity(x, y, t);
         return none();
       }});
  add({"moveToward", {{"x", P::Float}, {"y", P::Float}, {"theta", P::Float}}, "void",
       "Walks at normalised velocity -1..1 of the maximum. Non-blocking.",
       [this](const Params& p) {
         double x = numberArg(p, 0), y = numberArg(p, 1), t = numberArg(p, 2);
         for (double v : {x, y, t})
           if (v < -1.0 || v > 1.0) throw CallError("moveToward: values must be in -1..1");
         if (x != 0 || y != 0 || t != 0) requireStanding("moveToward");
         robot_.setVelocity(x * RobotState::kMaxWalkX, y * RobotState::kMaxWalkY,
                            t * RobotState::kMaxWalkTheta);
         return none();
       }});
  add({"setWalkTargetVelocity",
       {{"x", P::Float}, {"y", P::Float}, {"theta", P::Float}, {"frequency", P::Float}}, "void",
       "1.10 walk API: x, y, theta in -1..1, step frequency 0..1 (0 stops). Non-blocking.",
       [this](const Params& p) {
         double x = numberArg(p, 0), y = numberArg(p, 1), t = numberArg(p, 2), f = numberArg(p, 3);
         for (double v : {x, y, t})
           if (v < -1.0 || v > 1.0) throw CallError("setWalkTargetVelocity: x, y, theta must be in -1..1");
         if (f < 0.0 || f > 1.0) throw CallError("setWalkTargetVelocity: frequency must be in 0..1");
         if (f > 0 && (x != 0 || y != 0 || t != 0)) requireStanding("setWalkTargetVelocity");
         robot_.setVelocity(x * f * RobotState::kMaxWalkX, y * f * RobotState::kMaxWalkY,
                            t * f * RobotState::kMaxWalkTheta);
         return none();
       }});
  for (const char* verb : {"stopMove", "killMove", "killWalk"}) {
    add({verb, {}, "void", "Stops walking (interrupts moveTo).", [this](const Params&) {
           robot_.setVelocity(0, 0, 0);
           return none();
         }});
  }
  for (const char* verb : {"moveIsActive", "walkIsActive"}) {
    add({verb, {}, "bool", "True while walking.",
         [this](const Params&) { return std::optional<Value>(boolValue(robot_.moving())); }});
  }
  for (const char* verb : {"waitUntilMoveIsFinished", "waitUntilWalkIsFinished"}) {
    add({verb, {}, "void", "Blocks until the robot stops walking.", [this](const Params&) {
           robot_.waitUntilStill();
           return none();
         }});
  }
  add({"getRobotPosition", {{"useSensors", P::Bool}}, "Vec<float>", "[x, y, theta] in FRAME_WORLD.",
       [this](const Params&) {
         auto pos = robot_.position();
         return std::optional<Value>(floatList({pos[0], pos[1], pos[2]}));
       }});
  add({"getRobotVelocity", {}, "Vec<float>", "[vx, vy, vtheta] in FRAME_ROBOT.",
       [this](const Params&) {
         auto v = robot_.velocity();
         return std::optional<Value>(floatList({v[0], v[1], v[2]}));
       }});
  for (const char* verb : {"getBodyNames", "getJointNames"}) {
    add({verb, {{"name", P::Names}}, "Vec<str>", "Joint names of a joint, chain or Body.",
         [this](const Params& p) {
           return std::optional<Value>(stringList(robot_.expandNames(namesArg(p, 0))));
         }});
  }
  add({"getLimits", {{"name", P::Names}}, "any",
       "Per joint [minAngle, maxAngle, maxVelocity, maxTorque] (rad, rad/s, N.m).",
       [this](const Params& p) {
         std::vector<Value> rows;
         for (const auto& j : robot_.expandNames(namesArg(p, 0))) {
           const JointInfo& info = robot_.joint(j);
           rows.push_back(floatList({info.min, info.max, RobotState::kJointMaxSpeed, 1.0}));
         }
         return std::optional<Value>(arrayValue(std::move(rows)));
       }});
  add({"getSummary", {}, "str", "Text table of joints, stiffness, angles and walk state.",
       [this](const Params&) {
         std::ostringstream out;
         out << "Posture: " << robot_.posture() << "\nJoint            Stiffness  Command  Sensor\n";
         for (const auto& j : RobotState::joints()) {
           out << j.name << std::string(17 - j.name.size(), ' ') << robot_.stiffness(j.name)
               << "\t" << robot_.commandedAngle(j.name) << "\t" << robot_.sensedAngle(j.name) << "\n";
         }
         auto v = robot_.velocity();
         out << "Walk velocity: " << v[0] << " " << v[1] << " " << v[2] << "\n";
         return std::optional<Value>(stringValue(out.str()));
       }});
  add({"setFallManagerEnabled", {{"enable", P::Bool}}, "void", "Fall manager on/off (flag only).",
       [this](const Params& p) { fallManager_ = boolArg(p, 0); return none(); }});
  add({"getFallManagerEnabled", {}, "bool", "Fall manager flag.",
       [this](const Params&) { return std::optional<Value>(boolValue(fallManager_)); }});
  add({"setMoveArmsEnabled", {{"leftArmEnable", P::Bool}, {"rightArmEnable", P::Bool}}, "void",
       "Arm swing while walking (flags only).", [this](const Params& p) {
         leftArmSwing_ = boolArg(p, 0);
         rightArmSwing_ = boolArg(p, 1);
         return none();
       }});
  add({"getMoveArmsEnabled", {{"chainName", P::String}}, "bool", "LArm, RArm or Arms.",
       [this](const Params& p) {
         std::string chain = stringArg(p, 0);
         bool v = chain == "LArm" ? leftArmSwing_.load()
                  : chain == "RArm" ? rightArmSwing_.load()
                  : chain == "Arms" ? (leftArmSwing_ && rightArmSwing_)
                  : throw CallError("chainName must be LArm, RArm or Arms");
         return std::optional<Value>(boolValue(v));
       }});
  // Getters and velocity/stiffness/angle commands only set state; the interpolations,
  // posture changes, moveTo and waits block for robot time.
  markQuick({"robotIsWakeUp", "setStiffnesses", "getStiffnesses", "setAngles", "changeAngles",
             "getAngles", "move", "moveToward", "setWalkTargetVelocity", "stopMove", "killMove",
             "killWalk", "moveIsActive", "walkIsActive", "getRobotPosition", "getRobotVelocity",
             "getBodyNames", "getJointNames", "getLimits", "getSummary", "setFallManagerEnabled",
             "getFallManagerEnabled", "setMoveArmsEnabled", "getMoveArmsEnabled"});
}

void SimMotion::requireStanding(const char* method) const {
  std::string posture = robot_.posture();
  if (RobotState::familyOf(posture) != "Standing") {
    throw CallError(std::string("ALMotion.") + method + ": robot is not standing (posture " +
                    posture + "); call ALRobotPosture.goToPosture(\"Stand\", 1.0) first");
  }
}

void SimMotion::setAngles(const std::vector<std::string>& joints,
                          const std::vector<double>& targets, double fraction, bool relative) {
  checkFraction(fraction, "fractionMaxSpeed");
  for (std::size_t i = 0; i < joints.size(); ++i) {
    double target = relative ? robot_.commandedAngle(joints[i]) + targets[i] : targets[i];
    double seconds = std::abs(target - robot_.sensedAngle(joints[i])) /
                     (fraction * RobotState::kJointMaxSpeed);
    robot_.commandAngle(joints[i], target, seconds);  // ignored when stiffness is 0
  }
}

}  // namespace touchline::nao
