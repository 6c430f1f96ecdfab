#include "sim_module.h"

#include <sstream>
#include <stdexcept>

namespace touchline::nao {

const char* paramTypeName(ParamType t) {
  switch (t) {
    case ParamType::String: return "str";
    case ParamType::Int: return "int";
    case ParamType::Float: return "float";
    case ParamType::Bool: return "bool";
    case ParamType::Binary: return "binary";
    case ParamType::Names: return "str or Vec<str>";
    case ParamType::Numbers: return "float or Vec<float>";
    case ParamType::Any: return "any";
  }
  return "?";
}

bool matches(ParamType t, const Value& v) {
  Kind k = kindOf(v);
  switch (t) {
    case ParamType::String: return k == Kind::String;
    case ParamType::Int: return k == Kind::Int;
    case ParamType::Float: return isNumber(v);
    case ParamType::Bool: return k == Kind::Bool;
    case ParamType::Binary: return k == Kind::Binary;
    case ParamType::Names:
      if (k == Kind::String) return true;
      if (k != Kind::Array || v.array_size() == 0) return false;
      for (const auto& item : v.array()) if (kindOf(item) != Kind::String) return false;
      return true;
    case ParamType::Numbers:
      if (isNumber(v)) return true;
      if (k != Kind::Array || v.array_size() == 0) return false;
      for (const auto& item : v.array()) if (!isNumber(item)) return false;
      return true;
    case ParamType::Any: return true;
  }
  return false;
}

SimModule::SimModule(std::string name, std::string description)
    : name_(std::move(name)), description_(std::move(description)) {
  // The methods every NAOqi module has (1.10 header and 2.x service dump agree).
  add({"getMethodList", {}, "Vec<str>", "Names of all methods of this module.",
       [this](const Params&) { return std::optional<Value>(stringList(order_)); }});
  add({"getMethodHelp", {{"methodName", ParamType::String}}, "any",
       "[name, description, [[paramName, paramType]...], returnType] of a method.",
       [this](const Params& p) { return std::optional<Value>(methodHelp(stringArg(p, 0))); }});
  add({"getModuleHelp", {}, "any", "[moduleName, description].",
       [this](const Params&) {
         return std::optional<Value>(stringList({name_, description_}));
       }});
  add({"getUsage", {{"methodName", ParamType::String}}, "str", "Signature of a method.",
       [this](const Params& p) {
         auto it = methods_.find(stringArg(p, 0));
         if (it == methods_.end()) throw CallError(name_ + ": no method '" + stringArg(p, 0) + "'");
         return std::optional<Value>(stringValue(usage(it->second)));
       }});
  add({"version", {}, "str", "Module version.",
       [](const Params&) { return std::optional<Value>(stringValue("touchline-sim 1.0")); }});
  add({"ping", {}, "bool", "Always true: the module is alive.",
       [](const Params&) { return std::optional<Value>(boolValue(true)); }});
  add({"getBrokerName", {}, "str", "Name of the broker the module runs in.",
       [](const Params&) { return std::optional<Value>(stringValue("touchline-nao-sim")); }});
  markQuick({"getMethodList", "getMethodHelp", "getModuleHelp", "getUsage", "version", "ping",
             "getBrokerName"});
}

void SimModule::markQuick(std::initializer_list<const char*> methods) {
  for (const char* m : methods) {
    // A misspelt name would silently send a blocking call to the frontend thread's table.
    if (methods_.count(m) == 0) throw std::logic_error(name_ + ": markQuick of unknown method " + m);
    quick_.insert(m);
  }
}

bool SimModule::isQuick(const std::string& method) const {
  return quick_.count(method) > 0 || methods_.count(method) == 0;
}

void SimModule::add(MethodSpec spec) {
  std::string key = spec.name;
  if (methods_.count(key) == 0) order_.push_back(key);
  methods_[key] = std::move(spec);
}

std::string SimModule::usage(const MethodSpec& spec) const {
  std::ostringstream out;
  out << spec.returns << ' ' << name_ << '.' << spec.name << '(';
  std::size_t required = spec.params.size() - spec.optionalTail;
  for (std::size_t i = 0; i < spec.params.size(); ++i) {
    if (i) out << ", ";
    if (i >= required) out << '[';
    out << spec.params[i].name << ": " << paramTypeName(spec.params[i].type);
    if (i >= required) out << ']';
  }
  out << ')';
  return out.str();
}

Value SimModule::methodHelp(const std::string& method) const {
  auto it = methods_.find(method);
  if (it == methods_.end()) throw CallError(name_ + ": no method '" + method + "'");
  const MethodSpec& spec = it->second;
  std::vector<Value> params;
  for (const auto& p : spec.params) params.push_back(stringList({p.name, paramTypeName(p.type)}));
  return arrayValue({stringValue(spec.name), stringValue(spec.help), arrayValue(std::move(params)),
                     stringValue(spec.returns)});
}

std::optional<Value> SimModule::call(const std::string& method, const Params& params,
                                     CallLog* log) const {
  auto it = methods_.find(method);
  if (it == methods_.end()) {
    throw CallError("unknown method '" + method + "' in module " + name_ +
                    " (getMethodList lists the methods)");
  }
  const MethodSpec& spec = it->second;
  std::size_t required = spec.params.size() - spec.optionalTail;
  if (params.size() < required || params.size() > spec.params.size()) {
    throw CallError(name_ + "." + method + ": expected " +
                    (spec.optionalTail ? std::to_string(required) + ".." : std::string()) +
                    std::to_string(spec.params.size()) + " parameters, got " +
                    std::to_string(params.size()) + "; usage: " + usage(spec));
  }
  for (std::size_t i = 0; i < params.size(); ++i) {
    if (!matches(spec.params[i].type, params[i])) {
      throw CallError(name_ + "." + method + ": parameter " + std::to_string(i + 1) + " (" +
                      spec.params[i].name + ") must be " + paramTypeName(spec.params[i].type) +
                      ", got " + kindName(kindOf(params[i])) + " " + describe(params[i], 40) +
                      "; usage: " + usage(spec));
    }
  }
  if (log) {
    std::string entry = name_ + "." + method + "(";
    for (std::size_t i = 0; i < params.size(); ++i) entry += (i ? ", " : "") + describe(params[i], 60);
    log->record(entry + ")");
  }
  return spec.handler(params);
}

std::string stringArg(const Params& p, std::size_t i) { return p.at(i).string(); }
double numberArg(const Params& p, std::size_t i) { return numberOf(p.at(i)); }
std::uint32_t intArg(const Params& p, std::size_t i) { return p.at(i).int_(); }
bool boolArg(const Params& p, std::size_t i) { return p.at(i).bool_(); }

std::vector<std::string> namesArg(const Params& p, std::size_t i) {
  const Value& v = p.at(i);
  if (kindOf(v) == Kind::String) return {v.string()};
  std::vector<std::string> out;
  for (const auto& item : v.array()) out.push_back(item.string());
  return out;
}

std::vector<double> numbersArg(const Params& p, std::size_t i) {
  const Value& v = p.at(i);
  if (isNumber(v)) return {numberOf(v)};
  std::vector<double> out;
  for (const auto& item : v.array()) out.push_back(numberOf(item));
  return out;
}

}  // namespace touchline::nao
