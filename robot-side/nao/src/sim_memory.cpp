#include "sim_modules.h"

namespace touchline::nao {

namespace {
const std::string kDevicePrefix = "Device/SubDeviceList/";
const std::string kBatteryKey = "Device/SubDeviceList/Battery/Charge/Sensor/Value";
const std::string kCallLogKey = "Touchline/CallLog";
const std::string kPostureKey = "robotPosture";
}  // namespace

SimMemory::SimMemory(RobotState& robot, CallLog& log)
    : SimModule("ALMemory", "Key/value store; joint, battery and posture keys are live."),
      robot_(robot), log_(log) {
  add({"getData", {{"key", ParamType::String}}, "any", "Value of a key (error if absent).",
       [this](const Params& p) { return std::optional<Value>(get(stringArg(p, 0))); }});
  add({"insertData", {{"key", ParamType::String}, {"value", ParamType::Any}}, "void",
       "Stores a value (device keys are read-only).", [this](const Params& p) {
         insert(stringArg(p, 0), p[1]);
         return none();
       }});
  add({"insertListData", {{"list", ParamType::Any}}, "void", "[[key, value], ...].",
       [this](const Params& p) {
         for (const auto& pair : p[0].array()) {
           if (pair.array_size() != 2 || kindOf(pair.array(0)) != Kind::String)
             throw CallError("insertListData: expected [[key, value], ...]");
         }
         for (const auto& pair : p[0].array()) insert(pair.array(0).string(), pair.array(1));
         return none();
       }});
  add({"getListData", {{"keyList", ParamType::Names}}, "any", "Values of several keys.",
       [this](const Params& p) {
         std::vector<Value> out;
         for (const auto& key : namesArg(p, 0)) out.push_back(get(key));
         return std::optional<Value>(arrayValue(std::move(out)));
       }});
  add({"getDataList", {{"filter", ParamType::String}}, "Vec<str>", "Keys containing filter.",
       [this](const Params& p) {
         std::vector<std::string> out;
         std::string filter = stringArg(p, 0);
         for (const auto& key : deviceKeys()) if (key.find(filter) != std::string::npos) out.push_back(key);
         std::lock_guard<std::mutex> lock(mutex_);
         for (const auto& [key, v] : data_) if (key.find(filter) != std::string::npos) out.push_back(key);
         return std::optional<Value>(stringList(out));
       }});
  add({"getDataListName", {}, "Vec<str>", "All keys.", [this](const Params&) {
         std::vector<std::string> out = deviceKeys();
         std::lock_guard<std::mutex> lock(mutex_);
         for (const auto& [key, v] : data_) out.push_back(key);
         return std::optional<Value>(stringList(out));
       }});
  add({"getType", {{"key", ParamType::String}}, "str", "Kind of the stored value.",
       [this](const Params& p) {
         return std::optional<Value>(stringValue(kindName(kindOf(get(stringArg(p, 0))))));
       }});
  add({"removeData", {{"key", ParamType::String}}, "void", "Removes a key.",
       [this](const Params& p) {
         std::lock_guard<std::mutex> lock(mutex_);
         auto it = data_.find(stringArg(p, 0));
         if (it == data_.end()) throw CallError("ALMemory: no key '" + stringArg(p, 0) + "'");
         storedBytes_ -= it->second.ByteSizeLong();
         data_.erase(it);
         return none();
       }});
  add({"declareEvent", {{"eventName", ParamType::String}}, "void", "Declares an event.",
       [this](const Params& p) {
         std::lock_guard<std::mutex> lock(mutex_);
         events_.insert(stringArg(p, 0));
         return none();
       }});
  add({"raiseEvent", {{"name", ParamType::String}, {"value", ParamType::Any}}, "void",
       "Stores the value under the event name (no subscribers in the simulator).",
       [this](const Params& p) {
         {
           std::lock_guard<std::mutex> lock(mutex_);
           events_.insert(stringArg(p, 0));
         }
         insert(stringArg(p, 0), p[1]);
         return none();
       }});
  add({"getEventList", {}, "Vec<str>", "Declared or raised events.", [this](const Params&) {
         std::lock_guard<std::mutex> lock(mutex_);
         return std::optional<Value>(stringList({events_.begin(), events_.end()}));
       }});
  // Map reads and writes under a short lock; requests above RpcServer's inline size limit
  // (a large insertData) go to a worker anyway.
  markQuick({"getData", "insertData", "insertListData", "getListData", "getDataList",
             "getDataListName", "getType", "removeData", "declareEvent", "raiseEvent",
             "getEventList"});
}

std::vector<std::string> SimMemory::deviceKeys() const {
  std::vector<std::string> keys;
  for (const auto& j : RobotState::joints()) {
    keys.push_back(kDevicePrefix + j.name + "/Position/Actuator/Value");
    keys.push_back(kDevicePrefix + j.name + "/Position/Sensor/Value");
    keys.push_back(kDevicePrefix + j.name + "/Hardness/Actuator/Value");
  }
  keys.push_back(kBatteryKey);
  keys.push_back(kPostureKey);
  keys.push_back(kCallLogKey);
  return keys;
}

std::optional<Value> SimMemory::deviceKey(const std::string& key) const {
  if (key == kBatteryKey) return floatValue(robot_.batteryPercent() / 100.0f);
  if (key == kPostureKey) return stringValue(robot_.posture());
  if (key == kCallLogKey) return stringList(log_.entries());
  if (key.rfind(kDevicePrefix, 0) != 0) return std::nullopt;
  std::string rest = key.substr(kDevicePrefix.size());
  auto slash = rest.find('/');
  if (slash == std::string::npos) return std::nullopt;
  std::string joint = rest.substr(0, slash), leaf = rest.substr(slash);
  for (const auto& j : RobotState::joints()) {
    if (j.name != joint) continue;
    if (leaf == "/Position/Actuator/Value") return floatValue(static_cast<float>(robot_.commandedAngle(joint)));
    if (leaf == "/Position/Sensor/Value") return floatValue(static_cast<float>(robot_.sensedAngle(joint)));
    if (leaf == "/Hardness/Actuator/Value") return floatValue(static_cast<float>(robot_.stiffness(joint)));
  }
  return std::nullopt;
}

Value SimMemory::get(const std::string& key) const {
  if (auto v = deviceKey(key)) return *v;
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = data_.find(key);
  if (it == data_.end()) throw CallError("ALMemory: no key '" + key + "'");
  return it->second;
}

void SimMemory::insert(const std::string& key, const Value& value) {
  if (deviceKey(key)) throw CallError("ALMemory: key '" + key + "' is read-only (device key)");
  std::lock_guard<std::mutex> lock(mutex_);
  // Bounded like every store fed from the network: a client cannot fill the robot's RAM.
  auto it = data_.find(key);
  std::size_t replaced = it == data_.end() ? 0 : it->second.ByteSizeLong();
  if (it == data_.end() && data_.size() >= kMaxKeys)
    throw CallError("ALMemory: key limit reached (" + std::to_string(kMaxKeys) + " keys)");
  if (storedBytes_ - replaced + value.ByteSizeLong() > kMaxBytes)
    throw CallError("ALMemory: storage limit reached (" + std::to_string(kMaxBytes) + " bytes)");
  storedBytes_ = storedBytes_ - replaced + value.ByteSizeLong();
  data_[key] = value;
}

}  // namespace touchline::nao
