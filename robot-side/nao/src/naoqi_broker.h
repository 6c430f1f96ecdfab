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

  // Wakes blocking calls so worker threads can be joined at shutdown.
  virtual void shutdown() {}
};

}  // namespace touchline::nao
