#include "robot_state.h"

#include <algorithm>
#include <cmath>

#include "mixed_value.h"

namespace touchline::nao {

namespace {
// Head/arm rows: doc.aldebaran.com 1-14 joints page (V4 body); legs: Aldebaran H25 table as
// reproduced in public codebases; hands 0 (closed) .. 1 (open). See shared brief nao.md.
const std::vector<JointInfo> kJoints = {
    {"HeadYaw", "Head", -2.0857, 2.0857},
    {"HeadPitch", "Head", -0.6720, 0.5149},
    {"LShoulderPitch", "LArm", -2.0857, 2.0857},
    {"LShoulderRoll", "LArm", -0.3142, 1.3265},
    {"LElbowYaw", "LArm", -2.0857, 2.0857},
    {"LElbowRoll", "LArm", -1.5446, -0.0349},
    {"LWristYaw", "LArm", -1.8238, 1.8238},
    {"LHand", "LArm", 0.0, 1.0},
    {"LHipYawPitch", "LLeg", -1.145303, 0.740810},
    {"LHipRoll", "LLeg", -0.379472, 0.790477},
    {"LHipPitch", "LLeg", -1.535889, 0.484090},
    {"LKneePitch", "LLeg", -0.092346, 2.112528},
    {"LAnklePitch", "LLeg", -1.189516, 0.922747},
    {"LAnkleRoll", "LLeg", -0.397880, 0.769001},
    {"RHipYawPitch", "RLeg", -1.145303, 0.740810},
    {"RHipRoll", "RLeg", -0.790477, 0.379472},
    {"RHipPitch", "RLeg", -1.535889, 0.484090},
    {"RKneePitch", "RLeg", -0.103083, 2.120198},
    {"RAnklePitch", "RLeg", -1.186448, 0.932056},
    {"RAnkleRoll", "RLeg", -0.768992, 0.397935},
    {"RShoulderPitch", "RArm", -2.0857, 2.0857},
    {"RShoulderRoll", "RArm", -1.3265, 0.3142},
    {"RElbowYaw", "RArm", -2.0857, 2.0857},
    {"RElbowRoll", "RArm", 0.0349, 1.5446},
    {"RWristYaw", "RArm", -1.8238, 1.8238},
    {"RHand", "RArm", 0.0, 1.0},
};

// Approximate joint angles of the predefined postures (ours, for plausible getAngles
// answers; unlisted joints are 0, everything is clamped to the limits).
const std::map<std::string, std::map<std::string, double>> kPostureAngles = {
    {"Stand", {{"LShoulderPitch", 1.4}, {"RShoulderPitch", 1.4}, {"LShoulderRoll", 0.2},
               {"RShoulderRoll", -0.2}, {"LElbowRoll", -0.4}, {"RElbowRoll", 0.4}}},
    {"StandInit", {{"LHipPitch", -0.45}, {"RHipPitch", -0.45}, {"LKneePitch", 0.7},
                   {"RKneePitch", 0.7}, {"LAnklePitch", -0.35}, {"RAnklePitch", -0.35},
                   {"LShoulderPitch", 1.4}, {"RShoulderPitch", 1.4}, {"LElbowRoll", -1.0},
                   {"RElbowRoll", 1.0}}},
    {"StandZero", {}},
    {"Crouch", {{"LHipPitch", -0.87}, {"RHipPitch", -0.87}, {"LKneePitch", 2.1},
                {"RKneePitch", 2.1}, {"LAnklePitch", -1.18}, {"RAnklePitch", -1.18},
                {"LShoulderPitch", 1.5}, {"RShoulderPitch", 1.5}}},
    {"Sit", {{"LHipPitch", -1.5}, {"RHipPitch", -1.5}, {"LKneePitch", 1.0}, {"RKneePitch", 1.0},
             {"LAnklePitch", 0.8}, {"RAnklePitch", 0.8}, {"LShoulderPitch", 0.9},
             {"RShoulderPitch", 0.9}}},
    {"SitRelax", {{"LHipPitch", -1.5}, {"RHipPitch", -1.5}, {"LKneePitch", 1.0},
                  {"RKneePitch", 1.0}, {"LShoulderPitch", 2.0}, {"RShoulderPitch", 2.0}}},
    {"LyingBack", {}},
    {"LyingBelly", {{"LShoulderPitch", -1.5}, {"RShoulderPitch", -1.5}}},
};

double clamp(double v, double lo, double hi) { return std::max(lo, std::min(hi, v)); }
}  // namespace

RobotState::RobotState(double timeScale, std::shared_ptr<SimClock> clock)
    : timeScale_(timeScale), clock_(std::move(clock)), lastAdvance_(clock_->now()) {
  for (const auto& j : kJoints) joints_[j.name] = JointMotion{};
  applyPostureAnglesLocked(posture_);
}

const std::vector<JointInfo>& RobotState::joints() { return kJoints; }

std::vector<std::string> RobotState::chains() { return {"Head", "LArm", "LLeg", "RLeg", "RArm"}; }

std::vector<std::string> RobotState::expandNames(const std::vector<std::string>& names) const {
  std::vector<std::string> out;
  for (const auto& name : names) {
    bool found = false;
    for (const auto& j : kJoints) {
      if (name == "Body" || j.chain == name || j.name == name) {
        out.push_back(j.name);
        found = true;
      }
    }
    if (!found) {
      throw CallError("unknown joint or chain '" + name +
                      "' (use a joint name, Head, LArm, RArm, LLeg, RLeg or Body)");
    }
  }
  return out;
}

const JointInfo& RobotState::joint(const std::string& name) const {
  for (const auto& j : kJoints) if (j.name == name) return j;
  throw CallError("unknown joint '" + name + "'");
}

void RobotState::setStiffness(const std::string& joint, double value) {
  std::lock_guard<std::mutex> lock(mutex_);
  auto& m = joints_.at(joint);
  if (value <= 0.0) {
    // A limp joint stays where it is now.
    auto now = clock_->now();
    double here = sensedLocked(m, now);
    m.from = m.to = here;
    m.realSeconds = 0.0;
  }
  m.stiffness = clamp(value, 0.0, 1.0);
}

double RobotState::stiffness(const std::string& joint) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return joints_.at(joint).stiffness;
}

