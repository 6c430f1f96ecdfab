#include "sim_modules.h"

namespace touchline::nao {

SimRobotInfo::SimRobotInfo(std::function<std::vector<std::string>()> modules, CallLog& log,
                           const RpcCounters* counters)
    : SimModule("Robot", "Touchline's robot-side info: modules, call log, RPC counters.") {
  add({"getModuleList", {}, "Vec<str>", "Modules this robot serves.",
       [modules](const Params&) { return std::optional<Value>(stringList(modules())); }});
  add({"getCallLog", {}, "Vec<str>",
       "Calls executed so far (last 1000), \"<seq> Module.method(args)\"; Robot.* not logged.",
       [&log](const Params&) { return std::optional<Value>(stringList(log.entries())); }});
  add({"clearCallLog", {}, "void", "Empties the call log.", [&log](const Params&) {
         log.clear();
         return none();
       }});
  add({"getRpcStats", {}, "any", "[[counterName, value]...] of the RPC module.",
       [counters](const Params&) {
         std::vector<Value> rows;
         if (counters) {
           auto row = [&rows](const char* name, std::uint64_t v) {
             rows.push_back(arrayValue({stringValue(name), intValue(static_cast<std::uint32_t>(v))}));
           };
           row("requests", counters->requests);
           row("replies", counters->replies);
           row("errors", counters->errors);
           row("malformedEnvelopes", counters->malformedEnvelopes);
           row("malformedPayloads", counters->malformedPayloads);
           row("oversize", counters->oversize);
           row("deadlinePassed", counters->deadlinePassed);
           row("inlineCalls", counters->inlineCalls);
           row("queuedCalls", counters->queuedCalls);
         }
         return std::optional<Value>(arrayValue(std::move(rows)));
       }});
  markQuick({"getModuleList", "getCallLog", "clearCallLog", "getRpcStats"});
}

}  // namespace touchline::nao
