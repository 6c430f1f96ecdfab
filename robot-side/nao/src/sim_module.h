// A simulated NAOqi module: a table of methods with typed parameters, help texts and a
// handler each. The table gives every module getMethodList/getMethodHelp/getModuleHelp for
// free, and lets the dispatcher reject wrong parameter types before a handler runs.
#pragma once

#include <functional>
#include <initializer_list>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "call_log.h"
#include "mixed_value.h"

namespace touchline::nao {

enum class ParamType {
  String,
  Int,
  Float,    // int or float
  Bool,
  Binary,
  Names,    // string or list of strings (joint, chain, "Body")
  Numbers,  // number or list of numbers
  Any,
};

const char* paramTypeName(ParamType t);
bool matches(ParamType t, const Value& v);

struct ParamSpec {
  std::string name;
  ParamType type;
};

struct MethodSpec {
  std::string name;
  std::vector<ParamSpec> params;
  std::string returns;  // "void", "bool", "float", "Vec<str>", ...
  std::string help;
  std::function<std::optional<Value>(const Params&)> handler;
  std::size_t optionalTail = 0;  // how many trailing params may be left out
};

class SimModule {
 public:
  SimModule(std::string name, std::string description);
  virtual ~SimModule() = default;
  SimModule(const SimModule&) = delete;
  SimModule& operator=(const SimModule&) = delete;

  const std::string& name() const { return name_; }
  std::vector<std::string> methodNames() const { return order_; }

  // Checks the parameter count and types, records the call in log (if given) and runs
  // the handler. Throws CallError. Calls rejected before running are not logged.
  std::optional<Value> call(const std::string& method, const Params& params,
                            CallLog* log = nullptr) const;

  // True if method is known to return within microseconds: it never waits for robot time
  // or for another call (getters, non-blocking setters, stop commands). An unknown method
  // is quick too: it fails at once. The RPC module runs quick calls on its frontend thread.
  bool isQuick(const std::string& method) const;

 protected:
  void add(MethodSpec spec);
  // Marks methods as quick (see isQuick); every other method may block.
  void markQuick(std::initializer_list<const char*> methods);

 private:
  Value methodHelp(const std::string& method) const;
  std::string usage(const MethodSpec& spec) const;

  std::string name_;
  std::string description_;
  std::map<std::string, MethodSpec> methods_;
  std::vector<std::string> order_;
  std::set<std::string> quick_;
};

// Parameter accessors for handlers (types were checked by SimModule::call).
std::string stringArg(const Params& p, std::size_t i);
double numberArg(const Params& p, std::size_t i);
std::uint32_t intArg(const Params& p, std::size_t i);
bool boolArg(const Params& p, std::size_t i);
std::vector<std::string> namesArg(const Params& p, std::size_t i);
std::vector<double> numbersArg(const Params& p, std::size_t i);

// Helpers for void / value returns in handlers.
inline std::optional<Value> none() { return std::nullopt; }

}  // namespace touchline::nao
