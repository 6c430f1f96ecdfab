// The simulated robot's body: stiffness and angle per joint (within the joint limits),
// posture, position and walk velocity, battery. Shared by the simulated modules; every
// public method locks, so modules may be called from several worker threads at once.
// Time: durations are "robot seconds"; sleepFor() waits robot seconds x timeScale of clock
// time, so unit tests can run a 3 s posture change in 150 ms. The clock is injected
// (SimClock): the steady clock by default, a manual clock in unit tests.
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "sim_clock.h"

namespace touchline::nao {

struct JointInfo {
  std::string name;
  std::string chain;
  double min;
  double max;
};

class RobotState {
 public:
  using TimePoint = SimClock::time_point;

  static constexpr double kJointMaxSpeed = 6.0;    // rad/s, all joints (simplification)
  static constexpr double kMaxWalkX = 0.10;        // m/s
  static constexpr double kMaxWalkY = 0.07;        // m/s
  static constexpr double kMaxWalkTheta = 0.5;     // rad/s

  explicit RobotState(double timeScale = 1.0,
                      std::shared_ptr<SimClock> clock = std::make_shared<SteadySimClock>());

  static const std::vector<JointInfo>& joints();
  static std::vector<std::string> chains();  // Head, LArm, LLeg, RLeg, RArm
  // Expands joint / chain / "Body" names; throws CallError for unknown names.
  std::vector<std::string> expandNames(const std::vector<std::string>& names) const;
  const JointInfo& joint(const std::string& name) const;

  void setStiffness(const std::string& joint, double value);  // clamped to 0..1
  double stiffness(const std::string& joint) const;
  bool anyStiffness() const;
  // Moves the joint towards target (clamped to its limits) over robotSeconds. Does nothing
  // and returns false when the joint's stiffness is 0 (a limp motor does not move).
  bool commandAngle(const std::string& joint, double target, double robotSeconds);
  // Last accepted command (actuator). Removing stiffness stops the joint where it is
  // (sensor) but keeps the command, as on the robot.
  double commandedAngle(const std::string& joint) const;
  double sensedAngle(const std::string& joint) const;     // where the joint is now (sensor)

  // Postures: Crouch, LyingBack, LyingBelly, Sit, SitRelax, Stand, StandInit, StandZero.
  static std::vector<std::string> postures();
  static std::string familyOf(const std::string& posture);
  std::string posture() const;
  // Robot seconds a transition to target takes at speed 1.0 from the current posture.
  double transitionSeconds(const std::string& target) const;
  // Blocks for the transition (base / speed), stiffens the body, then takes the posture.
  // Returns false when interrupted by stopPosture() or shutdown.
  bool goToPosture(const std::string& target, double speed);
  void stopPosture();

  // Walking, in the robot frame (m/s, rad/s). Changing the velocity interrupts a moveTo.
  void setVelocity(double vx, double vy, double vtheta);
  std::array<double, 3> velocity() const;
  std::array<double, 3> position() const;  // x, y, theta in the world frame
  bool moving() const;
  // Walks the displacement (robot frame) at the walk speed; blocks. False if interrupted.
  // The walk ends where planned even if this thread wakes late: the position never
  // integrates the walk's velocity past its planned end.
  bool moveBy(double x, double y, double theta);
  // Blocks until no walk is active (or shutdown). False on shutdown.
  bool waitUntilStill();

  int batteryPercent() const;

  double timeScale() const { return timeScale_; }
  // Sleeps robotSeconds x timeScale; returns false if woken early by stop(): either
  // shutdown, or cancelled() turned true (checked under the lock, so use atomics).
  bool sleepFor(double robotSeconds, const std::function<bool()>& cancelled = {});
  void wakeSleepers();
  void shutdown();
  bool isShutdown() const { return shutdown_; }

 private:
  struct JointMotion {
    double stiffness = 0.0;
    double command = 0.0;  // last accepted command (the actuator value)
    double from = 0.0;
    double to = 0.0;
    TimePoint start{};
    double realSeconds = 0.0;
  };
  double sensedLocked(const JointMotion& m, TimePoint now) const;
  void advanceLocked(TimePoint now) const;  // integrates walk and battery
  SimClock::duration clockTime(double robotSeconds) const;  // x timeScale
  // Sets the walk velocity (clamped), ending at plannedEnd if given; returns its generation.
  std::uint64_t startWalk(const std::array<double, 3>& v, std::optional<TimePoint> plannedEnd);
  bool sleepUntil(TimePoint deadline, const std::function<bool()>& cancelled);
  void applyPostureAnglesLocked(const std::string& posture);

  const double timeScale_;
  const std::shared_ptr<SimClock> clock_;
  mutable std::mutex mutex_;
  std::condition_variable cv_;
  std::atomic<bool> shutdown_{false};
  std::atomic<std::uint64_t> moveGeneration_{0};
  std::atomic<std::uint64_t> postureGeneration_{0};

  std::map<std::string, JointMotion> joints_;
  std::string posture_ = "Crouch";
  mutable std::array<double, 3> position_{0, 0, 0};
  mutable std::array<double, 3> velocity_{0, 0, 0};
  mutable std::optional<TimePoint> walkEnd_;  // planned end of a moveBy; none for move
  mutable double battery_ = 100.0;
  mutable TimePoint lastAdvance_;
};

}  // namespace touchline::nao
