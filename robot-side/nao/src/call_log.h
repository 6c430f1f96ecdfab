// Bounded log of the calls the simulated broker executed, so tests (including the Java
// ones) can prove that a call did or did not run.
#pragma once

#include <cstdint>
#include <deque>
#include <mutex>
#include <string>
#include <vector>

namespace touchline::nao {

class CallLog {
 public:
  explicit CallLog(std::size_t capacity = 1000) : capacity_(capacity) {}

  void record(std::string entry);
  std::vector<std::string> entries() const;  // oldest first, "<seq> <module.method(args)>"
  void clear();
  std::uint64_t total() const;

 private:
  mutable std::mutex mutex_;
  std::size_t capacity_;
  std::deque<std::string> entries_;
  std::uint64_t seq_ = 0;
};

}  // namespace touchline::nao
