#include "core/common/json_writer.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sightline {
namespace {

TEST(JsonWriter, WritesNestedCompactJson) {
  JsonWriter w(false);
  w.BeginObject();
  w.Key("a").Int(1);
  w.Key("b").BeginArray().Double(0.5).Bool(true).Null().EndArray();
  w.Key("c").BeginObject().EndObject();
  w.Key("s").String("q\"\\\n");
  w.Key("nan").Double(std::nan(""));
  w.EndObject();
  EXPECT_EQ(w.str(), R"({"a":1,"b":[0.5,true,null],"c":{},"s":"q\"\\\n","nan":null})");
}

TEST(JsonWriter, PrettyOutputHasOneMemberPerLine) {
  JsonWriter w(true);
  w.BeginObject().Key("x").Int(1).Key("y").Int(2).EndObject();
  EXPECT_EQ(w.str(), "{\n  \"x\": 1,\n  \"y\": 2\n}");
}

}  // namespace
}  // namespace sightline