bool RobotState::anyStiffness() const {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& [name, m] : joints_) if (m.stiffness > 0.0) return true;
  return false;
}

double RobotState::sensedLocked(const JointMotion& m, TimePoint now) const {
  if (m.realSeconds <= 0.0) return m.to;
  double t = std::chrono::duration<double>(now - m.start).count() / m.realSeconds;
  return m.from + (m.to - m.from) * clamp(t, 0.0, 1.0);
}

bool RobotState::commandAngle(const std::string& jointName, double target, double robotSeconds) {
  const JointInfo& info = joint(jointName);
  std::lock_guard<std::mutex> lock(mutex_);
  auto& m = joints_.at(jointName);
  if (m.stiffness <= 0.0) return false;
  auto now = clock_->now();
  m.from = sensedLocked(m, now);
  m.to = m.command = clamp(target, info.min, info.max);
  m.start = now;
  m.realSeconds = std::max(0.0, robotSeconds) * timeScale_;  // clock seconds
  return true;
}

double RobotState::commandedAngle(const std::string& joint) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return joints_.at(joint).command;
}

double RobotState::sensedAngle(const std::string& joint) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return sensedLocked(joints_.at(joint), clock_->now());
}

std::vector<std::string> RobotState::postures() {
  return {"Crouch", "LyingBack", "LyingBelly", "Sit", "SitRelax", "Stand", "StandInit",
          "StandZero"};
}

std::string RobotState::familyOf(const std::string& posture) {
  if (posture.rfind("Stand", 0) == 0) return "Standing";
  if (posture.rfind("Sit", 0) == 0) return "Sitting";
  if (posture == "Crouch") return "Crouching";
  return posture;  // LyingBack, LyingBelly
}

std::string RobotState::posture() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return posture_;
}

double RobotState::transitionSeconds(const std::string& target) const {
  // Our model (no official figures exist): standing up ~3 s, from the floor ~5 s.
  std::string from = posture();
  if (from == target) return 0.2;
  std::string a = familyOf(from), b = familyOf(target);
  if (a == b) return 1.0;
  if (a == "LyingBack" || a == "LyingBelly") return 5.0;
  if (b == "LyingBack" || b == "LyingBelly") return 2.0;
  if (a == "Standing" || b == "Standing") return 3.0;
  return 2.0;
}

bool RobotState::goToPosture(const std::string& target, double speed) {
  double seconds = transitionSeconds(target) / speed;
  setVelocity(0, 0, 0);
  for (const auto& j : kJoints) setStiffness(j.name, 1.0);
  std::uint64_t generation = postureGeneration_;
  bool completed =
      sleepFor(seconds, [this, generation] { return postureGeneration_ != generation; });
  if (!completed) return false;
  std::lock_guard<std::mutex> lock(mutex_);
  posture_ = target;
  applyPostureAnglesLocked(target);
  return true;
}

void RobotState::stopPosture() {
  ++postureGeneration_;
  wakeSleepers();
}

void RobotState::applyPostureAnglesLocked(const std::string& posture) {
  const auto& angles = kPostureAngles.at(posture);
  for (const auto& j : kJoints) {
    auto it = angles.find(j.name);
    double v = clamp(it == angles.end() ? 0.0 : it->second, j.min, j.max);
    auto& m = joints_.at(j.name);
    m.from = m.to = m.command = v;
    m.realSeconds = 0.0;
  }
}

