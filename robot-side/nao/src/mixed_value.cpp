#include "mixed_value.h"

#include <google/protobuf/io/coded_stream.h>

#include <algorithm>
#include <sstream>

namespace touchline::nao {

Kind kindOf(const Value& v) {
  if (v.has_string()) return Kind::String;
  if (v.has_int_()) return Kind::Int;
  if (v.has_float_()) return Kind::Float;
  if (v.has_binary()) return Kind::Binary;
  if (v.has_bool_()) return Kind::Bool;
  return Kind::Array;
}

const char* kindName(Kind k) {
  switch (k) {
    case Kind::String: return "string";
    case Kind::Int: return "int";
    case Kind::Float: return "float";
    case Kind::Binary: return "binary";
    case Kind::Bool: return "bool";
    case Kind::Array: return "array";
  }
  return "?";
}

Value stringValue(const std::string& s) { Value v; v.set_string(s); return v; }
Value intValue(std::uint32_t i) { Value v; v.set_int_(i); return v; }
Value floatValue(float f) { Value v; v.set_float_(f); return v; }
Value boolValue(bool b) { Value v; v.set_bool_(b); return v; }
Value binaryValue(std::string bytes) { Value v; v.set_binary(std::move(bytes)); return v; }

Value arrayValue(std::vector<Value> items) {
  Value v;
  for (auto& item : items) *v.add_array() = std::move(item);
  return v;
}

Value stringList(const std::vector<std::string>& items) {
  Value v;
  for (const auto& s : items) v.add_array()->set_string(s);
  return v;
}

Value floatList(const std::vector<double>& items) {
  Value v;
  for (double d : items) v.add_array()->set_float_(static_cast<float>(d));
  return v;
}

bool isNumber(const Value& v) {
  Kind k = kindOf(v);
  return k == Kind::Int || k == Kind::Float;
}

double numberOf(const Value& v) {
  return v.has_int_() ? static_cast<double>(v.int_()) : static_cast<double>(v.float_());
}

namespace {
void describeInto(const Value& v, std::ostringstream& out, std::size_t maxChars) {
  if (static_cast<std::size_t>(out.tellp()) > maxChars) return;
  switch (kindOf(v)) {
    case Kind::String: out << '"' << v.string().substr(0, maxChars) << '"'; break;
    case Kind::Int: out << v.int_(); break;
    case Kind::Float: out << v.float_(); break;
    case Kind::Binary: out << "<" << v.binary().size() << " bytes>"; break;
    case Kind::Bool: out << (v.bool_() ? "true" : "false"); break;
    case Kind::Array:
      out << '[';
      for (int i = 0; i < v.array_size(); ++i) {
        if (i) out << ", ";
        describeInto(v.array(i), out, maxChars);
        if (static_cast<std::size_t>(out.tellp()) > maxChars) break;
      }
      out << ']';
      break;
  }
}
}  // namespace

std::string describe(const Value& v, std::size_t maxChars) {
  std::ostringstream out;
  describeInto(v, out, maxChars);
  std::string s = out.str();
  if (s.size() > maxChars) s = s.substr(0, maxChars) + "...";
  return s;
}

int depthOf(const Value& v) {
  int deepest = 0;
  for (const auto& item : v.array()) deepest = std::max(deepest, depthOf(item));
  return 1 + deepest;
}

namespace {
bool parseWithLimit(const std::string& payload, int limit, ::nao::HAWActorRPCRequest& out) {
  google::protobuf::io::CodedInputStream in(
      reinterpret_cast<const std::uint8_t*>(payload.data()), static_cast<int>(payload.size()));
  in.SetRecursionLimit(limit);
  out.Clear();
  return out.ParsePartialFromCodedStream(&in) && in.ConsumedEntireMessage();
}
}  // namespace

std::optional<std::string> parseRequest(const std::string& payload,
                                        ::nao::HAWActorRPCRequest& out) {
  if (payload.size() > static_cast<std::size_t>(INT32_MAX)) return "request too large";
  // The recursion limit counts embedded messages below the request: params are level 1.
  if (!parseWithLimit(payload, kMaxNesting, out)) {
    // Parse again with protobuf's default bound only to tell "too deep" from "garbage".
    ::nao::HAWActorRPCRequest probe;
    if (parseWithLimit(payload, 100, probe)) {
      out.Clear();
      return "MixedValue nested deeper than " + std::to_string(kMaxNesting) + " levels";
    }
    out.Clear();
    return "payload is not a HAWActorRPCRequest (" + std::to_string(payload.size()) +
           " bytes, protobuf parse failed or nesting deeper than 100)";
  }
  if (!out.has_module() || !out.has_method()) {
    return std::string("request lacks required field ") + (out.has_module() ? "method" : "module");
  }
  return std::nullopt;
}

}  // namespace touchline::nao
