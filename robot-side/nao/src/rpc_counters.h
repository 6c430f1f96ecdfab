// Counters of the RPC module, readable through Robot.getRpcStats.
#pragma once

#include <atomic>
#include <cstdint>

namespace touchline::nao {

struct RpcCounters {
  std::atomic<std::uint64_t> requests{0};            // well-formed envelopes received
  std::atomic<std::uint64_t> replies{0};
  std::atomic<std::uint64_t> errors{0};              // replies carrying an error
  std::atomic<std::uint64_t> malformedEnvelopes{0};  // wrong frame layout: dropped
  std::atomic<std::uint64_t> malformedPayloads{0};   // not a HAWActorRPCRequest / too deep
  std::atomic<std::uint64_t> oversize{0};            // payload above the request limit
  std::atomic<std::uint64_t> deadlinePassed{0};      // late requests not executed
  std::atomic<std::uint64_t> inlineCalls{0};         // quick calls run on the frontend thread
  std::atomic<std::uint64_t> queuedCalls{0};         // calls that waited for a free worker
};

}  // namespace touchline::nao