void RobotState::advanceLocked(TimePoint now) const {
  if (now <= lastAdvance_) return;
  bool walking = velocity_[0] != 0 || velocity_[1] != 0 || velocity_[2] != 0;
  // A moveBy's walk stops at its planned end, however late its thread wakes.
  TimePoint walkUntil = walking && walkEnd_ ? std::clamp(*walkEnd_, lastAdvance_, now) : now;
  auto robotSeconds = [this](SimClock::duration d) {
    return std::chrono::duration<double>(d).count() / timeScale_;
  };
  double walked = walking ? robotSeconds(walkUntil - lastAdvance_) : 0.0;
  double stood = robotSeconds(now - lastAdvance_) - walked;
  const auto v = velocity_;
  lastAdvance_ = now;
  if (walkEnd_ && *walkEnd_ <= now) {
    velocity_ = {0, 0, 0};
    walkEnd_.reset();
  }
  // Battery model (ours): 1 % per 2 min standing still, 1 % per 20 s walking.
  battery_ = std::max(0.0, battery_ - walked / 20.0 - stood / 120.0);
  if (walked <= 0) return;
  int steps = static_cast<int>(std::min(1000.0, std::ceil(walked / 0.02)));
  double h = walked / steps;
  for (int i = 0; i < steps; ++i) {
    double c = std::cos(position_[2]), s = std::sin(position_[2]);
    position_[0] += (c * v[0] - s * v[1]) * h;
    position_[1] += (s * v[0] + c * v[1]) * h;
    position_[2] = std::remainder(position_[2] + v[2] * h, 2 * M_PI);
  }
}

void RobotState::setVelocity(double vx, double vy, double vtheta) {
  startWalk({vx, vy, vtheta}, std::nullopt);
}

std::uint64_t RobotState::startWalk(const std::array<double, 3>& v,
                                    std::optional<TimePoint> plannedEnd) {
  std::uint64_t generation;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    advanceLocked(clock_->now());
    velocity_ = {clamp(v[0], -kMaxWalkX, kMaxWalkX), clamp(v[1], -kMaxWalkY, kMaxWalkY),
                 clamp(v[2], -kMaxWalkTheta, kMaxWalkTheta)};
    walkEnd_ = plannedEnd;
    generation = ++moveGeneration_;
  }
  wakeSleepers();
  return generation;
}

std::array<double, 3> RobotState::velocity() const {
  std::lock_guard<std::mutex> lock(mutex_);
  advanceLocked(clock_->now());
  return velocity_;
}

std::array<double, 3> RobotState::position() const {
  std::lock_guard<std::mutex> lock(mutex_);
  advanceLocked(clock_->now());
  return position_;
}

bool RobotState::moving() const {
  std::lock_guard<std::mutex> lock(mutex_);
  advanceLocked(clock_->now());
  return velocity_[0] != 0 || velocity_[1] != 0 || velocity_[2] != 0;
}

bool RobotState::moveBy(double x, double y, double theta) {
  theta = std::remainder(theta, 2 * M_PI);
  double seconds = std::max({std::hypot(x, y) / kMaxWalkX, std::abs(theta) / kMaxWalkTheta, 0.1});
  // Constant velocity in the robot frame: for a pure translation or rotation this ends
  // exactly at the target; combined moves end on an arc near it (good enough here).
  TimePoint end = clock_->now() + clockTime(seconds);
  std::uint64_t generation = startWalk({x / seconds, y / seconds, theta / seconds}, end);
  bool completed = sleepUntil(end, [this, generation] { return moveGeneration_ != generation; });
  if (completed) setVelocity(0, 0, 0);
  return completed;
}

bool RobotState::waitUntilStill() {
  std::unique_lock<std::mutex> lock(mutex_);
  cv_.wait(lock, [this] {
    return shutdown_ || (velocity_[0] == 0 && velocity_[1] == 0 && velocity_[2] == 0);
  });
  return !shutdown_;
}

int RobotState::batteryPercent() const {
  std::lock_guard<std::mutex> lock(mutex_);
  advanceLocked(clock_->now());
  return static_cast<int>(std::ceil(battery_));
}

SimClock::duration RobotState::clockTime(double robotSeconds) const {
  return std::chrono::duration_cast<SimClock::duration>(
      std::chrono::duration<double>(robotSeconds * timeScale_));
}

bool RobotState::sleepFor(double robotSeconds, const std::function<bool()>& cancelled) {
  return sleepUntil(clock_->now() + clockTime(robotSeconds), cancelled);
}

bool RobotState::sleepUntil(TimePoint deadline, const std::function<bool()>& cancelled) {
  std::unique_lock<std::mutex> lock(mutex_);
  bool woken = clock_->waitUntil(cv_, lock, deadline,
                                 [&] { return shutdown_ || (cancelled && cancelled()); });
  return !woken;
}

void RobotState::wakeSleepers() {
  // Taking the lock orders this notify after a sleeper's predicate check.
  { std::lock_guard<std::mutex> lock(mutex_); }
  cv_.notify_all();
}

void RobotState::shutdown() {
  shutdown_ = true;
  wakeSleepers();
}

}  // namespace touchline::nao
