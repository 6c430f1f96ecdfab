// One-line, thread-safe diagnostics on stderr (stdout carries the "listening" lines).
#pragma once

#include <iostream>
#include <mutex>
#include <string>

namespace touchline::nao {

inline void logLine(const std::string& line) {
  static std::mutex mutex;
  std::lock_guard<std::mutex> lock(mutex);
  std::cerr << "[nao-sim] " << line << std::endl;
}

}  // namespace touchline::nao
