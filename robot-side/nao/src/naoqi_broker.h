// The seam between the RPC module and a NAOqi broker. The simulator implements it here; a
// real binding would implement call() by converting Params to AL::ALValue and invoking
// AL::ALProxy(module).genericCall(method, ...) (see README.md).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "mixed_value.h"

namespace touchline::nao {

class NaoqiBroker {
 public:
  virtual ~NaoqiBroker() = default;

  // Calls module.method(params) and blocks as long as the action takes. Returns the value,
  // or nothing for a void method. Throws CallError (or any std::exception) on failure.
  // Must be safe to call from several worker threads at once.
  virtual std::optional<Value> call(const std::string& module, const std::string& method,
                                    const Params& params) = 0;

  virtual std::vector<std::string> moduleNames() const = 0;

  // True if module.method is known to return within microseconds: it never waits for robot
  // time or for another call (getters, non-blocking setters, stop commands), and a name the
  // broker does not know fails at once. The RPC module runs such calls on its frontend
  // thread instead of handing them to a worker. Must be thread-safe and cheap. The default,
  // false, sends every call to a worker (always correct, one thread hand-off slower).
  virtual bool isQuick(const std::string& module, const std::string& method) const {
    (void)module;
    (void)method;
    return false;
  }

  // Wakes blocking calls so worker threads can be joined at shutdown.
  virtual void shutdown() {}
};

}  // namespace touchline::nao
