// MixedValue (NAOqi's ALValue on the wire): construction, type checks, text rendering and
// the depth-limited request parser used by the RPC module.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "nao.pb.h"

namespace touchline::nao {

using Value = ::nao::MixedValue;
using Params = std::vector<Value>;

// Thrown by a module for any failure the caller should see as HAWActorRPCResponse.error.
class CallError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A MixedValue with no scalar field set is an array (possibly empty).
enum class Kind { String, Int, Float, Binary, Bool, Array };

Kind kindOf(const Value& v);
const char* kindName(Kind k);

Value stringValue(const std::string& s);
Value intValue(std::uint32_t i);
Value floatValue(float f);
Value boolValue(bool b);
Value binaryValue(std::string bytes);
Value arrayValue(std::vector<Value> items);
Value stringList(const std::vector<std::string>& items);
Value floatList(const std::vector<double>& items);

bool isNumber(const Value& v);
double numberOf(const Value& v);  // Int or Float; caller checked isNumber

// Short, human-readable rendering for logs and the call log, cut at maxChars.
std::string describe(const Value& v, std::size_t maxChars = 120);

// Deepest array nesting: a scalar is depth 1, [x] is depth 2.
int depthOf(const Value& v);

// Deepest MixedValue nesting a request may carry (params count as level 1).
constexpr int kMaxNesting = 32;

// Parses payload into out without unbounded recursion (protobuf's recursion limit bounds
// the parser's stack). Returns an error message, or nothing on success.
std::optional<std::string> parseRequest(const std::string& payload,
                                        ::nao::HAWActorRPCRequest& out);

}  // namespace touchline::nao
