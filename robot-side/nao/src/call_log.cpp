#include "call_log.h"

namespace touchline::nao {

void CallLog::record(std::string entry) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++seq_;
  entries_.push_back(std::to_string(seq_) + " " + entry);
  while (entries_.size() > capacity_) entries_.pop_front();
}

std::vector<std::string> CallLog::entries() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return {entries_.begin(), entries_.end()};
}

void CallLog::clear() {
  std::lock_guard<std::mutex> lock(mutex_);
  entries_.clear();
}

std::uint64_t CallLog::total() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return seq_;
}

}  // namespace touchline::nao
