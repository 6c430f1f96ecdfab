#include <gtest/gtest.h>

#include "mixed_value.h"

using namespace touchline::nao;

namespace {
Value nested(int depth) {
  Value v = intValue(7);
  for (int i = 1; i < depth; ++i) v = arrayValue({v});
  return v;
}

// A params entry nested `depth` levels, built as raw bytes so the builder itself cannot
// recurse: each level is field 6 (array), length-delimited.
std::string deepRequestBytes(int depth) {
  std::string inner = std::string("\x10\x07", 2);  // int = 7
  auto varint = [](std::size_t n) {
    std::string out;
    while (n >= 0x80) { out.push_back(static_cast<char>((n & 0x7f) | 0x80)); n >>= 7; }
    out.push_back(static_cast<char>(n));
    return out;
  };
  for (int i = 1; i < depth; ++i) inner = "\x32" + varint(inner.size()) + inner;
  return std::string("\x0a\x01M\x12\x01m", 6) + "\x1a" + varint(inner.size()) + inner;
}
}  // namespace

TEST(MixedValue, KindOfEveryType) {
  EXPECT_EQ(kindOf(stringValue("a")), Kind::String);
  EXPECT_EQ(kindOf(intValue(3)), Kind::Int);
  EXPECT_EQ(kindOf(floatValue(1.5f)), Kind::Float);
  EXPECT_EQ(kindOf(binaryValue("xy")), Kind::Binary);
  EXPECT_EQ(kindOf(boolValue(false)), Kind::Bool);
  EXPECT_EQ(kindOf(Value()), Kind::Array);
  EXPECT_EQ(kindOf(stringList({"a", "b"})), Kind::Array);
  EXPECT_TRUE(isNumber(intValue(1)));
  EXPECT_FALSE(isNumber(stringValue("1")));
}

TEST(MixedValue, DescribeAndDepth) {
  EXPECT_EQ(describe(arrayValue({stringValue("hi"), intValue(2), boolValue(true)})),
            "[\"hi\", 2, true]");
  EXPECT_EQ(describe(binaryValue(std::string(10, 'x'))), "<10 bytes>");
  EXPECT_EQ(depthOf(intValue(1)), 1);
  EXPECT_EQ(depthOf(nested(5)), 5);
  EXPECT_LE(describe(stringValue(std::string(1000, 'a')), 50).size(), 60u);
}

TEST(ParseRequest, AcceptsAWellFormedRequest) {
  ::nao::HAWActorRPCRequest out;
  ::nao::HAWActorRPCRequest in;
  in.set_module("ALMotion");
  in.set_method("getAngles");
  *in.add_params() = stringValue("HeadYaw");
  *in.add_params() = boolValue(true);
  EXPECT_FALSE(parseRequest(in.SerializeAsString(), out));
  EXPECT_EQ(out.module(), "ALMotion");
  EXPECT_EQ(out.params_size(), 2);
}

TEST(ParseRequest, RejectsGarbageAndMissingFields) {
  ::nao::HAWActorRPCRequest out;
  auto garbage = parseRequest("\xff\xff\xff\xff garbage", out);
  ASSERT_TRUE(garbage);
  EXPECT_NE(garbage->find("not a HAWActorRPCRequest"), std::string::npos);
  ::nao::HAWActorRPCRequest noMethod;
  noMethod.set_module("ALMotion");
  auto missing = parseRequest(noMethod.SerializePartialAsString(), out);
  ASSERT_TRUE(missing);
  EXPECT_NE(missing->find("method"), std::string::npos);
}

TEST(ParseRequest, DepthLimitIs32) {
  ::nao::HAWActorRPCRequest out;
  EXPECT_FALSE(parseRequest(deepRequestBytes(kMaxNesting), out));
  EXPECT_EQ(depthOf(out.params(0)), kMaxNesting);
  auto tooDeep = parseRequest(deepRequestBytes(kMaxNesting + 1), out);
  ASSERT_TRUE(tooDeep);
  EXPECT_NE(tooDeep->find("nested deeper than 32"), std::string::npos);
}

TEST(ParseRequest, VeryDeepNestingIsRejectedWithoutRecursingThroughIt) {
  ::nao::HAWActorRPCRequest out;
  auto error = parseRequest(deepRequestBytes(20000), out);  // would blow an unbounded parser
  ASSERT_TRUE(error);
}
