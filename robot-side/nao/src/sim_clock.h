// The simulated robot's time source. The body (RobotState) reads "now" and waits for
// deadlines only through a SimClock, so unit tests can run the robot on a manual clock
// and assert on simulated time instead of the wall clock.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>

namespace touchline::nao {

class SimClock {
 public:
  using duration = std::chrono::steady_clock::duration;
  using time_point = std::chrono::steady_clock::time_point;

  virtual ~SimClock() = default;
  virtual time_point now() const = 0;
  // Called with lock held (on the mutex cv waits with). Waits until deadline or until
  // woken() is true (checked under the lock). Returns woken().
  virtual bool waitUntil(std::condition_variable& cv, std::unique_lock<std::mutex>& lock,
                         time_point deadline, const std::function<bool()>& woken) = 0;
};

// Real time: the steady clock and real waits (the simulator, integration tests).
class SteadySimClock : public SimClock {
 public:
  time_point now() const override { return std::chrono::steady_clock::now(); }
  bool waitUntil(std::condition_variable& cv, std::unique_lock<std::mutex>& lock,
                 time_point deadline, const std::function<bool()>& woken) override {
    return cv.wait_until(lock, deadline, woken);
  }
};

// Unit-test time: stands still until advanced. A wait that is not woken at once jumps the
// clock to its deadline (a blocking call takes exactly its simulated time, no real time).
class ManualSimClock : public SimClock {
 public:
  time_point now() const override { return time_point(duration(ticks_.load())); }
  void advance(duration by) { ticks_ += by.count(); }
  // Simulated time since the clock was made.
  double elapsedSeconds() const {
    return std::chrono::duration<double>(duration(ticks_.load())).count();
  }
  bool waitUntil(std::condition_variable&, std::unique_lock<std::mutex>&, time_point deadline,
                 const std::function<bool()>& woken) override {
    if (woken()) return true;
    auto target = deadline.time_since_epoch().count();
    auto current = ticks_.load();
    while (current < target && !ticks_.compare_exchange_weak(current, target)) {
    }
    return false;
  }

 private:
  std::atomic<duration::rep> ticks_{0};
};

}  // namespace touchline::nao
